// The kill matrix of a mutate run: for each mutant kind and case family, how
// many (case, mutant) pairs applied and how many the comparison failed; the
// survivors, each with the reason it may legally survive or none (a hole).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "mutate/mutate_case.h"

namespace rayspec {

struct KillCell {
  size_t applied = 0, killed = 0, legal = 0;  // legal: survivors with a reason
};

struct Survivor {
  std::string case_name, mutant, what, reason;  // reason "": unexplained
};

// A legal device that failed (legal_devices.h): the judge's false alarm.
struct FalseAlarm {
  std::string case_name, device, rule, headline;
  int64_t ray = -1;
};

struct KillMatrix {
  std::vector<std::string> families;                             // sorted
  std::map<std::string, std::map<std::string, KillCell>> cells;  // [kind][family]
  std::map<std::string, KillCell> by_kind;
  size_t cases = 0, judged = 0;
  std::vector<std::pair<std::string, std::string>> not_judged;  // case, why
  std::vector<Survivor> survivors;
  // Legal devices: variants judged, the cases they were judged on, and each
  // that failed.
  size_t legal_variants = 0, legal_cases = 0;
  std::vector<FalseAlarm> false_alarms;
  // Wall seconds summed over the cases: the legal devices, the generic mutants.
  double legal_seconds = 0, mutant_seconds = 0;
  size_t unexplained() const;
  size_t nullKilled() const {
    return by_kind.count("null-device") ? by_kind.at("null-device").killed : 0;
  }
  // Judged cases where the null device changes something: not those whose
  // device answer is all zero already (a launch with no rays, R-LAUNCH-3D).
  size_t nullApplied() const {
    return by_kind.count("null-device") ? by_kind.at("null-device").applied : 0;
  }
};

KillMatrix buildKillMatrix(const std::vector<CaseMutation>& cases);

// The matrix as text: a table (kinds down, families across: killed/applied),
// the score, and every survivor with its reason.
std::string killMatrixText(const KillMatrix& m);
// The same as JSON (mutate.json).
std::string killMatrixJson(const KillMatrix& m, const std::string& run_dir,
                           const std::string& device);

}  // namespace rayspec
