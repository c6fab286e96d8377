// What the stage programs of a case observe of an id built-in (primitive_id,
// instance_id), so that a permutation of ids can keep every observation: a
// program that records the id as itself observes nothing the harness cannot
// map back; `odd` / `even` of it observe its parity; a comparison with a uint
// literal observes which side of the literal it lies; anything else
// (arithmetic, a callable index, a report kind...) observes the id itself.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "case/case.h"
#include "program/builtins.h"

namespace rayspec {

struct IdObservations {
  bool exact = false;            // the id itself is observed: no id may move
  bool parity = false;           // odd / even
  std::vector<uint64_t> equals;  // eq / ne with these literals
  std::vector<uint64_t> below;   // lt / le / gt / ge: the side of these thresholds (id < T)
  // Two ids of one class may be exchanged without a program noticing.
  std::vector<uint64_t> classOf(uint64_t id) const;
};

// `id`: kBiPrimitive or kBiInstance (a ray query's candidate.* and
// committed.* getters of it count as it).
IdObservations observeId(const Pipeline& p, Builtin id);

}  // namespace rayspec
