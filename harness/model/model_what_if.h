// The exact tier's what-if runs (model_exact_tier.cpp): the hit a decision
// commits, an intersection program's decision that rounding may flip, and
// how one what-if run decides.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "model/model_program.h"

namespace rayspec {

// Exact tier, R-PREC: a decision of an intersection program that float
// rounding may flip on a device (reason "shader-arith"): the n-th (ordinal)
// sphere_hit (kind 0) or report interval test (kind 1) of candidate `cand`'s
// intersection program, and the value it took (or is forced to take).
struct ShaderDecision {
  size_t cand = 0;
  uint8_t kind = 0;
  uint32_t ordinal = 0;
  bool value = false;
};

// The hit a traversal committed.
struct Committed {
  bool valid = false;
  double t = 0;
  uint32_t instance = 0, geometry = 0, primitive = 0, kind = 0;
  float b1 = 0, b2 = 0;
  // Exact tier: bound on a device's t beyond the model's (a sphere root's
  // rounding, a triangle's frame error).
  double t_err = 0;
  std::array<uint32_t, kMaxAttributeWords> words{};  // a report's attribute words
  SizedSlots sized;                                  // a report's sized attribute members
  // Exact tier: a digest of what the decision left behind (this hit, the
  // payload, the launch ray's record and counters, a query's frame): two
  // what-if runs with the same digest go on alike (ModelTracer::effectOf).
  uint64_t effect = 0;
};

// R-TIE: what a what-if run of another order (R-ORDER-UNSPEC) does with a
// candidate confirmable at the committed t (within the error bound), which
// the specification lets a device set as the closest hit or drop ("If t =
// tmax", Ray Closest Hit Determination), its any-hit run or not (a triangle
// found before the commit lowered tmax, there being no ordering guarantee
// between candidates). Model: the model's own rule (a report replaces, a
// triangle with the smaller key replaces); Keep: dropped before its any-hit;
// Replace: its any-hit runs and it replaces; ConfirmDrop: its any-hit runs
// and it is dropped (triangles and intersection-program reports alike).
enum class TieRule : uint8_t { Model, Keep, Replace, ConfirmDrop };

// How one what-if run of the exact tier decides (ModelTracer::sandbox):
// candidates forced to be a hit (1) or not (0), -1 the model's own decision;
// the candidate that wins every tie (prefer) or is processed first (first),
// -1 none; intersection programs' decisions flipped; the order candidates
// are processed in (a permutation of their indices; empty: the model's own,
// R-ORDER-UNSPEC); what a candidate at the committed t does (R-TIE, TieRule).
// `actual`: the trace's own run, no what-if.
struct WhatIf {
  bool actual = false;
  std::vector<int8_t> force;  // empty: none forced
  long prefer = -1, first = -1;
  std::vector<ShaderDecision> shaders;  // each with the value it is forced to
  std::vector<uint32_t> order;
  TieRule tie = TieRule::Model;
};
struct WhatIfAnswer {
  Committed best;
  WhatIf how;
  // The run's intersection-program reports (candidate, t; NAN: it ran),
  // where collected (ModelTracer::whatIf): which boxes tie with `best`.
  std::vector<std::pair<size_t, double>> reports;
};

}  // namespace rayspec
