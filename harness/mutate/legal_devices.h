// The dual of the kill matrix: devices the specification allows that differ
// from the model, each judged by the usual comparison against the model. A
// correct driver never fails, so each must Pass (or QualityWarning where a
// "should" is not met); a Fail is a false alarm of the judge.
//   answer-<j>          every ambiguous ray takes its j-th legal answer, its
//                       shaders run as that answer makes them run (the model
//                       replays the trace so: fault/planted_fault.h)
//   replay-<j>          every ambiguous ray leaves its j-th legal answer
//                       as the model replayed it through the launch ray
//                       (its whole record, the counters as it moves them)
//   pass-between-edges  every ray through a shared edge or vertex passes
//                       between its triangles where that changes the answer
//                       (R-WATERTIGHT, a "should": QualityWarning at most)
//   <legal fault>       each planted fault the catalog calls legal (any-hit
//                       repeated without NO_DUPLICATE, candidates far to near, ...)
//   aabb-neighbours     intersection programs also run for the boxes beside
//                       the entered ones (R-AABB-CONS: the test is conservative)
//   aabb-near           intersection programs also run for every box a ray
//                       misses by no more than a device's error bound (R-PREC:
//                       model/box_bound.h; whole units from a far origin)
//   last-<i>.<g>.<p>    candidate (instance i, geometry g, primitive p)
//                       decided after every other, the rest near to far
//                       (R-ORDER-UNSPEC; one per candidate of a scene of at
//                       most kMaxLastCandidates: fault/planted_fault.h)
//   tolerance-bound     every written hit_t, hit_position and barycentric
//                       moved by 0.9 of the error the comparison allows (the
//                       model's t bound of the ray, carried into hit_position)
#pragma once

#include <string>
#include <vector>

#include "case/case.h"
#include "compare/verdict.h"
#include "plan/plan.h"
#include "results/results.h"

namespace rayspec {

struct LegalDevice {
  std::string name;
  bool applied = false;  // false: the variant does not differ from the model here
  std::string what;      // what it changes, or why it does not apply
  Status status = Status::Pass;
  std::string headline;  // the verdict's
  bool false_alarm = false;
  // A false alarm's first failing finding: its rule and first ray.
  std::string rule;
  int64_t ray = -1;
};

// One legal device's results, before they are judged.
struct LegalVariant {
  std::string name;
  Results device;
  bool applied = false;  // false: the variant does not differ from the model here
  std::string what;      // what it changes, or why it does not apply
};

// The legal devices of one case made from `model` (the exact tier's run of
// the case, as `rayspec mutate` makes it); `threads` for the model's runs of
// the answer variants (0: every core).
std::vector<LegalVariant> legalVariants(const Case& c, const Plan& plan, const Results& model,
                                        unsigned threads);
// One legal device judged against `model` by the usual comparison, as a
// device's results (v.device.backend becomes "vulkan"); the verdict in
// *verdict when given.
LegalDevice judgeLegalVariant(const Case& c, const Plan& plan, const Results& model,
                              LegalVariant& v, Verdict* verdict = nullptr);
// Every legal device of one case, each judged against `model`.
std::vector<LegalDevice> judgeLegalDevices(const Case& c, const Plan& plan, const Results& model,
                                           unsigned threads);

}  // namespace rayspec
