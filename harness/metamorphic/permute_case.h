// The permutation check of R-ORDER-UNSPEC: the order of the primitives within
// each geometry and the order of the instances are not the order in which a
// device meets them, so permuting them must not move a verdict.
// permuteCase() permutes a parsed case deterministically from a seed; the
// permuted case is an ordinary case, run on a device and on the model alike
// (`rayspec run --permute SEED`), and the mapping leads its ids back
// (metamorphic/compare_permuted.h).
//
// What moves: triangles (indexed: the index triples, and the vertex buffer
// with the indices remapped; otherwise the vertex triples, each triangle's
// own vertex order kept), AABBs, and instances (with everything they carry:
// transform, mask, custom index, SBT offset, flags). Ids that a stage
// program observes stay in their class (metamorphic/id_observations.h): an
// `odd: primitive_id` keeps every primitive's parity, `eq: [instance_id, 2]`
// keeps instance 2 where it is, and an id used in arithmetic does not move.
// Geometries, the SBT and the rays keep their order.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "case/case.h"

namespace rayspec {

struct CasePermutation {
  Case permuted;
  uint64_t seed = 0;
  std::vector<uint32_t> instance_of;  // permuted instance index -> original
  // [blas][geometry][permuted primitive] -> original primitive
  std::vector<std::vector<std::vector<uint32_t>>> primitive_of;
  bool vertices_moved = false;  // an indexed geometry's vertex buffer reordered
  bool primitivesMoved() const;
  bool instancesMoved() const;
  // False: the permuted case is the case as written (each geometry of one
  // primitive or its ids kept where a program observes them, one instance,
  // or the seed's shuffle the identity), so a run of it repeats the plain run.
  bool movedAnything() const { return primitivesMoved() || instancesMoved() || vertices_moved; }
};

CasePermutation permuteCase(const Case& c, uint64_t seed);

}  // namespace rayspec
