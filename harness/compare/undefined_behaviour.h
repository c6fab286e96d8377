// Rays whose behaviour the specification leaves undefined (R-UB), as the model
// found them (Results::undefined): the case's own diagnosis, never judged and
// never blamed on the driver.
#pragma once

#include "case/case.h"
#include "compare/verdict.h"
#include "results/results.h"

namespace rayspec {

// The model's undefined rays by reason (in reason order), with the first
// rays and the first ray's `what` of each.
std::vector<UndefinedRays> groupUndefinedRays(const std::vector<UndefinedRay>& rays);

// What undefined rays make of a case's verdict; the one place it is decided.
// v holds the device's own status (backendVerdict) when called. With no
// undefined rays (or no model result) v is left as it is. Otherwise v.undefined
// gets the groups, and:
//   - a case that does not claim R-UB is at fault itself: v becomes CaseError
//     whatever the device did ("the device crashed; the case has undefined
//     behaviour: ..." when it crashed or hung), and nothing is compared;
//   - a case that claims R-UB is a robustness probe: its undefined rays only
//     need the device to survive. A device Crash / Timeout stays what it is
//     (nothing is compared); a device that ran gets an informational Pass
//     finding "R-UB probe: ...", and its other rays are judged as usual.
// Returns true when the comparison of the other rays goes on.
bool judgeUndefinedBehaviour(const Case& c, const Results& device, const Results& model,
                             Verdict& v);

}  // namespace rayspec
