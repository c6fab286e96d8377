// compareRejections (R-STAGE-INTERFACE): a shader the model expects to be
// rejected and the device side rejected is a Pass finding; one the device
// side did not reject (an accepting compiler, a null device) a Fail.
#include <gtest/gtest.h>

#include "compare/compare_results.h"
#include "parse_support.h"
#include "plan/plan.h"

namespace rayspec {
namespace {

Case missAttributeCase() {
  return parsedCase(R"(rules: [R-STAGE-INTERFACE]
expect_rejected: [miss0]
scene:
  blas:
    tri: [{triangles: {vertices: [[-1, -1, 0], [2, -1, 0], [-1, 2, 0]]}}]
  instances: [{blas: tri}]
rays:
  list: [{origin: [50, 0, 1], direction: [0, 0, -1]}]
pipeline:
  raygen: [trace: {}, record: {color: payload.color}]
  miss:
    - [payload: {color: {vec4: [{x: barycentrics}, 0.0, 0.0, 1.0]}}]
  hit_groups:
    - closest_hit: [payload: {color: [1.0, 1.0, 1.0, 1.0]}]
outputs:
  per_ray: [color]
)");
}

TEST(CompareRejections, ARejectionTheModelExpectsPassesAndAMissingOneFails) {
  const Case c = missAttributeCase();
  const Plan plan = derivePlan(c);
  Results model, device;
  model.rejected = device.rejected = {"miss0"};
  const Verdict pass = compareResults(c, plan, device, model);
  EXPECT_EQ(pass.status, Status::Pass) << pass.headline();
  ASSERT_EQ(pass.findings.size(), 1u);
  EXPECT_NE(pass.findings[0].message.find(
                "miss0 uses barycentrics (line 12), which needs hitAttributeEXT: the compiler "
                "rejected it"),
            std::string::npos)
      << pass.findings[0].message;
  device.rejected.clear();
  const Verdict fail = compareResults(c, plan, device, model);
  EXPECT_EQ(fail.status, Status::Fail);
  EXPECT_NE(fail.headline().find("R-STAGE-INTERFACE"), std::string::npos) << fail.headline();
  EXPECT_NE(fail.headline().find("its stage cannot declare hitAttributeEXT"), std::string::npos);
}

}  // namespace
}  // namespace rayspec
