// The device side of a case that expects its compiler to reject shaders
// (expect_rejected, R-STAGE-INTERFACE): no launch, each named shader's GLSL
// (which declares the interface its program uses, even where its stage
// cannot) compiled with glslang and SPIRV-Tools. A shader refused with
// "'<qualifier>' : not supported in this stage" for the interface the
// checker found is listed in Results::rejected; one accepted, or refused for
// another reason, is not (the comparison then fails it).
#pragma once

#include "case/case.h"
#include "plan/plan.h"
#include "results/results.h"

namespace rayspec {

void compileExpectedRejections(const Case& c, const Plan& plan, Results& r);

}  // namespace rayspec
