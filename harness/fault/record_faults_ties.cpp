// Record edits of rays the model marks ambiguous for a tie (R-TIE): a device
// that answers a tie with neither of the tied candidates.
#include "fault/fault_impl.h"

namespace rayspec {

FaultResult tieAnsweredNeither(RecordFaultArgs& a) {
  RecordEdit& dev = a.dev;
  for (const RayAmbiguity& amb : a.model.ambiguous) {
    if (amb.reason != AmbiguityReason::TTie && amb.reason != AmbiguityReason::TmaxTie &&
        amb.reason != AmbiguityReason::TminTie)
      continue;
    bool miss_legal = false;
    for (const Candidate& k : amb.candidates) miss_legal = miss_legal || !k.hit;
    if (miss_legal || amb.ray >= dev.rays() || dev.get(amb.ray, "closest_hit_runs") == 0) continue;
    dev.set(amb.ray, "closest_hit_runs", 0);
    dev.set(amb.ray, "miss_runs", 1);
    if (dev.written(amb.ray, "hit")) dev.set(amb.ray, "hit", 0);
    dev.bumpCounter(closestHitCounters(a.c), -1);
    dev.bumpCounter(missCounters(a.c), +1);
    return describeRay(amb.ray, std::string("a ") + ambiguityReasonName(amb.reason) +
                                    " answered with neither candidate: now a miss");
  }
  return notApplicable(
      "no tie ray the model marks ambiguous, without a legal miss, hit on the device");
}

}  // namespace rayspec
