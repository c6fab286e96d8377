#include <algorithm>

#include "glsl/stage_context.h"
#include "program/builtins.h"
#include "program/hit_object.h"
#include "program/ops.h"
#include "program/payload_words.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

bool kept(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

void visitExpr(const Expr& e, StageUses& u) {
  if (e.kind == Expr::Kind::Builtin) {
    using namespace builtin_needs;
    const BuiltinNeeds needs = builtinNeeds(e.builtin);
    if (needs & BoxData) u.scene = true;
    if (needs & HitAttribute) u.hit_attribute = true;
    if (needs & CullMask) u.cull_mask = true;
    if (needs & InPayload) u.incoming_payload = true;
    if (isHitVertexPosition(e.builtin)) u.position_fetch = true;
    if (isQueryVertexPosition(e.builtin)) u.query_position_fetch = true;
    if (needs & ChildPayload) u.reads_child = true;
    if (needs & CalleeData) u.reads_callee = true;
    if (needs & HitObject) u.hit_object = true;
  } else if (e.kind == Expr::Kind::Op) {
    if (isSphereOp(e.op)) u.scene = u.sphere = true;
    if (e.op == Op::RecordUint || e.op == Op::RecordFloat) u.shader_record = true;
    if (isHitObjectRecordRead(e)) u.hit_object = u.hit_object_record = true;
    if (isLightOp(e.op)) u.light = u.shader_record = true;
    if (const auto words = wordArrayOf(e.op)) {
      u.incoming_payload = u.incoming_payload || *words == WordArray::Payload;
      u.reads_child = u.reads_child || *words == WordArray::Child;
      u.reads_callee = u.reads_callee || *words == WordArray::Callee;
    }
  } else if (e.kind == Expr::Kind::RecordMember) {
    u.record_members = true;
  }
  for (const Expr& a : e.args) visitExpr(a, u);
}

void visitExprs(const std::vector<Expr>& v, StageUses& u) {
  for (const Expr& e : v) visitExpr(e, u);
}

// A ray_query (its fields; in raygen a missing one reads the launch ray) or
// a generate (its t).
void visitQuery(const Stmt& s, Stage stage, StageUses& u) {
  if (s.kind == Stmt::Kind::Generate) {
    visitExpr(s.t, u);
    return;
  }
  u.ray_query = true;
  const TraceArgs& t = s.trace;
  for (const auto* v : {&t.origin, &t.direction, &t.tmin, &t.tmax, &t.flags, &t.cull_mask}) {
    visitExprs(*v, u);
    if (v->empty() && stage == Stage::Raygen) u.launch_ray = true;
  }
}

// A trace's fields (a record_miss's too): in raygen a missing one reads the
// launch ray.
void visitTraceArgs(const TraceArgs& t, Stage stage, StageUses& u) {
  for (const auto* v : {&t.origin, &t.direction, &t.tmin, &t.tmax, &t.flags, &t.cull_mask,
                        &t.sbt_offset, &t.sbt_stride, &t.miss}) {
    visitExprs(*v, u);
    if (v->empty() && stage == Stage::Raygen) u.launch_ray = true;
  }
}

// execute (its payload is a trace's), record_miss, record_empty, reorder.
void visitHitObjectStatement(const Stmt& s, Stage stage, StageUses& u) {
  if (!isHitObjectStatement(s)) return;
  u.hit_object = true;
  for (const auto& a : s.assigns) visitExpr(a.second, u);
  if (s.kind == Stmt::Kind::RecordMiss || s.kind == Stmt::Kind::RecordHit)
    visitTraceArgs(s.trace, stage, u);
  if (s.kind != Stmt::Kind::ExecuteHitObject) return;
  u.trace = true;
  u.trace_locations.insert(s.trace.location);
}

void visitProgram(const Program& p, Stage stage, const Plan& plan, StageUses& u) {
  for (const Stmt& s : p) {
    switch (s.kind) {
      case Stmt::Kind::Count:
        if (kept(plan.counters, s.counter)) u.counters = true;
        break;
      case Stmt::Kind::Record:
        for (const auto& [field, value] : s.assigns) {
          visitExpr(value, u);
          const int index = recordFieldIndex(field);
          if (plan.records && index >= 0 && kept(plan.record_fields, field))
            u.record_fields.insert(index);
        }
        break;
      case Stmt::Kind::SetPayload:
        u.incoming_payload = true;
        for (const auto& a : s.assigns) visitExpr(a.second, u);
        break;
      case Stmt::Kind::SetCall:
        for (const auto& a : s.assigns) visitExpr(a.second, u);
        break;
      case Stmt::Kind::Call:
        u.call = true;
        u.call_locations.insert(s.call_location);
        visitExpr(s.call_index, u);
        for (const auto& a : s.assigns) visitExpr(a.second, u);
        break;
      case Stmt::Kind::Light:
        u.light = u.shader_record = true;
        break;
      case Stmt::Kind::Report:
        u.hit_attribute = true;
        visitExpr(s.t, u);
        visitExpr(s.hit_kind, u);
        visitExprs(s.attribute, u);
        break;
      case Stmt::Kind::Trace: {
        u.trace = true;
        u.hit_object = u.hit_object || s.trace.hit_object;
        u.trace_locations.insert(s.trace.location);
        for (const auto& a : s.assigns) visitExpr(a.second, u);
        visitTraceArgs(s.trace, stage, u);
        break;
      }
      case Stmt::Kind::RayQuery:
      case Stmt::Kind::RestartQuery:
      case Stmt::Kind::Generate:
        visitQuery(s, stage, u);
        break;
      case Stmt::Kind::If:
      case Stmt::Kind::Switch:
        visitExpr(s.cond, u);
        break;
      case Stmt::Kind::Repeat:
        visitExpr(s.count, u);
        visitExpr(s.from, u);
        break;
      case Stmt::Kind::Store:
        if (wordArrayOfStore(s.local) == WordArray::Payload) u.incoming_payload = true;
        visitExpr(s.index, u);
        for (const auto& a : s.assigns) visitExpr(a.second, u);
        break;
      case Stmt::Kind::Let:
      case Stmt::Kind::Set:
      case Stmt::Kind::Invoke:
        for (const auto& a : s.assigns) visitExpr(a.second, u);
        break;
      default:  // the hit object's; ignore, terminate, array, break, continue, return, case
        visitHitObjectStatement(s, stage, u);
        break;
    }
    visitProgram(s.then_, stage, plan, u);
    visitProgram(s.else_, stage, plan, u);
  }
}

}  // namespace

StageUses findStageUses(const Program& program, Stage stage, const Plan& plan) {
  StageUses u;
  visitProgram(program, stage, plan, u);
  u.query_sphere = u.sphere && stage != Stage::Intersection;  // in aabb blocks (program/ops.h)
  if (stage == Stage::Raygen && plan.records) {
    // Raygen copies the image fields from the record into the images.
    for (const ImageOutput& img : plan.images)
      if (int index = recordFieldIndex(img.field); index >= 0) u.record_fields.insert(index);
  }
  return u;
}

}  // namespace rayspec
