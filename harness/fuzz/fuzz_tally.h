// What a fuzz run found, case by case: each outcome sorted into refused by
// the checks (the case is at fault: undefined behaviour, order dependence,
// not portable, a file the parser refuses), a rayspec defect (a generated
// shader that does not compile, the model crashed or timed out, any other
// CaseError), a finding (every other non-Pass but NotSupported), or none;
// findings grouped by signature. fuzz.txt is written from it.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "fuzz/known_classes.h"
#include "report/case_outcome.h"

namespace rayspec {

enum class FuzzClass { Pass, NotSupported, Refused, Finding, RayspecDefect };

struct FuzzSignature {
  std::string status, rule, kind;  // the worst finding's status, rule, and kind (digits as #)
  std::string folder;              // OUT/findings/<folder>: the three, as a file name
};

// The class of an outcome, and the signature of its worst finding.
FuzzClass classify(const CaseOutcome& o);
FuzzSignature signatureOf(const CaseOutcome& o);

struct FuzzTally {
  size_t generated = 0, run = 0;
  std::map<std::string, size_t> statuses;  // by status name
  size_t refused = 0;
  size_t unjudged = 0;  // --saved-cases: seeds whose saved case is missing or not the one run
  std::map<std::string, size_t> refusals;  // by rule of the refusing finding
  struct Group {
    FuzzSignature signature;
    bool rayspec_defect = false;
    std::string known;  // the known class's reason its cases hold ("" new)
    std::vector<uint64_t> seeds;
    std::string reduced;  // how its reduction ended ("" not tried)
  };
  std::map<std::string, Group> findings;  // by folder ("known_<feature>_" first for a known class)
  double seconds = 0;
  uint64_t first_seed = 0;
  std::string variant;  // --through, --plant-fault, as the run said

  // Counts the outcome of the case of `seed` (`known`: the known class its
  // case holds, nullptr none); the group it joined when it opens one (its
  // case and report are to be kept), else nullptr.
  const Group* add(uint64_t seed, const CaseOutcome& o, const KnownClass* known);
  // Cases of findings, of known classes or new ones.
  size_t findingCases(bool known) const;
  // fuzz.txt.
  std::string text() const;
};

}  // namespace rayspec
