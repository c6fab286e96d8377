// Cases that expect the compiler to reject a shader (expect_rejected,
// R-STAGE-INTERFACE): the checker lets the forbidden use through only in the
// shaders named, the GLSL declares what the program uses and glslang refuses
// that declaration (the shader without the use compiles), and a case that
// names no such shader, or the wrong one, is an error at its line.
#include <gtest/gtest.h>

#include "parse/parse_case.h"
#include "parse_support.h"
#include "plan/plan.h"
#include "vulkan/expected_rejections.h"

namespace rayspec {
namespace {

const char* kIntersectionPayload = R"(rules: [R-STAGE-INTERFACE]
expect_rejected: [hit0.intersection]
scene:
  blas:
    box: [{aabbs: [[-1, -1, -1, 1, 1, 1]]}]
  instances: [{blas: box}]
rays:
  list: [{origin: [0, 0, 5], direction: [0, 0, -1]}]
pipeline:
  raygen: [trace: {}, record: {value: payload.value}]
  hit_groups:
    - intersection: [{report: {t: {float: payload.value}, kind: 1}}]
      closest_hit: [payload: {value: 7}]
outputs:
  per_ray: [value]
)";

// Every error of the case text with `from` replaced by `to`, one per line.
std::string errors(std::string text, const std::string& from, const std::string& to) {
  if (!from.empty()) text.replace(text.find(from), from.size(), to);
  const ParseResult p = parseCaseText(text, "inline.yaml", "interface/inline");
  std::string all;
  for (const Error& e : p.errors) all += e.loc.field + ": " + e.message + "\n";
  return all.empty() ? "(no error)" : all;
}

TEST(ExpectedRejections, GlslangRefusesTheDeclarationAndNothingElse) {
  const Case c = parsedCase(kIntersectionPayload);
  ASSERT_EQ(c.expected_rejections.size(), 1u);
  ASSERT_EQ(c.expected_rejections[0].uses.size(), 1u);
  EXPECT_EQ(c.expected_rejections[0].uses[0].qualifier, "rayPayloadInEXT");
  EXPECT_EQ(c.expected_rejections[0].uses[0].what, "payload.value");
  Results device;
  compileExpectedRejections(c, derivePlan(c), device);
  EXPECT_EQ(device.rejected, std::vector<std::string>{"hit0.intersection"});
  // The same program without the forbidden use compiles: nothing rejected.
  Case fixed = c;
  fixed.pipeline.hit_groups[0].intersection->at(0).t.kind = Expr::Kind::Literal;
  fixed.pipeline.hit_groups[0].intersection->at(0).t.type = ValueType::Float;
  fixed.pipeline.hit_groups[0].intersection->at(0).t.literal = {4.5};
  fixed.pipeline.hit_groups[0].intersection->at(0).t.args.clear();
  Results accepted;
  compileExpectedRejections(fixed, derivePlan(fixed), accepted);
  EXPECT_TRUE(accepted.rejected.empty());
}

TEST(ExpectedRejections, OnlyTheShadersNamedMayUseWhatTheirStageCannot) {
  // Not named: the use is the case error it always was.
  EXPECT_NE(errors(kIntersectionPayload, "expect_rejected: [hit0.intersection]\n", "")
                .find("built-in 'payload.value' cannot be read in intersection"),
            std::string::npos);
  EXPECT_NE(errors(kIntersectionPayload, "[hit0.intersection]", "[hit1.intersection]")
                .find("'hit1.intersection' is no shader of this pipeline"),
            std::string::npos);
  EXPECT_NE(errors(kIntersectionPayload, "[hit0.intersection]", "[hit0.closest_hit]")
                .find("'hit0.closest_hit' uses nothing its stage cannot declare"),
            std::string::npos);
  EXPECT_NE(errors(kIntersectionPayload, "rules: [R-STAGE-INTERFACE]", "rules: [R-PAYLOAD]")
                .find("claims R-STAGE-INTERFACE"),
            std::string::npos);
  // Other errors in a named shader stay errors.
  EXPECT_NE(errors(kIntersectionPayload, "kind: 1}", "kind: 1.5}").find("kind"), std::string::npos);
}

}  // namespace
}  // namespace rayspec
