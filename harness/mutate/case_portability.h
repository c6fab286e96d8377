// Whether a case is portable: every device the specification allows passes
// it (`rayspec check`, `rayspec run --check-case`; issue 61). The model's
// exact tier runs the case; then each legal device `rayspec mutate` knows
// (mutate/legal_devices.h: each legal answer of an ambiguous ray, a
// conservative AABB test, other candidate orders, each candidate decided
// last, any-hit run twice, values at the edge of their tolerance, ...) is
// judged as a device would be. A legal device the judge fails is the case's
// fault, not the judge's: each is diagnosed (mutate/not_portable_cause.h)
// as the declaration to change. Needs the model: a run-only build checks
// nothing.
#pragma once

#include <string>
#include <vector>

#include "case/case.h"
#include "compare/verdict.h"
#include "mutate/not_portable_cause.h"
#include "results/results.h"

namespace rayspec {

struct CasePortability {
  bool checked = false;
  std::string not_checked;  // why not: no model here, the model did not run it
  // The model's own answers as a device fail the case (a CaseError the
  // model diagnosed: undefined behaviour, order dependence, ...; or a Fail,
  // where the judge holds the model to what the model does not do): its
  // headline, and that verdict's status.
  std::string own_answers;
  Status own_status = Status::Pass;
  size_t devices = 0;  // legal devices made
  size_t applied = 0;  // those that differ from the model's own answers here
  // One per declaration to change, the first device that shows it and the
  // others in `also`.
  std::vector<NotPortable> problems;
  double seconds = 0;  // wall time of the check
  bool portable() const { return checked && own_answers.empty() && problems.empty(); }
};

// The model's exact tier and every legal device on `c`; `threads` for the
// model (0: every core). *model (when given): the model's run of `c`.
CasePortability checkPortability(const Case& c, unsigned threads, Results* model = nullptr);

// The CaseError message of a case that is not portable: the model's own
// answers failing it other than by a CaseError (the run gives that one
// itself, by its own rule), or each problem's notPortableMessage, one a line
// (the first unindented); "" when portable or not checked.
std::string notPortableText(const CasePortability& p);

}  // namespace rayspec
