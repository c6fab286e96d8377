// Every planted fault is caught: each test runs a real case on the Vulkan
// device (lavapipe) and on the model, checks the pair passes untouched, plants
// the fault in the device's results and asserts the status it must give.
// Without the comparison catching the fault the status would stay Pass.
#include <gtest/gtest.h>

#include <map>
#include <memory>

#include "case/parse_case.h"
#include "compare/compare_results.h"
#include "fault/planted_fault.h"
#include "model/model_backend.h"
#include "plan/plan.h"
#include "results/record_layout.h"
#include "vulkan/vulkan_backend.h"

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
    backend_ = VulkanBackend::create(opt, &backend_error_).release();
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
  Verdict plant(const std::string& case_name, const std::string& fault) {
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
    return compareResults(r.c, r.plan, corrupted, r.model);
  }

  static bool hasFinding(const Verdict& v, Status s, const std::string& rule) {
    for (const Finding& f : v.findings)
      if (f.status == s && f.rule.find(rule) != std::string::npos) return true;
    return false;
  }

  static VulkanBackend* backend_;
  static std::string backend_error_;
  static std::map<std::string, Ran> runs_;
};

VulkanBackend* PlantedFault::backend_ = nullptr;
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
  // Not a rule the case checks by its field: the case's own rules are named.
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
    for (const Finding& fd : bv.findings) named = named || fd.message.find("differ on the device") != std::string::npos;
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

}  // namespace
}  // namespace rayspec
