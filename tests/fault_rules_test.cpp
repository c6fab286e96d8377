// Every rule a case claims is proven by a planted fault: the model's exact
// tier serves as the perfect device (no Vulkan), each fault of the rule
// (fault/rule_faults.h) is planted in its results, and the comparison must
// give Fail (QualityWarning for R-WATERTIGHT). A claim no fault breaks is
// hollow and fails here, named with every fault's outcome. Every case must
// also pass a device that finds candidates far to near (R-ORDER-UNSPEC).
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <set>

#include "compare/compare_results.h"
#include "fault/planted_fault.h"
#include "fault/prove_case.h"
#include "fault/rule_faults.h"
#include "model/model_engine.h"
#include "parse/parse_case.h"
#include "plan/plan.h"
#include "suite_cases.h"

namespace rayspec {
namespace {

const std::string kCases = kSuiteCases;

std::vector<std::string> caseNames() {
  std::vector<std::string> names;
  for (const CaseFile& f : suiteCases()) names.push_back(f.name);
  return names;
}

ParseResult parseNamed(const std::string& name) {
  const std::optional<CaseFile> f = suiteCase(name);
  if (!f) return ParseResult{};
  return loadSuiteCase(*f);
}

struct Judged {
  Case c;
  Plan plan;
  Results model, perfect;
};

Judged judge(const std::string& name) {
  ParseResult parsed = parseNamed(name);
  Judged j;
  if (!parsed.value) {
    ADD_FAILURE() << name << ": " << (parsed.errors.empty() ? "" : parsed.errors[0].format());
    return j;
  }
  j.c = *parsed.value;
  j.plan = derivePlan(j.c);
  j.model = runOnModel(j.c, j.plan, ModelOptions{});
  j.perfect = perfectDevice(j.c, j.model);
  return j;
}

class CaseClaims : public ::testing::TestWithParam<std::string> {};

TEST_P(CaseClaims, EveryClaimedRuleIsBrokenByAFault) {
  ParseResult parsed = parseNamed(GetParam());
  ASSERT_TRUE(parsed.value) << (parsed.errors.empty() ? "" : parsed.errors[0].format());
  // The proof `rayspec prove` gives (fault/prove_case.h).
  const CaseProof proof = proveCase(*parsed.value);
  ASSERT_TRUE(proof.model.ok()) << proof.model.statusText();
  ASSERT_EQ(proof.clean.status, Status::Pass)
      << "the model as a device does not pass: " << proof.clean.headline();
  for (const ClaimProof& p : proof.claims) {
    std::cout << GetParam() << " " << p.describe() << "\n";
    EXPECT_TRUE(claimHolds(p)) << "hollow claim: " << GetParam() << " claims " << p.describe();
  }
  EXPECT_EQ(proof.reversed.status, Status::Pass)
      << "the verdict depends on the candidate order: " << proof.reversed.headline();
}

INSTANTIATE_TEST_SUITE_P(Cases, CaseClaims, ::testing::ValuesIn(caseNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string n = info.param;
                           for (char& ch : n)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return n;
                         });

TEST(RuleFaultTable, OneEntryPerRuleOfTheCatalogAndEveryFaultUsed) {
  const YAML::Node catalog = YAML::LoadFile(RAYSPEC_SOURCE_DIR "/references/spec-rules.yaml");
  std::set<std::string> rules;
  for (const auto& kv : catalog) rules.insert(kv.first.as<std::string>());
  std::set<std::string> used;
  for (const RuleFaults& r : ruleFaults()) {
    EXPECT_TRUE(rules.count(r.rule)) << r.rule << " is not in references/spec-rules.yaml";
    for (const auto* list : {&r.breaks, &r.legal})
      for (const std::string& f : *list) {
        const FaultInfo* info = findFault(f);
        ASSERT_NE(info, nullptr) << r.rule << ": no fault named " << f;
        EXPECT_NE(info->kind, FaultKind::Process) << f;
        EXPECT_NE(info->kind, FaultKind::Vulkan) << f << ": a live device's fault belongs in live";
        used.insert(f);
      }
    for (const std::string& f : r.live) {
      const FaultInfo* info = findFault(f);
      ASSERT_NE(info, nullptr) << r.rule << ": no fault named " << f;
      EXPECT_EQ(info->kind, FaultKind::Vulkan) << f;
      used.insert(f);
    }
    EXPECT_TRUE(!r.breaks.empty() || !r.legal.empty() || !r.pending.empty())
        << r.rule << " has no proof";
  }
  for (const std::string& rule : rules)
    EXPECT_NE(findRuleFaults(rule), nullptr) << rule << " has no entry";
  for (const FaultInfo& f : faultTable()) {
    // The run's own faults (a crash, a lost device) break no rule:
    // tests/fault_table_test.cpp names them.
    if (f.kind == FaultKind::Process || f.kind == FaultKind::Vulkan) continue;
    EXPECT_TRUE(used.count(f.name)) << f.name << " stands for no rule";
  }
}

// The coverage contract: every rule but R-UB is claimed by some case.
TEST(RuleFaultTable, EveryRuleIsClaimedByACase) {
  std::set<std::string> claimed;
  for (const std::string& name : caseNames()) {
    ParseResult parsed = parseNamed(name);
    ASSERT_TRUE(parsed.value) << name;
    claimed.insert(parsed.value->rules.begin(), parsed.value->rules.end());
  }
  for (const RuleFaults& r : ruleFaults()) {
    if (r.rule == "R-UB") continue;
    EXPECT_TRUE(claimed.count(r.rule)) << r.rule << " is claimed by no case";
  }
}

// The proof can fail: a claim the case does not check is named hollow.
TEST(RuleFaultTable, AClaimTheCaseDoesNotCheckIsHollow) {
  Judged j = judge("anyhit/unused-any-hit");
  for (const char* rule : {"R-MASK", "R-SBT-MISS", "R-TOFH"}) {
    const ClaimProof p = proveClaim(j.c, j.plan, j.model, j.perfect, rule);
    EXPECT_EQ(p.result, ClaimResult::Hollow) << p.describe();
  }
}

// A case whose check a legal variation breaks is named: the intersection
// counter of sphere-both-roots declared exact fails a device that runs an
// intersection shader twice (R-ISECT-MULTI allows it).
TEST(RuleFaultTable, ACaseThatFailsALegalDeviceIsNamed) {
  Judged j = judge("intersection/sphere-both-roots");
  j.c.outputs.counter_modes["isect"] = "exact";
  const ClaimProof p = proveClaim(j.c, j.plan, j.model, j.perfect, "R-ISECT-MULTI");
  EXPECT_EQ(p.result, ClaimResult::FailsLegal) << p.describe();
  j.c.outputs.counter_modes["isect"] = "at_least";
  EXPECT_EQ(proveClaim(j.c, j.plan, j.model, j.perfect, "R-ISECT-MULTI").result,
            ClaimResult::Proven);
}

}  // namespace
}  // namespace rayspec
