// A case checked before it runs (`rayspec run --check-case`, issue 61): the
// check (the command line's: every device the specification allows must
// pass the case, mutate/case_portability.h) runs on the case as it will run,
// in a child process under the run's limits (in this process with
// --no-isolation), before any case runs; a case it refuses is a CaseError
// (finding `not-portable`) and does not run. By default (--check-case
// neither given nor refused) the cases of files outside the library folder
// (RAYSPEC_SOURCE_DIR/cases) are checked: the library's own are held to
// every legal device by ctest (mutate/kill-matrix).
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "case/case.h"
#include "library/case_discovery.h"
#include "report/case_outcome.h"
#include "run/run_options.h"

namespace rayspec {

// "" when the case passes the check, else the CaseError's message.
using CaseCheck = std::function<std::string(const Case&)>;

// The library folder, whose cases are not checked by default.
inline constexpr const char* kLibraryCasesDir = RAYSPEC_SOURCE_DIR "/cases";

// Whether `path` lies inside `folder` (both as the file system resolves them).
bool insideFolder(const std::string& path, const std::string& folder);

// Whether the run checks the case of `file`: --check-case or
// --no-check-case, else whether the file lies outside the library folder.
bool checksCase(const RunOptions& opt, const CaseFile& file);

// What the check made of a case: the CaseError outcome of a case it
// refuses (then the case does not run), or, for a case it could not finish
// on (the check crashed, ran out of memory or past --timeout: the case runs
// unchecked, and shows its own crash or timeout), a note that joins the
// case's findings. A line on standard output says how the check went.
struct CheckedCase {
  std::optional<CaseOutcome> refused;
  std::string not_checked;
};
CheckedCase checkedCase(const CaseCheck& check, const Case& c, const RunOptions& opt);

}  // namespace rayspec
