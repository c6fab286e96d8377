// `rayspec devices --check-limits`: each usable device's ray tracing limits
// against the Vulkan specification's required ones (vulkan/required_limits.h),
// judged against a baseline of known violations the way `rayspec run` judges
// cases: a violation it does not list fails, one it lists that is gone is an
// unexpected pass (the baseline wants updating).
#pragma once

#include <string>
#include <vector>

#include "report/baseline.h"
#include "vulkan/vulkan_engine.h"

namespace rayspec {

struct LimitsVerdict {
  int violations = 0, expected = 0, unexpected = 0, unexpected_passes = 0;
  std::vector<std::string> unexpected_limits;  // limits/<name> of each unexpected violation
};

// Prints one line per limit; counts what the baseline says of them.
LimitsVerdict printLimitChecks(const DeviceInfo& d, const Baseline& baseline);

// The baseline of known violations (--check-limits --baseline FILE): one
// `limits/<name>,Fail` line per limit the driver is known to break. An entry
// that names no limit of the table (a case, a misspelt limit) or says any
// status but Fail would never apply: it is the error naming the file and
// line, as is a malformed line.
Result<Baseline> loadLimitsBaseline(const std::string& path);

// The limits baselines in `folder` (its *-limits.csv files, those rayspec
// keeps in references/baselines) that list every one of `violations` as a
// known one: what to pass with --baseline when a driver's known violations
// fail the check. A file that does not load is passed over.
std::vector<std::string> baselinesListing(const std::string& folder,
                                          const std::vector<std::string>& violations);

}  // namespace rayspec
