// rayspec export of ray queries (export/export_c.h): a ray_query statement in
// raygen, in closest-hit and miss, in any-hit and intersection; traces run as
// query loops in raygen (pipeline.traces: ray_query) and raygen as a compute
// shader (ray_query_compute, a compute pipeline and a dispatch). Each export
// built and run on lavapipe agrees with rayspec (lavapipe.csv lists none of
// them), and expectations of a model that breaks a query rule make it fail.
#include <gtest/gtest.h>

#include "export_play.h"

namespace rayspec {
namespace {

TEST(ExportRayQuery, QueriesInEveryStageAndFromComputePassOnLavapipe) {
  for (const char* name : {"ray-query/query-first-hit", "ray-query/query-in-hit-and-miss",
                           "ray-query/query-in-any-hit-and-intersection",
                           "ray-query/closest-hit-and-miss", "ray-query/compute-query-in-loop"}) {
    const ExportCase l = loadExportCase(name);
    const Played p = exportAndPlay(l, exportModelOf(l), l.c.name);
    EXPECT_EQ(p.status, 0) << name << ":\n" << p.output;
    EXPECT_NE(p.output.find("PASS: "), std::string::npos) << p.output;
  }
}

TEST(ExportRayQuery, TheComputeFormIsADispatchOfAComputePipeline) {
  const ExportCase l = loadExportCase("ray-query/compute-query-in-loop");
  const Result<std::string> text = exportCaseAsC(l.c, l.plan, exportModelOf(l));
  ASSERT_TRUE(text) << text.error().format();
  EXPECT_NE(text->find("#define RS_COMPUTE 1\n"), std::string::npos);
  EXPECT_NE(text->find("{VK_SHADER_STAGE_COMPUTE_BIT, rs_spirv_0"), std::string::npos);
  EXPECT_NE(text->find("#define RS_SHADER_COUNT 1\n"), std::string::npos);
  EXPECT_NE(text->find("#define RS_NEEDS_RAY_QUERY 1\n"), std::string::npos);
}

TEST(ExportRayQuery, ExpectationsOfAModelWhoseConfirmCommitsNothingFail) {
  // R-RQ-COMMIT broken: rayQueryConfirmIntersectionEXT commits nothing, so
  // the model expects nothing committed where lavapipe commits instance 1.
  const ExportCase l = loadExportCase("ray-query/query-first-hit");
  ModelFaults faults;
  faults.rq_confirm_ignored = true;
  const Played p = exportAndPlay(l, exportModelOf(l, faults), "rq-confirm-ignored");
  EXPECT_EQ(p.status, 1) << p.output;
  EXPECT_NE(p.output.find("FAIL: "), std::string::npos) << p.output;
}

TEST(ExportRayQuery, ExpectationsOfAComputeModelThatKeepsTheOldCommitFail) {
  // R-RQ-INIT broken: the second trip's rayQueryInitializeEXT keeps the
  // first trip's commit.
  const ExportCase l = loadExportCase("ray-query/compute-query-in-loop");
  ModelFaults faults;
  faults.rq_init_keeps_committed = true;
  const Played p = exportAndPlay(l, exportModelOf(l, faults), "rq-init-keeps-committed");
  EXPECT_EQ(p.status, 1) << p.output;
  EXPECT_NE(p.output.find("FAIL: "), std::string::npos) << p.output;
}

}  // namespace
}  // namespace rayspec
