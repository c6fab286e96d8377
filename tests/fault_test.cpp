// Every planted fault is caught: each test runs a real case on the Vulkan
// device (lavapipe) and on the model, checks the pair passes untouched, plants
// the fault in the device's results and asserts the status it must give.
// Without the comparison catching the fault the status would stay Pass.
#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <memory>
#include <set>

#include "compare/compare_results.h"
#include "fault/planted_fault.h"
#include "fault/record_edit.h"
#include "model/model_engine.h"
#include "parse/parse_case.h"
#include "plan/plan.h"
#include "result_support.h"
#include "results/record_layout.h"
#include "vulkan/vulkan_engine.h"

namespace rayspec {
namespace {

struct Ran {
  Case c;
  Plan plan;
  Results device, model;
};

class PlantedFault : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    VulkanOptions opt;
    opt.validation = false;
    backend_ = orError(VulkanEngine::create(opt), &backend_error_).release();
  }
  static void TearDownTestSuite() {
    delete backend_;
    backend_ = nullptr;
    runs_.clear();
  }

  // The case run once on both sides (cached across tests).
  static const Ran& run(const std::string& name) {
    auto it = runs_.find(name);
    if (it != runs_.end()) return it->second;
    const std::string cases = RAYSPEC_SOURCE_DIR "/cases";
    ParseResult parsed = parseCaseFile(cases + "/" + name + ".yaml", cases);
    Ran r;
    if (!parsed.value) {
      ADD_FAILURE() << name << ": " << (parsed.errors.empty() ? "" : parsed.errors[0].format());
      return runs_[name] = r;
    }
    r.c = *parsed.value;
    r.plan = derivePlan(r.c);
    r.model = runOnModel(r.c, r.plan, ModelOptions{});
    if (backend_) r.device = backend_->run(r.c, r.plan);
    return runs_[name] = std::move(r);
  }

  // Plants the fault and returns the verdict; checks first that the untouched
  // pair passes, so the status comes from the fault.
  Verdict plant(const std::string& case_name, const std::string& fault,
                Results* planted = nullptr) {
    if (!backend_) {
      ADD_FAILURE() << "no Vulkan ray tracing device: " << backend_error_;
      return {};
    }
    const Ran& r = run(case_name);
    EXPECT_EQ(r.device.statusText(), "ok") << case_name;
    const Verdict clean = compareResults(r.c, r.plan, r.device, r.model);
    EXPECT_EQ(clean.status, Status::Pass) << case_name << " without a fault: " << clean.headline();
    Results corrupted = r.device;
    const FaultResult f = plantFault(fault, r.c, r.plan, corrupted, r.model);
    EXPECT_TRUE(f.applied) << fault << " in " << case_name << ": " << f.what;
    EXPECT_NE(corrupted.records, r.device.records) << "the fault changed no record";
    if (planted) *planted = corrupted;
    return compareResults(r.c, r.plan, corrupted, r.model);
  }

  // The device's results with one edit, judged; the untouched pair must pass.
  Verdict edited(const std::string& case_name,
                 const std::function<void(const Ran&, RecordEdit&)>& edit) {
    const Ran& r = run(case_name);
    EXPECT_EQ(compareResults(r.c, r.plan, r.device, r.model).status, Status::Pass) << case_name;
    Results device = r.device;
    RecordEdit e{device};
    edit(r, e);
    return compareResults(r.c, r.plan, device, r.model);
  }

  // A finding of status s whose rule holds `rule`, or that names it among
  // the claims it is evidence against.
  static bool hasFinding(const Verdict& v, Status s, const std::string& rule) {
    for (const Finding& f : v.findings)
      if (f.status == s && (f.rule.find(rule) != std::string::npos || findingNames(f, rule)))
        return true;
    return false;
  }

  static VulkanEngine* backend_;
  static std::string backend_error_;
  static std::map<std::string, Ran> runs_;
};

VulkanEngine* PlantedFault::backend_ = nullptr;
std::string PlantedFault::backend_error_;
std::map<std::string, Ran> PlantedFault::runs_;

