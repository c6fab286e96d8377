// R-WATERTIGHT: a miss through a shared edge or vertex is a leak only where
// the triangles left after culling close around the ray (model/closed_fan.h).
// Fuzz seed 110735 on NVIDIA: a ray traced twice through a vertex whose two
// remaining triangles leave its fan open missed both times; the model filed
// the miss as a leak, and the counters allowed one move for the ray (a
// Fail). Here: the corner of a quad (an open fan) may be missed on every
// trace and passes; the centre of a closed fan missed on both traces is a
// leak (a QualityWarning, not a Fail: each trace may leak once).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>

#include "compare/compare_results.h"
#include "fault/planted_fault.h"
#include "model_support.h"

namespace rayspec {
namespace {

using namespace model_test;

// One mesh (QUAD or FAN below), one ray straight down through ORIGIN, traced
// twice by raygen; miss and closest-hit count themselves and record which ran.
std::string twiceTracedCase(const std::string& indices, const std::string& origin,
                            const std::string& flags) {
  return R"(rules: [R-WATERTIGHT]
scene:
  blas:
    mesh:
      - triangles:
          vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0], [-1, 0, 0], [0, -1, 0], [1, 1, 0]]
          indices: )" +
         indices + R"(
        flags: [opaque]
  instances:
    - {blas: mesh}
rays:
  list:
    - {origin: )" +
         origin + R"(, direction: [0, 0, -1], flags: )" + flags + R"(}
pipeline:
  raygen: [{repeat: 2, var: l0, do: [{trace: {}}]}]
  miss:
    - [{count: miss}, {record: {value: 1}}]
  hit_groups:
    - closest_hit: [{count: chit}, {record: {value: 2}}]
outputs:
  per_ray: [value]
  counters: [miss, chit]
)";
}

struct FanRun {
  Case c;
  Plan plan;
  Results model;
};

FanRun fanRunOf(const std::string& yaml) {
  FanRun r;
  r.c = parseInline(yaml, "model/open-fan");
  r.plan = derivePlan(r.c);
  r.model = runOnModel(r.c, r.plan, ModelOptions{});
  return r;
}

// The device of `r` whose ray 0 missed on both of its traces.
Results missedTwice(const FanRun& r) {
  Results d = perfectDevice(r.c, r.model);
  uint32_t* rec = d.records.data();
  rec[findRecordField("value")->offset] = 1;
  rec[findRecordField("miss_runs")->offset] = 2;
  rec[findRecordField("closest_hit_runs")->offset] = 0;
  d.counters["miss"] += 2;
  d.counters["chit"] -= 2;
  return d;
}

bool hasMissReplay(const RayAmbiguity& a) {
  return std::any_of(a.replays.begin(), a.replays.end(), [](const LegalReplay& p) {
    return p.counter_moves.count("miss") && p.counter_moves.at("miss") == 2;
  });
}

// The quad (0,1,5) and (0,5,2) shares its edge 0-5, and its corner 0 with
// an open fan: a ray through the corner may miss on each trace.
TEST(OpenFan, TheCornerOfAQuadMayBeMissedOnEveryTrace) {
  const FanRun r = fanRunOf(twiceTracedCase("[0, 1, 5, 0, 5, 2]", "[0, 0, 10]", "[]"));
  ASSERT_EQ(r.model.statusText(), "ok");
  ASSERT_EQ(r.model.ambiguous.size(), 1u);
  const RayAmbiguity& a = r.model.ambiguous[0];
  EXPECT_EQ(a.reason, AmbiguityReason::Vertex);
  EXPECT_EQ(a.traces, 2u);
  EXPECT_TRUE(a.leak_answers.empty());
  EXPECT_TRUE(hasMissReplay(a));
  const Verdict v = compareResults(r.c, r.plan, missedTwice(r), r.model);
  EXPECT_EQ(v.status, Status::Pass) << v.headline();
}

