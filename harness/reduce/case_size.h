// How big a case is, in the parts a reduction shrinks: the numbers the
// summary prints before and after.
#pragma once

#include <cstddef>
#include <string>

#include "case/case.h"

namespace rayspec {

struct CaseSize {
  size_t rays = 0, instances = 0, geometries = 0, primitives = 0, statements = 0;
};

CaseSize caseSize(const Case& c);

// "rays 64 -> 1, instances 6 -> 2, ..." (before -> after).
std::string sizeChange(const CaseSize& before, const CaseSize& after);

}  // namespace rayspec
