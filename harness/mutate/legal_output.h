// Whether what a planted fault's device answers is what some legal device
// answers too (mutate/planted_mutants.h): then its survival is no hole in
// the judge, for a judge must pass every legal device. Each changed ray's
// record must be, bit for bit, one of its legal answers replayed whole
// (Results' RayAmbiguity::replays) or the record a legal device deciding in
// another order gives it (reverse-order, permuted-order-1..3, and in a
// scene of a few candidates each one decided last: lastCandidateDevices,
// fault/planted_fault.h); and each
// counter it moved must be one that traversal order moves (informational),
// or, where every changed ray was a replay, moved as those replays move it.
// An ambiguous ray alone is no excuse: a record that is none of these (the
// custom index of neither tied instance) still makes a hole.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "case/case.h"
#include "plan/plan.h"
#include "results/results.h"

namespace rayspec {

// The reason (R-ORDER-UNSPEC ...) where `device`, which differs from `base`
// (the model's own answers as a device) on `rays`, gives only what legal
// devices give; "" otherwise.
std::string legalOutput(const Case& c, const Plan& plan, const Results& model, const Results& base,
                        const Results& device, const std::vector<uint32_t>& rays);

}  // namespace rayspec