TEST_F(PlantedFault, DropMissFails) {
  const Verdict v = plant("results/miss-xor-closest-hit", "drop-miss");
  EXPECT_EQ(v.status, Status::Fail) << v.headline();
  EXPECT_TRUE(hasFinding(v, Status::Fail, "R-MISS-XOR-CHIT")) << v.headline();
}

TEST_F(PlantedFault, SwapPrimitiveIdFails) {
  const Verdict v = plant("anyhit/ignore-odd-primitives", "swap-primitive-id");
  EXPECT_EQ(v.status, Status::Fail) << v.headline();
  // The field's rule in the headline; the case's claims the field evidences
  // stay named by the finding (a proof of R-IGNORE reads them).
  EXPECT_EQ(v.headline().rfind("Fail: R-BUILTIN: per-ray field 'primitive_id' differs", 0), 0u)
      << v.headline();
  EXPECT_TRUE(hasFinding(v, Status::Fail, "R-IGNORE")) << v.headline();
  EXPECT_TRUE(hasFinding(v, Status::Fail, "image")) << "the primitive image shows the swap";
}

TEST_F(PlantedFault, ClosestHitAfterIgnoreFails) {
  const Verdict v = plant("anyhit/ignore-odd-primitives", "chit-after-ignore");
  EXPECT_EQ(v.status, Status::Fail) << v.headline();
  EXPECT_TRUE(hasFinding(v, Status::Fail, "R-MISS-XOR-CHIT")) << v.headline();
}

TEST_F(PlantedFault, ShiftTFails) {
  const Verdict v = plant("anyhit/ignore-odd-primitives", "shift-t");
  EXPECT_EQ(v.status, Status::Fail) << v.headline();
  EXPECT_TRUE(hasFinding(v, Status::Fail, "R-IGNORE")) << v.headline();
}

TEST_F(PlantedFault, DuplicateAnyHitFails) {
  const Verdict v = plant("anyhit/no-duplicate-any-hit", "duplicate-any-hit");
  EXPECT_EQ(v.status, Status::Fail) << v.headline();
  EXPECT_TRUE(hasFinding(v, Status::Fail, "R-AHIT-DUP")) << v.headline();
}

TEST_F(PlantedFault, LeakAtSharedEdgeIsAQualityWarning) {
  const Ran& r = run("watertight/shared-edges");
  ASSERT_FALSE(r.model.ambiguous.empty()) << "the model marks rays on shared edges ambiguous";
  const Verdict v = plant("watertight/shared-edges", "leak-edge");
  EXPECT_EQ(v.status, Status::QualityWarning) << v.headline();
  EXPECT_TRUE(hasFinding(v, Status::QualityWarning, "R-WATERTIGHT")) << v.headline();
}

TEST_F(PlantedFault, NoDuplicateAnyHitCaseChecksEveryRay) {
  const Ran& r = run("anyhit/no-duplicate-any-hit");
  const Verdict v = compareResults(r.c, r.plan, r.device, r.model);
  EXPECT_TRUE(hasFinding(v, Status::Pass, "R-AHIT-DUP")) << "the at-most check ran";
  // Every ray misses after any-hit ran on each crossed triangle; some cross two.
  const RecordField* ahit = findRecordField("any_hit_runs");
  uint32_t most = 0;
  for (size_t i = 0; i + recordWords() <= r.model.records.size(); i += recordWords())
    most = std::max(most, r.model.records[i + ahit->offset]);
  EXPECT_EQ(most, 2u);
}

