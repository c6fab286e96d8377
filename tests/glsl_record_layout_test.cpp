// The GLSL of a shader record block with members (pipeline.sbt.record_layout):
// the block in its layout with the members in order, reads as rs_members.NAME,
// the scalar layout's extension, and modules that compile and pass spirv-val.
// The case errors: a read of the record's words beside declared members, an
// unknown member, members that do not fit the record's data.
#include <gtest/gtest.h>

#include "glsl/generate_glsl.h"
#include "parse/parse_case.h"
#include "parse_support.h"
#include "plan/plan.h"
#include "spirv/compile_glsl.h"

namespace rayspec {
namespace {

std::string layoutCase(const std::string& layout, const std::string& read) {
  return R"(rules: [R-SBT-RECORD]
scene:
  blas:
    tri: [{triangles: {vertices: [[-1, -1, 0], [1, -1, 0], [0, 1, 0]]}}]
  instances: [{blas: tri}]
rays:
  list: [{origin: [0, 0, 5], direction: [0, 0, -1]}]
pipeline:
  raygen:
    - trace: {}
    - record: {value: payload.value}
  raygen_data: {words: [1, 2.5, 3.5, 4.5]}
  hit_groups:
    - closest_hit: [payload: {value: )" +
         read + R"(}]
  sbt:
    record_layout: {layout: )" +
         layout + R"(, members: {a: uint, b: vec2, c: float}}
outputs:
  per_ray: [value]
)";
}

TEST(GlslRecordLayout, TheBlockHasTheMembersInItsLayoutAndCompiles) {
  for (const char* layout : {"std430", "scalar"}) {
    SCOPED_TRACE(layout);
    const Case c =
        parsedCase(layoutCase(layout, "{add: [shader_record.a, {uint: shader_record.c}]}"));
    const GeneratedPipeline g = generateGlsl(c, derivePlan(c));
    const std::string& glsl = g.hit_groups.at(0).closest_hit->glsl;
    EXPECT_NE(
        glsl.find(std::string("layout(shaderRecordEXT, ") + layout + ") buffer RsRecordMembers {"),
        std::string::npos)
        << glsl;
    EXPECT_LT(glsl.find("uint a;"), glsl.find("vec2 b;"));
    EXPECT_LT(glsl.find("vec2 b;"), glsl.find("float c;"));
    EXPECT_NE(glsl.find("rs_members.a"), std::string::npos);
    EXPECT_EQ(glsl.find("GL_EXT_scalar_block_layout") != std::string::npos,
              std::string(layout) == "scalar");
    // The raygen reads no member: no block there.
    EXPECT_EQ(g.raygen.glsl.find("RsRecordMembers"), std::string::npos);
    const SpirvResult spirv = compileGlsl(glsl, Stage::ClosestHit);
    EXPECT_TRUE(spirv.error.empty()) << spirv.error;
  }
}

std::string firstError(const std::string& text) {
  const ParseResult p = parseCaseText(text, "inline.yaml", "inline");
  return p.errors.empty() ? "(no error)" : p.errors[0].loc.field + ": " + p.errors[0].message;
}

TEST(GlslRecordLayout, WordReadsUnknownMembersAndOversizedBlocksAreErrors) {
  EXPECT_NE(firstError(layoutCase("std430", "{shader_record_uint: 0}"))
                .find("pipeline.sbt.record_layout declares the record's members"),
            std::string::npos);
  EXPECT_NE(firstError(layoutCase("std430", "shader_record.z"))
                .find("'shader_record.z' is not a member of pipeline.sbt.record_layout"),
            std::string::npos);
  EXPECT_NE(firstError(layoutCase("std140", "shader_record.a"))
                .find("pipeline.sbt.record_layout.layout: 'std140': std430 or scalar"),
            std::string::npos);
  std::string big = layoutCase("std430", "shader_record.a");
  big.replace(big.find("c: float}"), 9, "c: float, d: vec3}");  // 16 + 12 + pad > 32
  EXPECT_NE(firstError(big).find("the members take 44 bytes (std430)"), std::string::npos)
      << firstError(big);
}

}  // namespace
}  // namespace rayspec
