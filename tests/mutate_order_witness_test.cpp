// The legal orders that decide one candidate after every other (fault/
// planted_fault.h lastCandidateDevices) as witnesses of mutate/legal_output:
// a planted query fault that answers as one of them does is a legal
// survivor, each such order is recognised as legal, and a device that
// answers what no legal order gives is still a hole (or killed).
#include <gtest/gtest.h>

#include "compare/compare_results.h"
#include "fault/planted_fault.h"
#include "fault/record_edit.h"
#include "mutate/legal_output.h"
#include "mutate_suite_case.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

// Four layers of non-opaque triangles under every ray: layers 0 and 1
// ignored, 2 terminates, 3 let be. Every order commits layer 2.
constexpr const char* kStop2[] = {
    "control/any-hit-functions/switch-stop-2", "control/any-hit-functions/loop-stop-2",
    "control/any-hit-functions/nested-stop-2", "control/any-hit-functions/early-return-stop-2"};

// One case through ray-query, its model run and the model as a device.
struct Judged {
  Case c;
  Plan plan;
  Results model, base;
  explicit Judged(const std::string& name)
      : c(suiteCaseThrough(name, FeaturePath::RayQuery)),
        plan(derivePlan(c)),
        model(runOnModel(c, plan, {})),
        base(perfectDevice(c, model)) {}
  std::string legal(const Results& device) const {
    return legalOutput(c, plan, model, base, device, changedRays(device));
  }
  std::vector<uint32_t> changedRays(const Results& device) const {
    std::vector<uint32_t> rays;
    const uint32_t words = recordWords();
    for (uint32_t ray = 0; ray * words < base.records.size(); ++ray)
      if (!std::equal(base.records.begin() + ray * words, base.records.begin() + (ray + 1) * words,
                      device.records.begin() + ray * words))
        rays.push_back(ray);
    return rays;
  }
};

// The loop going on past an ignored terminate commits layer 2 after running
// any-hit for all four layers: what a device meeting layer 2 last gives.
TEST(MutateOrderWitness, TerminateIgnoredAnswersAsTheTerminatingCandidateLast) {
  for (const char* name : kStop2) {
    const CaseMutation m = mutateSuiteCase(name, FeaturePath::RayQuery);
    ASSERT_TRUE(m.judged) << name << ": " << m.not_judged;
    const MutantOutcome* o = findPlanted(m, "query-terminate-ignored");
    ASSERT_NE(o, nullptr) << name;
    ASSERT_TRUE(o->mutation.applied) << name << ": " << o->mutation.what;
    EXPECT_FALSE(o->killed) << name << ": " << o->headline;
    EXPECT_EQ(o->legal_reason.rfind("R-ORDER-UNSPEC", 0), 0u) << name << ": " << o->legal_reason;
    size_t witnesses = 0;
    for (const LegalDevice& d : m.legal_devices) {
      EXPECT_FALSE(d.false_alarm) << name << " " << d.name << ": " << d.headline;
      witnesses += d.name.rfind("last-", 0) == 0;
    }
    EXPECT_EQ(witnesses, 4u) << name << ": one per layer";
  }
}

// Each candidate decided last is a legal device the judge passes, and
// legal_output recognises what it answers as legal.
TEST(MutateOrderWitness, EachWitnessOrderRecognised) {
  const Judged j("control/any-hit-functions/loop-stop-2");
  const std::vector<NamedDevice> witnesses = lastCandidateDevices(j.c, j.plan, 0);
  ASSERT_EQ(witnesses.size(), 4u);
  size_t differing = 0;
  for (const NamedDevice& w : witnesses) {
    ASSERT_TRUE(w.device.ok()) << w.name;
    Results device = w.device;
    device.backend = "vulkan";
    EXPECT_FALSE(isFailing(compareResults(j.c, j.plan, device, j.model).status)) << w.name;
    if (j.changedRays(w.device).empty()) continue;
    ++differing;
    EXPECT_EQ(j.legal(w.device).rfind("R-ORDER-UNSPEC", 0), 0u) << w.name;
  }
  // Layer 3 last runs the model's any-hits (layer 2 ends the traversal
  // first); layer 0 or 1 last runs two (1 or 0 ignored, then 2), layer 2
  // last all four: each commits layer 2.
  EXPECT_EQ(differing, 3u);
}

// Sound the other way: the witness of layer 2 last with one ray changed to
// what no legal order gives is no legal output, and the judge fails it.
TEST(MutateOrderWitness, WhatNoLegalOrderGivesStaysAHole) {
  const Judged j("control/any-hit-functions/loop-stop-2");
  const std::vector<NamedDevice> witnesses = lastCandidateDevices(j.c, j.plan, 0);
  const auto last2 = std::find_if(witnesses.begin(), witnesses.end(),
                                  [](const NamedDevice& w) { return w.name == "last-0.0.2"; });
  ASSERT_NE(last2, witnesses.end());
  Results layer3 = last2->device;  // layer 3 committed: the terminate lost
  RecordEdit{layer3}.set(0, "primitive_id", 3);
  RecordEdit{layer3}.setFloat(0, "hit_t", 8.0f);
  EXPECT_EQ(j.legal(layer3), "");
  layer3.backend = "vulkan";
  EXPECT_TRUE(isFailing(compareResults(j.c, j.plan, layer3, j.model).status));
  Results five_runs = last2->device;  // five any-hits of four layers, NO_DUPLICATE or not
  RecordEdit{five_runs}.set(0, "any_hit_runs", 5);
  EXPECT_EQ(j.legal(five_runs), "");
}

}  // namespace
}  // namespace rayspec