// callable/light-equivalence for each light type (the raygen record's word
// 0): the callable's and the inline colour are identical on the device and in
// the model; a device whose callable records run the next record's callable
// breaks the identity on the device.
TEST_F(PlantedFault, LightEquivalenceForEveryLightType) {
  ASSERT_TRUE(backend_) << backend_error_;
  const std::string cases = RAYSPEC_SOURCE_DIR "/cases";
  ParseResult parsed = parseCaseFile(cases + "/callable/light-equivalence.yaml", cases);
  ASSERT_TRUE(parsed.value);
  for (uint32_t type : {0u, 1u, 2u}) {
    Case c = *parsed.value;
    c.pipeline.raygen_data = {type};
    const Plan plan = derivePlan(c);
    const Results model = runOnModel(c, plan, ModelOptions{});
    const Results device = backend_->run(c, plan);
    const Verdict v = compareResults(c, plan, device, model);
    EXPECT_EQ(v.status, Status::Pass) << "light type " << type << ": " << v.headline();
    EXPECT_TRUE(hasFinding(v, Status::Pass, "image")) << "the identity was checked";
    if (type != 0) continue;
    Results broken = device;
    const FaultResult f = plantFault("callable-record-shifted", c, plan, broken, model);
    ASSERT_TRUE(f.applied) << f.what;
    const Verdict bv = compareResults(c, plan, broken, model);
    EXPECT_EQ(bv.status, Status::Fail) << bv.headline();
    bool named = false;
    for (const Finding& fd : bv.findings)
      named = named || fd.message.find("differ on the device") != std::string::npos;
    EXPECT_TRUE(named) << bv.headline();
  }
}

// Hand-built: a fault that finds no ray to corrupt says so and changes nothing.
TEST(PlantedFaultNames, UnknownOrInapplicableFaultChangesNothing) {
  Case c;
  Plan plan;
  Results device, model;
  device.records.assign(2 * recordWords(), 0);
  model.records = device.records;
  for (const char* name : {"drop-miss", "swap-primitive-id", "shift-t", "leak-edge", "nonsense"}) {
    const FaultResult f = plantFault(name, c, plan, device, model);
    EXPECT_FALSE(f.applied) << name;
    EXPECT_FALSE(f.what.empty()) << name;
  }
  EXPECT_EQ(device.records, model.records);
  EXPECT_TRUE(isFaultName("crash"));
  EXPECT_TRUE(isProcessFault("hang"));
  EXPECT_FALSE(isFaultName("nonsense"));
}

// ---- interval ends, ties and large coordinates ----------------------------

namespace numerics {

// Rays whose record differs between two results.
std::set<uint32_t> changedRays(const Results& a, const Results& b) {
  std::set<uint32_t> out;
  const size_t words = recordWords();
  for (uint32_t ray = 0; ray * words < a.records.size(); ++ray)
    if (!std::equal(a.records.begin() + ray * words, a.records.begin() + (ray + 1) * words,
                    b.records.begin() + ray * words))
      out.insert(ray);
  return out;
}

const Finding* failing(const Verdict& v, const std::string& field) {
  for (const Finding& f : v.findings)
    if (f.status == Status::Fail && f.message.find("'" + field + "'") != std::string::npos)
      return &f;
  return nullptr;
}

// The device answers `ray` with a miss, or with a hit on (instance, primitive)
// of geometry 0.
void answerMiss(const Case& c, RecordEdit& e, uint32_t ray) {
  if (e.get(ray, "closest_hit_runs") == 0) return;
  e.set(ray, "closest_hit_runs", 0);
  e.set(ray, "miss_runs", 1);
  e.set(ray, "hit", 0);
  e.bumpCounter(closestHitCounters(c), -1);
  e.bumpCounter(missCounters(c), +1);
}
// A hit's t: the model's where it hit too (a tie's answers share it).
void answerHit(const Case& c, RecordEdit& e, uint32_t ray, uint32_t instance, uint32_t primitive,
               const Results* model = nullptr) {
  if (e.get(ray, "closest_hit_runs") == 0) {
    e.bumpCounter(closestHitCounters(c), +1);
    e.bumpCounter(missCounters(c), -1);
  }
  e.set(ray, "closest_hit_runs", 1);
  e.set(ray, "miss_runs", 0);
  e.set(ray, "hit", 1);
  for (const std::string& f : c.outputs.per_ray) {
    if (f == "instance_id") e.set(ray, f, instance);
    if (f == "primitive_id") e.set(ray, f, primitive);
    if (f == "hit_t" && model && RecordView{*model}.written(ray, f))
      e.set(ray, f, RecordView{*model}.get(ray, f));
  }
}

}  // namespace numerics

