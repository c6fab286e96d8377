// A worker of the model (model_machine.h): its parts, and the loop over its
// launch rays.
#include "model/model_machine.h"

namespace rayspec {

Machine::Machine(const ModelShared& shared, uint32_t* records)
    : sh_(shared),
      sbt_(*shared.c),
      state_(shared, sbt_, records),
      builtins_(shared, state_),
      interp_(shared, state_, sbt_, builtins_, tracer_, hits_),
      hits_(shared, state_, interp_),
      tracer_(shared, state_, sbt_, interp_, hits_),
      alike_(shared.alike_rays) {}

void Machine::runRays(uint32_t begin, uint32_t end) {
  if (sh_.raygen_traces_launch_ray && sh_.direct) {
    tracer_.runLaunchRaysDirect(begin, end);
    return;
  }
  const uint32_t width = sh_.c->rays.width;
  state_.x = begin % width;
  state_.y = begin / width;
  const Rays& rays = sh_.c->rays;
  const size_t launch_rays = rays.launchRays();
  for (uint32_t i = begin; i < end; ++i) {
    if (!rays.same && i + 8 < end) __builtin_prefetch(&rays.rays[i + 8]);  // rays stream in
    const Ray& ray = rays.launchRay(i);
    if (!alike_.repeat(state_, ray, i)) {
      alike_.starting(state_, ray, i + 1 < launch_rays ? &rays.launchRay(i + 1) : nullptr);
      runWithReplays(i);
      alike_.traced(state_, i);
    }
    if (++state_.x == width) {
      state_.x = 0;
      ++state_.y;
    }
  }
}

void Machine::runWithReplays(uint32_t i) {
  if (!sh_.replays) {
    runRay(i);
    state_.keepRayFloors();
    return;
  }
  counters_before_ = state_.counters;
  const size_t ambiguous_before = state_.ambiguous.size();
  script_.reset();  // the model's own run, the first replay
  state_.replay = &script_;
  runRay(i);
  state_.replay = nullptr;
  state_.keepRayFloors();  // the model's own run's, before the replays
  if (state_.ambiguous.size() > ambiguous_before && !state_.ray_undefined)
    replayLegalAnswers(i, ambiguous_before, script_);
}

void Machine::runRay(uint32_t i) {
  state_.startRay(i);
  state_.bumpRuns(kRunsRaygen);
  if (sh_.raygen_traces_launch_ray) {
    // Raygen is one `trace: {}` of this launch's ray: no stage environment needed.
    tracer_.trace(launchRay(sh_.c->rays.launchRay(i)), 1, &sh_.programs->raygen[0]);
  } else {
    interp_.runRaygen();
  }
}

}  // namespace rayspec
