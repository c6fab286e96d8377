// The hit object's statements in the model (GL_NV_shader_invocation_reorder;
// a trace into it is execTrace's): execute runs what its trace would have
// run, record_miss and record_empty set it, reorder changes nothing a
// shader observes (R-REORDER: the hint is evaluated, as the GLSL does).
#include "case/bit_widths.h"
#include "model/model_tracer.h"
#include "model/stage_interpreter.h"

namespace rayspec {

// record_hit's values (assigns: instance, primitive, geometry, hit kind,
// attributes, then the SBT record index where given) and the ray.
void StageInterpreter::recordHit(const CStmt& s, StageEnv& env, uint32_t depth) {
  HitView given;
  given.instance = eval(s.assigns[0].value, env).u;
  given.primitive = eval(s.assigns[1].value, env).u;
  given.geometry = eval(s.assigns[2].value, env).u;
  given.hit_kind = eval(s.assigns[3].value, env).u;
  const Val attributes = eval(s.assigns[4].value, env);
  given.b1 = attributes.f[0];
  given.b2 = attributes.f[1];
  std::optional<uint32_t> index;
  if (s.assigns.size() > 5) index = eval(s.assigns[5].value, env).u;
  tracer_.recordHit(tracedRay(s, env), given, index, depth, &s, *env.hit_object);
}

void StageInterpreter::execHitObject(const CStmt& s, StageEnv& env) {
  if (!env.hit_object) return;  // a stage without one (refused by the checker)
  HitObjectState& h = *env.hit_object;
  const uint32_t depth = env.stage == Stage::Raygen ? 1 : env.depth + 1;
  switch (s.kind) {
    case Stmt::Kind::ExecuteHitObject: {
      Payload p = startPayload(s, env);
      p.depth = depth;
      tracer_.executeHitObject(h, p);
      if (env.stage == Stage::Raygen && env.payload)
        *env.payload = p;
      else
        env.child = p;
      loseLocals(env);
      return;
    }
    case Stmt::Kind::RecordMiss: {  // hitObjectRecordMissNV takes no flags or mask
      h = HitObjectState{};
      h.kind = HitObjectState::Kind::Miss;
      h.ray = tracedRay(s, env);
      h.ray.flags = 0;
      h.depth = depth;
      h.sbt_index = h.ray.miss & kTraceMissIndexMask;
      tracer_.noteRecordData(h);
      return;
    }
    case Stmt::Kind::RecordHit:
      recordHit(s, env, depth);
      return;
    case Stmt::Kind::RecordEmpty:
      h = HitObjectState{};
      return;
    default:  // reorder
      for (const CAssign& a : s.assigns) eval(a.value, env);
      return;
  }
}

}  // namespace rayspec
