// Planted faults (test-only): corrupt a device's results in known ways after
// the device ran and before the comparison, so tests can show that the
// comparison catches each kind of driver bug. `rayspec run --plant-fault NAME`.
//   drop-miss          a clear ray whose miss ran loses it (miss_runs 0, its
//                      miss counter -1)
//   swap-primitive-id  two clear hit rays with different primitive ids swap them
//   chit-after-ignore  a clear ray that missed (its candidates ignored) gets
//                      closest_hit_runs + 1 and its closest-hit counter + 1
//   shift-t            hit_t += 1e-3 on one clear hit ray
//   duplicate-any-hit  any-hit runs once more on a ray of a scene whose
//                      geometries are NO_DUPLICATE_ANY_HIT (any_hit_runs + 1,
//                      any-hit counter + 1)
//   leak-edge          a ray the model marks ambiguous at a shared edge or
//                      vertex (a miss not legal) becomes a miss
//   closed-triangle-interval
//                      the device hits a triangle at exactly the ray's tmin
//                      or tmax (the model run with that deviation; every ray
//                      it answers differently takes that answer)
//   open-aabb-interval reportIntersectionEXT at exactly tmin or the current
//                      tmax returns false (likewise)
// Process faults, raised in the device's child process (rayspec run isolates
// each case's device side):
//   crash              raise SIGSEGV after the device run
//   hang               sleep forever after the device run
#pragma once

#include <string>
#include <vector>

#include "case/case.h"
#include "plan/plan.h"
#include "results/results.h"

namespace rayspec {

const std::vector<std::string>& faultNames();
bool isFaultName(const std::string& name);
bool isProcessFault(const std::string& name);  // crash, hang

struct FaultResult {
  bool applied = false;
  std::string what;  // what was corrupted ("ray 17: miss_runs 1 -> 0"), or why nothing was
};

// Corrupts `device` by the results fault `name`; `model` chooses the rays
// (clear or ambiguous). Process faults and unknown names change nothing.
FaultResult plantFault(const std::string& name, const Case& c, const Plan& plan, Results& device,
                       const Results& model);

// crash: raises SIGSEGV; hang: sleeps forever; otherwise returns.
void raiseProcessFault(const std::string& name);

}  // namespace rayspec
