// The parts of compareResults, one file each (internal to compare/).
#pragma once

#include <set>

#include "compare/compare_results.h"

namespace rayspec {

// undefined_rays: how many rays the model found undefined (R-UB); the counters
// they may have moved (counter_modes.h) are then informational.
void compareCounters(const Case& c, const Results& device, const Results& model, size_t ambiguous_rays,
                     size_t undefined_rays, Verdict& v);
// `undefined`: rays left out (R-UB), as in compareAnyHitRuns.
void compareRecords(const Case& c, const Plan& plan, const Results& device, const Results& model,
                    const std::set<uint32_t>& undefined, Verdict& v);
// R-AHIT-DUP: with every geometry NO_DUPLICATE_ANY_HIT (triangles), a ray on
// which the model committed no hit ran any-hit once on every primitive it
// crosses: the device may run it at most that often on the ray.
void compareAnyHitRuns(const Case& c, const Results& device, const Results& model,
                       const std::set<uint32_t>& undefined, Verdict& v);
// masked: the pixels of ambiguous and of undefined rays, left out.
void compareImages(const Plan& plan, const Results& device, const Results& model, const std::set<uint32_t>& masked,
                   Verdict& v);
// Images a case declares equal (`equal_to`): texel for texel in the model
// (else CaseError: the case claims an identity its own reference does not
// have, and the device is not judged on them) and on the device (else Fail).
void compareEqualImages(const Plan& plan, const Results& device, const Results& model, Verdict& v);

// Collects the rays breaking one rule into one finding.
struct FindingBuilder {
  Finding finding;
  void addRay(uint32_t ray) {
    ++finding.ray_count;
    if (finding.rays.size() < kFirstRays) finding.rays.push_back(ray);
  }
  void flush(Verdict& v) {
    if (finding.ray_count) v.add(finding);
  }
};

}  // namespace rayspec
