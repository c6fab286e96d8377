// A reduction step must keep the case portable: a variant that fails the same
// way is kept only when every legal device (mutate/legal_devices.h: each
// legal answer of an ambiguous ray, candidates in another order, intersection
// programs run for boxes beside the entered ones, values at the edge of the
// tolerance, ...) still passes it. A step that drops a box test from an
// intersection program's guard, say, makes a case that a correct device may
// fail (R-AABB-CONS: it may run the program for a box the ray does not
// enter): such a step is rejected. A legal device that already fails the
// original case (a judge's false alarm, not the step's doing) is not held
// against the variants. The check is `rayspec check`'s
// (mutate/case_portability.h checkPortability). Needs the model: in a
// run-only build nothing is checked.
#pragma once

#include <set>
#include <string>

#include "case/case.h"

namespace rayspec {

class PortabilityCheck {
 public:
  // The original case's own false alarms noted; `threads` for the model.
  PortabilityCheck(const Case& original, unsigned threads);
  // "" when every legal device passes the variant (or fails the original
  // too), else "not portable: legal device <name> fails: <finding>".
  std::string whyNotPortable(const Case& variant) const;

 private:
  std::set<std::string> falseAlarms(const Case& c) const;

  unsigned threads_;
  std::set<std::string> original_false_alarms_;
};

}  // namespace rayspec