// R-CAND-TRI-OPEN: a device that hits a triangle at exactly tmax or tmin
// fails on every ray the candidates case puts on an exact end. The
// near-but-inexact rays are ambiguous: the planted device answers them one
// legal way, which is never judged a failure.
TEST_F(PlantedFault, ClosedTriangleIntervalFails) {
  Results planted;
  const Verdict v =
      plant("candidates/triangle-open-interval", "closed-triangle-interval", &planted);
  EXPECT_EQ(v.status, Status::Fail) << v.headline();
  EXPECT_TRUE(hasFinding(v, Status::Fail, "R-CAND-TRI-OPEN")) << v.headline();
  const Ran& r = run("candidates/triangle-open-interval");
  std::set<uint32_t> changed = numerics::changedRays(planted, r.device);
  for (const RayAmbiguity& a : r.model.ambiguous) changed.erase(a.ray);
  ASSERT_FALSE(changed.empty());
  const Finding* hit = numerics::failing(v, "hit");
  ASSERT_NE(hit, nullptr) << v.headline();
  EXPECT_EQ(hit->ray_count, changed.size()) << "every ray on an exact end is judged";
}

// R-CAND-AABB-CLOSED: a device whose reportIntersectionEXT rejects t ==
// tmin or t == tmax fails; the report's own return value shows it.
TEST_F(PlantedFault, OpenAabbIntervalFails) {
  Results planted;
  const Verdict v = plant("candidates/aabb-closed-interval", "open-aabb-interval", &planted);
  EXPECT_EQ(v.status, Status::Fail) << v.headline();
  EXPECT_TRUE(hasFinding(v, Status::Fail, "R-CAND-AABB-CLOSED")) << v.headline();
  const Ran& r = run("candidates/aabb-closed-interval");
  EXPECT_TRUE(r.model.ambiguous.empty()) << "no AABB end is a tie before a hit is committed";
  const Finding* value = numerics::failing(v, "value");
  ASSERT_NE(value, nullptr) << v.headline();
  EXPECT_GE(value->ray_count, 8u) << "the tmax and tmin reports of four intervals";
}

// R-TIE: where t rounds on a device (tmin-tie, tmax-tie) hit and miss are
// both legal, and a device giving either passes; one that answers neither
// (another primitive, or a miss on a tie of two coincident triangles) fails.
TEST_F(PlantedFault, InexactEndTiesAcceptBothAnswersAndNothingElse) {
  for (const std::string name : {"candidates/triangle-open-interval", "precision/tmax-ties"}) {
    const Ran& r = run(name);
    size_t ends = 0;
    for (const RayAmbiguity& a : r.model.ambiguous) {
      if (a.reason != AmbiguityReason::TminTie && a.reason != AmbiguityReason::TmaxTie) continue;
      ++ends;
      bool miss = false;
      const Candidate* hit = nullptr;
      for (const Candidate& k : a.candidates) (k.hit ? hit = &k : (miss = true, hit));
      ASSERT_TRUE(miss && hit) << name << " ray " << a.ray;
      const uint32_t ray = a.ray;
      EXPECT_EQ(
          edited(name, [&](const Ran& x, RecordEdit& e) { numerics::answerMiss(x.c, e, ray); })
              .status,
          Status::Pass)
          << name << " ray " << ray;
      const Verdict as_hit = edited(name, [&](const Ran& x, RecordEdit& e) {
        numerics::answerHit(x.c, e, ray, hit->instance, hit->primitive, &x.model);
        // Where the model missed, the hit's closest-hit records its own t.
        if (!RecordView{x.model}.written(ray, "hit_t") &&
            std::count(x.c.outputs.per_ray.begin(), x.c.outputs.per_ray.end(), "hit_t"))
          e.setFloat(ray, "hit_t", static_cast<float>(hit->t));
      });
      EXPECT_EQ(as_hit.status, Status::Pass) << name << " ray " << ray << ": " << as_hit.headline();
      const Verdict other = edited(name, [&](const Ran& x, RecordEdit& e) {
        numerics::answerHit(x.c, e, ray, hit->instance + 1, hit->primitive + 7);
      });
      EXPECT_EQ(other.status, Status::Fail) << name << " ray " << ray;
      EXPECT_TRUE(hasFinding(other, Status::Fail, "R-TIE")) << other.headline();
    }
    EXPECT_GE(ends, 2u) << name << ": ties at both ends";
  }
  const Ran& r = run("precision/tmax-ties");
  for (const RayAmbiguity& a : r.model.ambiguous) {
    if (a.reason != AmbiguityReason::TTie) continue;
    const Verdict v = edited("precision/tmax-ties", [&](const Ran& x, RecordEdit& e) {
      numerics::answerMiss(x.c, e, a.ray);
    });
    EXPECT_EQ(v.status, Status::Fail)
        << "a miss on a tie of two hits, ray " << a.ray << ": " << v.headline();
    EXPECT_TRUE(hasFinding(v, Status::Fail, "R-TIE")) << v.headline();
  }
}

