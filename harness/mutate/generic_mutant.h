// Generic wrong devices: changes a broken driver plausibly makes to what a
// trace produced, written without knowing the case's rules (unlike the
// planted faults of fault/, each chosen for one rule). `rayspec mutate`
// applies each to a saved device run and judges the result: a conformance
// suite is worth the wrong devices it catches.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "case/case.h"
#include "plan/plan.h"
#include "results/results.h"

namespace rayspec {

// What a mutant changed in one case's device results.
struct Mutation {
  bool applied = false;        // false: nothing of the kind to change (the reason in `what`)
  std::string what;            // e.g. "primitive_id + 1 on 64 rays"
  std::vector<uint32_t> rays;  // rays whose record changed (empty: counters or images only)
  std::string counter;         // the counter moved, for counter mutants
  int delta = 0;               // and by how much
  std::string field;           // the record field changed, for field mutants
};

struct MutantInput {
  const Case& c;
  const Plan& plan;
  const Results& model;
};

// One mutant of one case: `kind` groups mutants in the kill matrix
// ("field", "counter+1", ...); `name` is the instance ("field:primitive_id").
struct GenericMutant {
  std::string kind;
  std::string name;
  Mutation (*apply)(const MutantInput& in, const std::string& target, Results& device);
  std::string target;  // the field or counter it acts on, "" when none
};

// Every generic mutant that applies to this device run: the null device,
// each recorded field perturbed, each counter moved by +1 and -1, two rays'
// records swapped, miss and closest-hit both run, any-hit skipped or run once
// more, hit kind flipped, images zeroed.
std::vector<GenericMutant> genericMutants(const Case& c, const Results& device);

// The kinds, in kill-matrix order.
const std::vector<std::string>& mutantKinds();

}  // namespace rayspec
