// scene.build (R-AS-COPY): the build flags and the copy a case asks for, and
// each error at its line and field.
#include <gtest/gtest.h>

#include "case/flag_names.h"
#include "case/parse_case.h"

namespace rayspec {
namespace {

ParseResult parseBuild(const std::string& build) {
  return parseCaseText(
      "rules: [R-AS-COPY]\n"
      "scene:\n"
      "  build: " +
          build +
          "\n"
          "  blas:\n"
          "    t: [{triangles: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}}]\n"
          "  instances: [{blas: t}]\n"
          "rays:\n"
          "  list: [{origin: [0.2, 0.2, 1], direction: [0, 0, -1]}]\n"
          "pipeline:\n"
          "  hit_groups: [{closest_hit: [record: [hit]]}]\n"
          "outputs:\n"
          "  per_ray: [hit]\n",
      "t.yaml", "t/t");
}

std::string firstError(const ParseResult& r) {
  return r.errors.empty() ? std::string("(no error)") : r.errors[0].format();
}

TEST(SceneBuild, DefaultsToPreferFastTraceWithoutCopy) {
  const ParseResult r = parseBuild("{}");
  ASSERT_TRUE(r.value) << firstError(r);
  EXPECT_EQ(r.value->scene.build.flags, kBuildPreferFastTrace);
  EXPECT_EQ(r.value->scene.build.copy, AsCopy::None);
}

TEST(SceneBuild, FlagsAndCopyAreRead) {
  const ParseResult r = parseBuild("{flags: [prefer_fast_build, low_memory], copy: compact}");
  ASSERT_TRUE(r.value) << firstError(r);
  EXPECT_EQ(r.value->scene.build.flags, kBuildPreferFastBuild | kBuildLowMemory);
  EXPECT_EQ(r.value->scene.build.copy, AsCopy::Compact);
  EXPECT_STREQ(asCopyName(AsCopy::Clone), "clone");
}

TEST(SceneBuild, ErrorsNameTheLineAndField) {
  struct Bad {
    std::string build, field, message;
  } bad[] = {{"{copy: serialize}", "scene.build.copy", "unknown copy 'serialize'"},
             {"{flags: [prefer_fast_trace, prefer_fast_build]}", "scene.build.flags",
              "prefer_fast_trace and prefer_fast_build together"},
             {"{flags: [fastest]}", "scene.build.flags", "fastest"},
             {"{copies: clone}", "scene.build", "unknown key 'copies'"}};
  for (const Bad& b : bad) {
    const ParseResult r = parseBuild(b.build);
    EXPECT_FALSE(r.value) << b.build;
    const std::string e = firstError(r);
    EXPECT_NE(e.find("t.yaml:3"), std::string::npos) << e;
    EXPECT_NE(e.find(b.field), std::string::npos) << e;
    EXPECT_NE(e.find(b.message), std::string::npos) << e;
  }
}

}  // namespace
}  // namespace rayspec
