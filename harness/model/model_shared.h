// What every Machine of a run shares (model_engine.cpp sharedState): the
// case, its plan, the scene, the compiled programs, the paths the run may
// take, and the planted faults' seam.
#pragma once

#include "case/case.h"
#include "model/model_fault_seam.h"
#include "model/model_program.h"
#include "model/model_scene.h"
#include "plan/plan.h"

namespace rayspec {

struct ModelShared {
  const Case* c = nullptr;
  const Plan* plan = nullptr;
  const ModelScene* scene = nullptr;
  const CPipeline* programs = nullptr;  // compiled once per run
  bool direct = false;                  // rtcIntersect1's own closest hit (no filters)
  // Decided once per run from what the programs read: a direct hit needs its
  // facing only for hit_kind, its object-space ray only for object_ray_*.
  bool need_facing = true, need_object_ray = true;
  bool raygen_traces_launch_ray = false;  // raygen is exactly `trace: {}`
  bool payload_types = false;             // pipeline.payloads declares several locations
  ModelFaultSeam fault_seam;  // test only: the planted faults, read through this seam alone
  AnyHitRepeat any_hit_repeat = AnyHitRepeat::None;  // R-AHIT-DUP (model_engine.h)
  // Exact tier, the model's own answers: each ambiguous launch ray's legal
  // answers replayed (legal_replays.h).
  bool replays = false;
  // Some candidate may be undefined (a hit record beyond the region, a NaN
  // triangle): ModelTracer::checkCandidates looks at every candidate.
  bool check_candidates = true;
  // No program reads the launch id: a launch ray alike the one its Machine
  // traced last leaves what that one left (alike_rays.h).
  bool alike_rays = false;
};

}  // namespace rayspec
