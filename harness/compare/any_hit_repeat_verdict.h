// R-AHIT-DUP: what a device that runs any-hit more than once for a primitive
// may change (the model's Results::repeat_dependent and repeat_counters,
// model/any_hit_repeat.h) is never compared exactly: the records, image
// pixels and counters it may change are left out (compare_records.cpp,
// compare_images.cpp, compare_counters.cpp). Like undefined behaviour, a case
// whose results depend on it is diagnosed, not judged, unless it says so:
//   - a case that does not claim R-AHIT-DUP is not portable: CaseError,
//     nothing compared (add no_duplicate_any_hit to its geometries, or claim
//     the rule);
//   - a case that claims it gets an informational Pass finding naming what is
//     left out, and is judged on the rest.
#pragma once

#include "case/case.h"
#include "compare/verdict.h"
#include "results/results.h"

namespace rayspec {

// Returns true when the comparison goes on.
bool judgeAnyHitRepeat(const Case& c, const Results& model, Verdict& v);

}  // namespace rayspec
