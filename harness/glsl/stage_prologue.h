// What every stage does before its program, whether it is a stage of the
// pipeline (glsl/emit_stage.cpp, its main()) or inlined into raygen by
// --through ray-query (glsl/emit_ray_query.cpp, its function): which stages
// run at all, the record fields the prologue writes, and the prologue itself
// (the stage's run count; any-hit's slot).
#pragma once

#include <string>

#include "glsl/glsl_writer.h"
#include "glsl/stage_context.h"

namespace rayspec {

// The record field a stage's every run bumps ("raygen_runs", ...).
const char* stageRunsField(Stage s);

// Whether a hit group's any-hit or intersection is generated: the plan
// leaves out an any-hit when no candidate can be non-opaque (plan.any_hit),
// an intersection when no AABB is reached (plan.intersection).
bool anyHitRuns(const Plan& plan, const HitGroup& h);
bool intersectionRuns(const Plan& plan, const HitGroup& h);

// The record fields the prologue of a stage writes, added to `uses` (none
// where the plan keeps no records).
void addPrologueFields(const Plan& plan, Stage stage, StageUses& uses);
// Of those, the any-hit slot fields alone (any_hit_slots, any_hit_repeats).
void addAnyHitSlotFields(const Plan& plan, StageUses& uses);

// The GLSL of the hit an any-hit runs on: its instance, geometry and primitive.
struct PrologueHit {
  std::string instance, geometry, primitive;
};
// The prologue: the stage's run count bumped; in any-hit, the hit's slot
// marked (results/record_layout.h anyHitSlot).
void emitStagePrologue(const StageContext& ctx, const PrologueHit& hit, GlslWriter& out);

}  // namespace rayspec
