// The permutation check on the model's own results (R-ORDER-UNSPEC): a case
// and its permutation (metamorphic/permute_case.h), both run on the model,
// must agree once the permuted ids are led back:
//   - the same rays are undefined (R-UB);
//   - a ray clear in the original is clear in the permutation with the same
//     record (ids led back, floats within the tolerances of
//     results/tolerances.h, everything else exact);
//   - a ray ambiguous in the original answers, in the permutation, with one
//     of its legal answers;
//   - with no ambiguous and no undefined ray, the same counters.
// A record without instance_id or geometry_index leads a primitive_id back
// through every geometry it could belong to.
#pragma once

#include <string>
#include <vector>

#include "metamorphic/permute_case.h"
#include "results/results.h"

namespace rayspec {

// The differences found, one line each (at most `limit`); empty: none.
std::vector<std::string> comparePermuted(const CasePermutation& p, const Results& original,
                                         const Results& permuted, size_t limit = 20);

}  // namespace rayspec