// The fuzz case's shape: around vertex 0, (0,1,2) and (0,2,1) are one
// triangle in both windings, (0,2,3) shares edge 0-2 with the first; the
// ray culls back faces, so (0,2,1) goes and the fan left is open. Without
// culling, (0,2,1) faces the ray the other way and closes nothing either.
TEST(OpenFan, AFanCulledOpenMayBeMissed) {
  for (const std::string flags : {"[cull_back_facing]", "[]"}) {
    const FanRun r = fanRunOf(twiceTracedCase("[0, 1, 2, 0, 2, 1, 0, 2, 3]", "[0, 0, 10]", flags));
    ASSERT_EQ(r.model.ambiguous.size(), 1u) << flags;
    EXPECT_TRUE(r.model.ambiguous[0].leak_answers.empty()) << flags;
    EXPECT_TRUE(hasMissReplay(r.model.ambiguous[0])) << flags;
  }
  const FanRun r =
      fanRunOf(twiceTracedCase("[0, 1, 2, 0, 2, 1, 0, 2, 3]", "[0, 0, 10]", "[cull_back_facing]"));
  const Verdict v = compareResults(r.c, r.plan, missedTwice(r), r.model);
  EXPECT_EQ(v.status, Status::Pass) << v.headline();
}

// Four triangles close a fan around vertex 0; the quad's shared edge 0-5 is
// closed too. A miss there on both traces is a leak: R-WATERTIGHT's
// warning, the counters within two moves (one per trace), not a Fail.
TEST(OpenFan, AClosedFanOrSharedEdgeMissedOnBothTracesLeaks) {
  const std::string fan = "[0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 1]";
  const std::string quad = "[0, 1, 5, 0, 5, 2]";
  for (const auto& [indices, origin] :
       {std::pair{fan, "[0, 0, 10]"}, std::pair{quad, "[0.5, 0.5, 10]"}}) {
    const FanRun r = fanRunOf(twiceTracedCase(indices, origin, "[]"));
    ASSERT_EQ(r.model.ambiguous.size(), 1u) << indices;
    EXPECT_EQ(r.model.ambiguous[0].traces, 2u);
    EXPECT_FALSE(r.model.ambiguous[0].leak_answers.empty()) << indices;
    EXPECT_FALSE(hasMissReplay(r.model.ambiguous[0])) << indices;
    const Verdict v = compareResults(r.c, r.plan, missedTwice(r), r.model);
    EXPECT_EQ(v.status, Status::QualityWarning) << indices << ": " << v.headline();
    EXPECT_NE(v.headline().find("R-WATERTIGHT"), std::string::npos) << v.headline();
  }
}

// The closed fan of four split into geometries of one instance, or into
// instances of the identity transform, still closes (case/share_frame.h): a
// miss on both traces leaks. Into instances moved apart (axes cycled, every
// other one lifted), each triangle is a frame of its own: the miss is one of
// the legal answers, a plain tie, no leak.
TEST(OpenFan, AFanSplitIntoGeometriesOrIdentityInstancesStillCloses) {
  const std::string fan = "[0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 1]";
  std::string yaml = twiceTracedCase(fan, "[0, 0, 10]", "[]");
  const std::string instances = "  instances:\n    - {blas: mesh}\n";
  yaml.replace(yaml.find("[{trace: {}}]"), 13, "[{trace: {sbt_stride: 0}}]");
  for (const auto& [split, status] :
       {std::pair{"{blas: mesh, into: geometries}", Status::QualityWarning},
        std::pair{"{blas: mesh, into: instances}", Status::QualityWarning},
        std::pair{"{blas: mesh, into: instances, translate: [0, 0, 4], cycle_axes: true}",
                  Status::Pass}}) {
    std::string split_yaml = yaml;
    split_yaml.replace(split_yaml.find(instances), instances.size(),
                       instances + "  split: " + split + "\n");
    const FanRun r = fanRunOf(split_yaml);
    ASSERT_EQ(r.model.statusText(), "ok") << split;
    ASSERT_EQ(r.model.ambiguous.size(), 1u) << split;
    EXPECT_EQ(r.model.ambiguous[0].leak_answers.empty(), status == Status::Pass) << split;
    EXPECT_EQ(hasMissReplay(r.model.ambiguous[0]), status == Status::Pass) << split;
    const Verdict v = compareResults(r.c, r.plan, missedTwice(r), r.model);
    EXPECT_EQ(v.status, status) << split << ": " << v.headline();
  }
}

}  // namespace
}  // namespace rayspec
