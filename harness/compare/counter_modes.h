// How each counter is compared, by what the specification guarantees about
// the stage that counts it:
//   exact          counted only in raygen, miss, closest-hit or callables:
//                  one per trace / call (R-MISS-XOR-CHIT, R-CALLABLE);
//   at_least       declared in the case (`counters: [{anyhit: at_least}]`):
//                  the device ran it at least as often as the model, which
//                  runs the minimum (candidates in t order, none beyond the
//                  committed hit): e.g. any-hit and intersection counts
//                  without terminate (R-AHIT-CLOSEST, R-ISECT-CLOSEST);
//   at_most        declared: at most as often, e.g. any-hit under
//                  NO_DUPLICATE_ANY_HIT_INVOCATION with every candidate ignored;
//   informational  counted in any-hit or intersection, or in a ray_query's
//                  candidate blocks: depends on traversal order and duplicate
//                  invocations (R-ORDER-UNSPEC, R-AHIT-DUP, R-ISECT-MULTI,
//                  R-RQ-CANDIDATES), reported, never failed.
//
// Modes are derived from the case (which stage counts), never declared in it:
// every counter a raygen, miss, closest-hit or callable counts is exact, every
// counter an any-hit or intersection counts is informational. The bounds the
// specification does give for any-hit are checked per ray instead, from the
// automatic any_hit_runs field (compare_any_hit.cpp): under
// NO_DUPLICATE_ANY_HIT_INVOCATION (every geometry triangles with the flag), a
// ray on which the model committed no hit ran any-hit once per crossed
// primitive, and the device may run it at most that often (R-AHIT-DUP).
#pragma once

#include <map>
#include <set>
#include <string>

#include "base/enum_names.h"
#include "case/case.h"

namespace rayspec {

#define RAYSPEC_COUNTER_MODES(X) \
  X(Exact, "exact") X(AtLeast, "at_least") X(AtMost, "at_most") X(Informational, "informational")
enum class CounterMode { RAYSPEC_COUNTER_MODES(RAYSPEC_ENUMERATOR) };
RAYSPEC_ENUM_NAMES(CounterMode, RAYSPEC_COUNTER_MODES);
const char* counterModeName(CounterMode m);

std::map<std::string, CounterMode> counterModes(const Case& c);

// The counters a ray with undefined behaviour (R-UB) may have moved: every
// counter a stage other than raygen counts, and a raygen count that comes
// after a trace, a call or a division (where the undefined behaviour can
// happen). Only a raygen count before all of those is safe. With undefined
// rays in a launch these are informational.
std::set<std::string> countersUndefinedRaysMayMove(const Case& c);

}  // namespace rayspec
