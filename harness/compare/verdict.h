// The outcome of comparing a device's results with the model's: a status with
// a stable name, and findings that name the rule broken and the first rays.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "base/enum_names.h"
#include "results/results.h"

namespace rayspec {

// Stable names: baselines and results.csv refer to them. CaseError: the case
// itself is at fault (a malformed file, or undefined behaviour the model
// diagnosed in it, R-UB); the device is not blamed for it.
// Rows: X(Status, "name", "deqp-runner's name").
#define RAYSPEC_STATUSES(X)                   \
  X(Pass, "Pass", "Pass")                     \
  X(Fail, "Fail", "Fail")                     \
  X(QualityWarning, "QualityWarning", "Warn") \
  X(NotSupported, "NotSupported", "Skip")     \
  X(Crash, "Crash", "Crash")                  \
  X(Timeout, "Timeout", "Timeout")            \
  X(CaseError, "CaseError", "Fail") /* deqp-runner has no name for it */
enum class Status { RAYSPEC_STATUSES(RAYSPEC_ENUMERATOR) };
RAYSPEC_ENUM_NAMES(Status, RAYSPEC_STATUSES);
inline constexpr auto kAllStatuses = enumValues<Status>();
inline const char* statusName(Status s) {
  return nameOf(s);
}
bool parseStatus(const std::string& name, Status* out);
// The worse of two statuses (Crash > Timeout > Fail > CaseError > QualityWarning > NotSupported >
// Pass). A run fails on any of Crash, Timeout, Fail and CaseError.
Status worse(Status a, Status b);
bool isFailing(Status s);

struct Finding {
  Status status = Status::Fail;
  std::string rule;            // rule label (references/spec-rules.yaml), e.g. "R-MISS-XOR-CHIT"
  std::string message;         // what differed
  std::vector<uint32_t> rays;  // first rays that broke it (launch index)
  uint32_t ray_count = 0;      // how many rays broke it in all
  // The rules the case claims that the finding is evidence against, `rule`
  // among them where claimed (compare/finding_rules.h): a claim's proof.
  std::vector<std::string> evidence;
};

// Whether the finding names `rule`: in its label ("R-A/R-B") or among the
// claimed rules it is evidence against.
bool findingNames(const Finding& f, const std::string& rule);
// Whether its label ("R-A/R-B") names `rule`.
bool labelNames(const Finding& f, const std::string& rule);
// One line of the finding: "Fail: R-IGNORE: ... (2 rays; first: 3 17)".
std::string findingLine(const Finding& f);

// The rays of one reason whose behaviour the model found undefined (R-UB):
// never judged, reported apart from the findings.
struct UndefinedRays {
  UndefinedReason reason = UndefinedReason::RayParameters;
  uint32_t ray_count = 0;
  std::vector<uint32_t> rays;  // first rays (launch index)
  std::string what;            // the first ray's: names the case field
};

struct Verdict {
  Status status = Status::Pass;
  std::vector<Finding> findings;         // Pass findings are informational notes
  std::vector<UndefinedRays> undefined;  // by reason, in reason order
  void add(Finding f);
  // One line: "Fail: R-IGNORE: ... (rays 3, 17, ...)" of the worst finding.
  std::string headline() const;
};

}  // namespace rayspec
