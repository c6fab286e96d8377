// Exact tier: a ray in a box's face plane may or may not enter the box on a
// device (R-ISECT-REPORT: its intersection program reports anywhere in the
// interval, before the box's slab entry or past its exit as well as inside).
#include <gtest/gtest.h>

#include <map>

#include "model_support.h"

namespace rayspec {
namespace {

using namespace model_test;

// Box [-1, 1]^3, rays from z = 5 down: slab entry t = 4, exit t = 6.
// Ray 0 crosses the box, ray 1 lies in its face plane x = 1.
Case grazedBoxCase(float report_t) {
  Geometry g;
  g.kind = Geometry::Kind::Aabbs;
  g.aabbs = {{-1, -1, -1, 1, 1, 1}};
  g.flags = kGeometryOpaque;
  Case c = baseCase({g}, {downRay(0.5f, 0), downRay(1.0f, 0)});
  Stmt rep;
  rep.kind = Stmt::Kind::Report;
  rep.t = litf(report_t);
  rep.hit_kind = lit(3);
  c.pipeline.hit_groups[0].intersection = Program{rep};
  return c;
}

// Before, inside and after the slab interval: the grazing ray is ambiguous
// with both answers (entered, not entered), the crossing ray clear. Before
// the fix a report before the slab entry left the grazing ray clear.
TEST(ModelGrazeReport, GrazedBoxIsUnsureWhereverItsProgramReports) {
  for (const float t : {1.0f, 4.5f, 7.5f}) {
    Case c = grazedBoxCase(t);
    Results r = run(c, ModelTier::Exact);
    ASSERT_EQ(r.statusText(), "ok") << t;
    EXPECT_EQ(word(r, 0, "hit"), 1u) << t;
    EXPECT_NEAR(fword(r, 0, "hit_t"), t, 1e-6) << t;
    std::map<uint32_t, const RayAmbiguity*> amb;
    for (const RayAmbiguity& a : r.ambiguous) amb[a.ray] = &a;
    EXPECT_EQ(amb.count(0), 0u) << t;
    ASSERT_EQ(amb.count(1), 1u) << t;
    EXPECT_EQ(amb[1]->reason, AmbiguityReason::AabbFace) << t;
    bool hit = false, miss = false;
    for (const Candidate& k : amb[1]->candidates) (k.hit ? hit : miss) = true;
    EXPECT_TRUE(hit && miss) << t;
  }
}

}  // namespace
}  // namespace rayspec
