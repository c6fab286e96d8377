// What "fails the same way" means for a reduction: the case's status, and a
// finding of the same rule and the same kind (its message with the numbers
// taken out: "per-ray field 'hit' differs ...", "miss: device #, model #").
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "report/case_outcome.h"

namespace rayspec {

struct FailureSignature {
  Status status = Status::Fail;   // the case's status
  Status finding = Status::Fail;  // the finding's own status
  std::string rule;               // its rule ("" for a crash or timeout)
  // --keep R-X: `rule` is that one rule, found among a finding's labels
  // ("R-FACE-DET/R-INST-XFORM" has R-FACE-DET) or the claims it is evidence
  // against (compare/verdict.h findingNames), whatever else they name.
  bool rule_among_labels = false;
  std::string kind;                // findingKind of its message ("" any)
  std::string message;             // as first seen, for the reports
  bool undefined_allowed = false;  // the original had rays of undefined behaviour too
};

// Whether a finding's rule label is the signature's rule (or, with
// rule_among_labels, the finding names it).
bool ruleMatches(const Finding& f, const FailureSignature& s);

// The message with every run of digits, and every list of them, replaced by '#'.
std::string findingKind(const std::string& message);

// The signature to keep in `o`: with keep == "" the worst finding of the
// case's status; with keep "crash" a Crash or Timeout; a rule label (R-...)
// that rule's finding (Fail or QualityWarning), any kind; else a finding
// whose message holds `keep`. nullopt: the case does not fail that way
// (a Pass, NotSupported, CaseError, or nothing matching keep).
std::optional<FailureSignature> failureToKeep(const CaseOutcome& o, const std::string& keep);

// Whether `o` fails the way `s` says.
bool failsTheSameWay(const CaseOutcome& o, const FailureSignature& s);

// The rays of o's findings that fail the way `s` says, ascending.
std::vector<uint32_t> failingRays(const CaseOutcome& o, const FailureSignature& s);

}  // namespace rayspec
