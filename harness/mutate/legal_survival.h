// Why a generic mutant may legally survive a case: the specification allows
// what it changed (an any-hit count under no NO_DUPLICATE_ANY_HIT_INVOCATION,
// a counter that depends on traversal order, rays with undefined behaviour).
// Derived from the case and the model's results, never listed by hand: a
// survivor with no such reason is a hole in the comparison.
#pragma once

#include <string>

#include "mutate/generic_mutant.h"

namespace rayspec {

// "" when nothing allows it. `mutated`: the mutant's results.
std::string legalSurvival(const MutantInput& in, const GenericMutant& g, const Mutation& m,
                          const Results& mutated);

}  // namespace rayspec
