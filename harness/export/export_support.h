// What `rayspec export --format c` exports so far, and the refusal of the
// rest: a case is exported when its shape is one the player (harness/export/player/)
// plays and its expectations are ones the player's comparison can hold.
#pragma once

#include <cstdint>
#include <string>

#include "case/case.h"
#include "plan/plan.h"
#include "results/results.h"

namespace rayspec {

// The most rays a reproducer embeds the records of (61 words a ray: a file
// of about 25 MB of C at most).
constexpr uint64_t kMaxExportedRays = 1u << 16;

// "" when the case can be exported; else the feature it uses that the export
// does not handle yet, named for "export: case uses X, not yet exported".
// model: the model's exact tier run of the case.
std::string unexportedFeature(const Case& c, const Plan& plan, const Results& model);

// r's image `name`, or null.
const Image* imageNamed(const Results& r, const std::string& name);

}  // namespace rayspec
