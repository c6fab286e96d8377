// What `rayspec export --format c` exports so far, and the refusal of the
// rest: a case is exported when its shape is one the player (player.c)
// plays and its expectations are ones the player's comparison can hold.
#pragma once

#include <string>

#include "case/case.h"
#include "plan/plan.h"
#include "results/results.h"

namespace rayspec {

// "" when the case can be exported; else the feature it uses that the export
// does not handle yet, named for "export: case uses X, not yet exported".
// model: the model's exact tier run of the case.
std::string unexportedFeature(const Case& c, const Plan& plan, const Results& model);

}  // namespace rayspec
