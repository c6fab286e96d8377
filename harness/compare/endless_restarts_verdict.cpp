#include "compare/endless_restarts_verdict.h"

#include "program/program.h"

namespace rayspec {

bool judgeEndlessRestarts(const Results& model, Verdict& v) {
  if (model.endless_restarts.empty()) return true;
  std::string what;
  for (const std::string& o : model.endless_restarts) what += (what.empty() ? "" : "; ") + o;
  v.add({Status::CaseError,
         "R-RQ-INIT",
         "endless-restarts: " + what + "; a query restarts at most " +
             std::to_string(kMaxQueryRestarts) +
             " times in one run: make the restart conditional on what the block has seen (a "
             "local it sets), so that the new ray does not restart it again",
         {},
         0});
  return false;
}

}  // namespace rayspec
