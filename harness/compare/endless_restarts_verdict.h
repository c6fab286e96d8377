// R-RQ-INIT: a restart_query that restarts its query more than
// kMaxQueryRestarts times in one run of the query (program/program.h) may
// restart it forever: the model stops restarting there, as the GLSL does,
// and the case is diagnosed, not judged: CaseError "endless-restarts",
// naming each restart_query and its file:line.
#pragma once

#include "compare/verdict.h"
#include "results/results.h"

namespace rayspec {

// Returns true when the comparison goes on.
bool judgeEndlessRestarts(const Results& model, Verdict& v);

}  // namespace rayspec
