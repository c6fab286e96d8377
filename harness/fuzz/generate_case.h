// `rayspec fuzz`'s cases: from a seed, a random case as case-file YAML (a
// file `rayspec run` runs again), the same text from the same seed on every
// machine (case/seeded_random.h: no std:: distributions). The scene (random
// instances with rotations, non-uniform scales and mirrors, masks, custom
// indices over 24 bits, SBT offsets and flags; several BLASes of triangles,
// indexed or not, in any vertex format, behind a geometry transform, or a
// mesh shape, or boxes, several geometries each, opaque or not, inactive
// and NaN primitives mixed in; build flags and input layouts; copies and
// updates in random order), the rays (a list mostly aimed at centres,
// edges and vertices of the primitives, grazing or from far away now and
// then, a grid, or the aim form; tmin, tmax, flags, cull masks, miss
// indices) and the stage programs (raygen, miss, closest-hit, any-hit that
// ignores or terminates on a condition, intersection reports, callables;
// records of built-ins and Uint expressions drawn from the vocabulary,
// fuzz/stage_vocabulary.h; counters; in some cases typed live state: locals,
// a struct and an array of the sized types across the traces, calls and
// reports) are all drawn from the seed. The case
// is judged by the rules of any case: a case the checks refuse (undefined
// behaviour, results that depend on what no device must keep) is refused,
// not a finding.
#pragma once

#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "fuzz/generator_features.h"

namespace rayspec {

struct GeneratedCase {
  uint64_t seed = 0;
  std::string name;  // "fuzz/seed-<seed>": the file is <cases>/fuzz/seed-<seed>.yaml
  std::string yaml;
  // What the case holds, by feature name ("rotation", "mirror", "aabbs",
  // "any-hit-ignore", ...): the generator's coverage.
  std::set<std::string> features;
};

// Every feature name a generated case may hold, in the order of the file.
const std::vector<std::string>& generatorFeatures();

// The case name of a seed.
std::string fuzzCaseName(uint64_t seed);

// The case of `seed` with the device features `allowed` leaves out never
// drawn (a case of its own: the default makes another).
GeneratedCase generateCase(uint64_t seed, const GeneratorFeatures& allowed = {});

}  // namespace rayspec
