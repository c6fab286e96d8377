// How each counter is compared, by what the specification guarantees about
// the stage that counts it:
//   exact          counted only in raygen, miss, closest-hit or callables:
//                  one per trace / call (R-MISS-XOR-CHIT, R-CALLABLE);
//   at_least       (declared in the case) e.g. any-hit of the closest hit;
//   at_most        (declared in the case) e.g. any-hit per primitive under
//                  NO_DUPLICATE_ANY_HIT_INVOCATION;
//   informational  counted in any-hit or intersection: depends on traversal
//                  order and duplicate invocations (R-ORDER-UNSPEC, R-AHIT-DUP,
//                  R-ISECT-MULTI), reported, never failed.
#pragma once

#include <map>
#include <string>

#include "case/case.h"

namespace rayspec {

enum class CounterMode { Exact, AtLeast, AtMost, Informational };
const char* counterModeName(CounterMode m);

std::map<std::string, CounterMode> counterModes(const Case& c);

}  // namespace rayspec
