// R-AHIT-DUP: without NO_DUPLICATE_ANY_HIT_INVOCATION a device may run any-hit
// more than once for the same primitive, and an any-hit that writes the
// payload or a record may then leave other values (`payload.value += 10`
// twice). The model runs any-hit once; the exact tier runs the case twice
// more as devices that repeat (the first any-hit of each launch ray, and
// every one; AnyHitRepeat in model_engine.h) and notes, per ray, the compared
// fields that came out otherwise, and the counters that moved
// (Results::repeat_dependent, repeat_counters). What repetition can change is
// not compared exactly (compare/any_hit_repeat_verdict.cpp).
#pragma once

#include "case/case.h"
#include "model/model_engine.h"
#include "plan/plan.h"
#include "results/results.h"

namespace rayspec {

// Whether a repeat could change anything: some geometry lacks the flag and
// some any-hit program writes the payload or a record.
bool anyHitRepeatMayMatter(const Case& c);

// Fills once.repeat_dependent and once.repeat_counters from runs of the case
// with each AnyHitRepeat (`opt` otherwise); `once` is the model's own run.
void findAnyHitRepeatDependence(const Case& c, const Plan& plan, const ModelOptions& opt,
                                Results& once);

}  // namespace rayspec
