#include "glsl/generate_glsl.h"

#include "glsl/emit_stage.h"
#include "glsl/stage_prologue.h"

namespace rayspec {

// Stages the plan says cannot run are left out (glsl/stage_prologue.h
// anyHitRuns, intersectionRuns). Everything else present in the case is
// generated.
GeneratedPipeline generateGlsl(const Case& c, const Plan& plan) {
  const Pipeline& p = c.pipeline;
  GeneratedPipeline g;
  g.raygen = emitStage(c, plan, Stage::Raygen, Pipeline::shaderName(Stage::Raygen, 0), p.raygen);
  g.raygen_group = p.raygen_group;
  // Run as a compute shader, raygen is the whole program: no ray tracing
  // pipeline holds the other stages.
  if (p.from_compute) return g;
  for (size_t i = 0; i < p.other_raygens.size(); ++i)
    g.other_raygens.push_back(emitStage(
        c, plan, Stage::Raygen, Pipeline::shaderName(Stage::Raygen, i, true), p.other_raygens[i]));
  for (size_t i = 0; i < p.miss.size(); ++i)
    g.miss.push_back(emitStage(c, plan, Stage::Miss, Pipeline::shaderName(Stage::Miss, i),
                               p.miss[i], p.missPayload(i)));
  for (size_t i = 0; i < p.hit_groups.size(); ++i) {
    const HitGroup& h = p.hit_groups[i];
    GeneratedGroup group;
    const bool procedural = h.intersection.has_value();
    if (h.closest_hit)
      group.closest_hit =
          emitStage(c, plan, Stage::ClosestHit, Pipeline::shaderName(Stage::ClosestHit, i),
                    *h.closest_hit, h.payload, procedural);
    if (anyHitRuns(plan, h))
      group.any_hit = emitStage(c, plan, Stage::AnyHit, Pipeline::shaderName(Stage::AnyHit, i),
                                *h.any_hit, h.payload, procedural);
    if (intersectionRuns(plan, h))
      group.intersection =
          emitStage(c, plan, Stage::Intersection, Pipeline::shaderName(Stage::Intersection, i),
                    *h.intersection, 0, procedural);
    g.hit_groups.push_back(std::move(group));
  }
  for (size_t i = 0; i < p.callables.size(); ++i)
    g.callables.push_back(emitStage(c, plan, Stage::Callable,
                                    Pipeline::shaderName(Stage::Callable, i), p.callables[i],
                                    p.callableData(i)));
  return g;
}

std::vector<const GeneratedShader*> everyStage(const GeneratedPipeline& g) {
  std::vector<const GeneratedShader*> out{&g.raygen};
  for (const auto* list : {&g.other_raygens, &g.miss})
    for (const GeneratedShader& s : *list) out.push_back(&s);
  for (const GeneratedGroup& h : g.hit_groups)
    for (const auto* s : {&h.closest_hit, &h.any_hit, &h.intersection})
      if (*s) out.push_back(&**s);
  for (const GeneratedShader& s : g.callables) out.push_back(&s);
  return out;
}

}  // namespace rayspec