// R-TIE with AABBs: any of the tied (instance, primitive) pairs passes; a
// miss, or a primitive outside them, fails.
TEST_F(PlantedFault, AabbTieAcceptsEveryTiedPairAndNothingElse) {
  const Ran& r = run("precision/aabb-tie");
  ASSERT_FALSE(r.model.ambiguous.empty());
  for (const RayAmbiguity& a : r.model.ambiguous) {
    ASSERT_EQ(a.reason, AmbiguityReason::TTie);
    for (const Candidate& k : a.candidates)
      EXPECT_EQ(edited("precision/aabb-tie",
                       [&](const Ran& x, RecordEdit& e) {
                         numerics::answerHit(x.c, e, a.ray, k.instance, k.primitive, &x.model);
                       })
                    .status,
                Status::Pass)
          << "ray " << a.ray << " instance " << k.instance << " primitive " << k.primitive;
    EXPECT_EQ(edited("precision/aabb-tie",
                     [&](const Ran& x, RecordEdit& e) { numerics::answerMiss(x.c, e, a.ray); })
                  .status,
              Status::Fail)
        << "ray " << a.ray;
    EXPECT_EQ(edited("precision/aabb-tie",
                     [&](const Ran& x, RecordEdit& e) { numerics::answerHit(x.c, e, a.ray, 0, 5); })
                  .status,
              Status::Fail)
        << "ray " << a.ray << ": primitive 5 does not exist";
  }
}

// R-PREC at 1e5: a ray through a triangle's interior is clear in every grid
// of the large-coordinates case (vertices at 1e5, an instance translation,
// a rotated instance), so a device that misses one fails; a miss on a
// shared edge stays a leak (a quality warning).
TEST_F(PlantedFault, CentreMissAtLargeCoordinatesFails) {
  const Ran& r = run("precision/large-coordinates");
  std::set<uint32_t> amb;
  for (const RayAmbiguity& a : r.model.ambiguous) amb.insert(a.ray);
  RecordEdit model{const_cast<Results&>(r.model)};
  std::set<uint32_t> instances;
  for (uint32_t ray = 0; ray < model.rays(); ++ray) {
    if (amb.count(ray) || model.get(ray, "hit") != 1 ||
        instances.count(model.get(ray, "instance_id")))
      continue;
    instances.insert(model.get(ray, "instance_id"));
    const Verdict v = edited("precision/large-coordinates", [&](const Ran& x, RecordEdit& e) {
      numerics::answerMiss(x.c, e, ray);
    });
    EXPECT_EQ(v.status, Status::Fail) << "ray " << ray << ": " << v.headline();
    const Finding* hit = numerics::failing(v, "hit");
    ASSERT_NE(hit, nullptr);
    EXPECT_EQ(hit->rays, std::vector<uint32_t>{ray});
  }
  EXPECT_EQ(instances.size(), 3u) << "a clear interior ray in each grid";
  for (const RayAmbiguity& a : r.model.ambiguous) {
    if (a.reason != AmbiguityReason::Edge || a.shared_triangles.size() < 2) continue;
    const Verdict v = edited("precision/large-coordinates", [&](const Ran& x, RecordEdit& e) {
      numerics::answerMiss(x.c, e, a.ray);
    });
    EXPECT_EQ(v.status, Status::QualityWarning) << v.headline();
    break;
  }
}

}  // namespace
}  // namespace rayspec
