// The planted faults the kill matrix judges beside the generic mutants: the
// ray query faults of fault/ (query-*, each a device breaking one R-RQ
// rule), planted in the model's own answers as a device (perfectDevice) and
// judged against the model. A survivor may survive legally only where every
// ray it changed has undefined behaviour, or where all it shows is what a
// legal device shows too (mutate/legal_output.h: each changed record one of
// the ray's legal answers replayed or another order's): an ambiguous ray is
// no excuse (the device's record is held to its legal answers as a whole,
// issue 55), so a fault that survives on a case whose rays are all
// ambiguous with a record none of them gives is a hole.
#pragma once

#include <vector>

#include "fault/planted_fault.h"
#include "mutate/mutate_case.h"

namespace rayspec {

// The planted fault `f` in `base` (a device's results that pass), judged
// against `model`: killed when the comparison fails. Kind "planted", name
// "planted:<fault>"; `explain`: a survivor gets its legal reason (or none:
// a hole), which costs model runs.
MutantOutcome judgePlantedFault(const Case& c, const Plan& plan, const Results& model,
                                const Results& base, const FaultInfo& f, bool explain);

// Kind "planted-query", name "planted:<fault>"; one per query fault.
std::vector<MutantOutcome> judgePlantedFaults(const Case& c, const Plan& plan,
                                              const Results& model);

}  // namespace rayspec
