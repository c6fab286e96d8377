// The CPU reference model: runs a case on Embree with the Vulkan meaning of
// every rule (references/spec-rules.yaml) and produces Results in the same schema
// as the device (results/results.h, results/record_layout.h).
//
// Candidate order (R-ORDER-UNSPEC): wherever a stage program can observe the
// order (any-hit, intersection programs, culls, the exact tier), the model
// first lets Embree enumerate every candidate of the trace, then processes
// them in ascending distance (triangles: their t; AABBs: where the ray enters
// the box, clamped to tmin), ties broken by (instance, geometry, primitive).
// Only a trace without any-hit, intersection, culls or special triangles in
// the fast/robust tiers uses rtcIntersect1 directly (Embree's closest hit).
//
// Undefined behaviour (R-UB) is diagnosed, never judged: Results.undefined
// lists each launch ray whose behaviour the specification leaves undefined,
// with the first reason and the case field at fault; the model goes on for
// that ray in the defined way model/launch_state_undefined.cpp documents,
// and the other rays are unaffected.
#pragma once

#include <optional>
#include <string>

#include "base/enum_names.h"
#include "case/case.h"
#include "model/model_faults.h"
#include "plan/plan.h"
#include "results/results.h"

namespace rayspec {

#define RAYSPEC_MODEL_TIERS(X) X(Fast, "fast") X(Robust, "robust") X(Exact, "exact")
enum class ModelTier { RAYSPEC_MODEL_TIERS(RAYSPEC_ENUMERATOR) };
RAYSPEC_ENUM_NAMES(ModelTier, RAYSPEC_MODEL_TIERS);
// "fast", "robust", "exact"; nullopt for another name.
std::optional<ModelTier> parseModelTier(const std::string& name);
const char* modelTierName(ModelTier t);

// R-AHIT-DUP: without NO_DUPLICATE_ANY_HIT_INVOCATION a device may run
// any-hit more than once for the same primitive. The model runs it once
// (None). First runs the first any-hit of each launch ray twice in a row, All
// every one; a geometry with the flag always runs it once. Legal behaviour
// both: the exact tier runs them to find what repetition can change
// (any_hit_repeat.cpp), and a planted fault stands for such a device.
enum class AnyHitRepeat { None, First, All };

struct ModelOptions {
  ModelTier tier = ModelTier::Exact;
  unsigned threads = 0;  // 0 = all cores
  AnyHitRepeat any_hit_repeat = AnyHitRepeat::None;
  ModelFaults faults;  // test only: the planted faults' hook (model/model_faults.h)
  // Trace every launch ray, also one alike the ray traced before it, whose
  // outcome the model otherwise copies (model/alike_rays.h): the tests and
  // bench/alike_rays.cpp compare the two.
  bool trace_each_ray = false;
};

Results runOnModel(const Case& c, const Plan& plan, const ModelOptions& opt);

// False in a run-only build (RAYSPEC_WITH_MODEL=OFF: model/model_absent.cpp),
// whose runOnModel only answers NotSupported.
bool modelInThisBuild();

}  // namespace rayspec
