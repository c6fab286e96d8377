// Turns the device's results and the model's into a verdict under the rules
// of the specification: counters by their mode, per-ray records exactly on
// clear rays and by the rule on ambiguous ones, images texel by texel.
#pragma once

#include "case/case.h"
#include "compare/verdict.h"
#include "plan/plan.h"
#include "results/results.h"

namespace rayspec {

// At most this many ray indices are kept per finding.
constexpr size_t kFirstRays = 8;

Verdict compareResults(const Case& c, const Plan& plan, const Results& device,
                       const Results& model);

// The status a backend reported as a verdict of its own; Pass for Ok.
Verdict backendVerdict(const Results& r);

// How far a legal device's exact (or at_least / at_most) counter may lie
// below and above the model's: what the legal answers of the model's
// ambiguous rays can change (compare_counters.cpp). Where every ambiguous ray
// has its answers replayed (RayAmbiguity::replays), the sums of each ray's
// largest moves down and up; else a slack both ways from what the case's
// shape tells.
struct CounterSlack {
  uint64_t below = 0, above = 0;
  bool replayed = false;  // from the replays
  bool operator==(const CounterSlack&) const = default;
};
CounterSlack counterSlack(const Case& c, const std::string& counter, const Results& model);

}  // namespace rayspec
