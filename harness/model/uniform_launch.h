// A launch whose ids are all alike (rays.same, no per-ray records, and no
// program reads gl_LaunchIDEXT): every id runs the same stages with the same
// values, so the model traces one id and multiplies what it counted by the
// launch's ids (builtins/launch-largest: 2^26 and 2^30 ids, where the model's
// few microseconds an id would take minutes to an hour).
#pragma once

#include <cstdint>

#include "case/case.h"
#include "model/model_program.h"
#include "plan/plan.h"
#include "results/results.h"

namespace rayspec {

// Some program reads the launch id (launch_id_x, _y or _z): ids of one ray
// may run otherwise; launch_size_* is the launch's, the same for every id.
bool launchIdRead(const CPipeline& programs);

// Every id of c's launch runs alike (see above); launch_size_* may be read.
bool launchUniform(const Case& c, const Plan& plan, const CPipeline& programs);

// Whether one id's results may stand for every id: no ray of it ambiguous or
// undefined (those are kept per ray, and the judge reads them per ray).
bool oneIdStandsForAll(const Results& one_id);

// One id's counters (and their floors) made the launch's `ids` ids'.
void scaleToLaunch(Results& one_id, uint64_t ids);

}  // namespace rayspec
