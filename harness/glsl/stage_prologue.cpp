#include "glsl/stage_prologue.h"

#include "glsl/emit_stmt.h"
#include "glsl/glsl_uint_text.h"
#include "results/record_layout.h"

namespace rayspec {

const char* stageRunsField(Stage s) {
  switch (s) {
    case Stage::Raygen:
      return "raygen_runs";
    case Stage::Miss:
      return "miss_runs";
    case Stage::ClosestHit:
      return "closest_hit_runs";
    case Stage::AnyHit:
      return "any_hit_runs";
    case Stage::Intersection:
      return "intersection_runs";
    case Stage::Callable:
      return "callable_runs";
  }
  return "raygen_runs";
}

bool anyHitRuns(const Plan& plan, const HitGroup& h) {
  return h.any_hit && plan.any_hit;
}

bool intersectionRuns(const Plan& plan, const HitGroup& h) {
  return h.intersection && plan.intersection;
}

void addAnyHitSlotFields(const Plan& plan, StageUses& uses) {
  if (!plan.records) return;
  for (const char* f : {"any_hit_slots", "any_hit_repeats"})
    uses.record_fields.insert(recordFieldIndex(f));
}

void addPrologueFields(const Plan& plan, Stage stage, StageUses& uses) {
  if (!plan.records) return;
  uses.record_fields.insert(recordFieldIndex(stageRunsField(stage)));
  if (stage == Stage::AnyHit) addAnyHitSlotFields(plan, uses);
}

void emitStagePrologue(const StageContext& ctx, const PrologueHit& hit, GlslWriter& out) {
  if (!ctx.plan.records) return;
  out.line("rs_bump_runs(" + fieldOffsetMacro(stageRunsField(ctx.stage)) + ");");
  if (ctx.stage == Stage::AnyHit)
    out.line("rs_mark_any_hit(" + fieldOffsetMacro("any_hit_slots") + ", " +
             fieldOffsetMacro("any_hit_repeats") + ", " +
             anyHitSlotGlsl(hit.instance, hit.geometry, hit.primitive) + ");");
}

}  // namespace rayspec
