#include "glsl/emit_trace.h"

#include "glsl/emit_expr.h"
#include "glsl/emit_payloads.h"
#include "glsl/emit_ray_query.h"
#include "glsl/glsl_literal.h"
#include "glsl/inlined_levels.h"
#include "glsl/tlas_function.h"
#include "program/payload_words.h"

namespace rayspec {
namespace {

// One trace argument: the case's expression, else the default.
struct Arg {
  const char* type;
  const char* local;
  const std::vector<Expr>* given;
  std::string fallback;  // GLSL; empty = required
};

void startSized(const Stmt& s, const StageContext& ctx, GlslWriter& out);

// The payload a trace starts with, in the variable of its location: every
// value read before any is written; depth 1 from raygen, else this stage's + 1.
void startPayload(const Stmt& s, const StageContext& ctx, GlslWriter& out) {
  const uint32_t location = s.trace.location;
  const std::vector<uint32_t>& types = ctx.c.pipeline.payload_words;
  const uint32_t words = location < types.size() ? types[location] : 0;
  std::string color = "vec4(0.0)", value = "0u";
  std::vector<std::string> word(words, "0u");
  for (const auto& [field, expr] : s.assigns) {
    if (field == "color") color = emitExpr(expr, ctx);
    if (field == "value") value = emitExpr(expr, ctx);
    if (auto i = payloadWordField(field); i && *i < words) word[*i] = emitExpr(expr, ctx);
  }
  out.line("vec4 rs_start_color = " + color + ";");
  out.line("uint rs_start_value = " + value + ";");
  for (uint32_t i = 0; i < words; ++i)
    out.line("uint rs_start_word" + std::to_string(i) + " = " + word[i] + ";");
  startSized(s, ctx, out);
  const std::string p = outgoingPayload(location);
  out.line(p + ".color = rs_start_color;");
  out.line(p + ".value = rs_start_value;");
  out.line(p + ".depth = " +
           (ctx.stage == Stage::Raygen ? std::string("1u") : "payload.depth + 1u") + ";");
  for (uint32_t i = 0; i < words; ++i)
    out.line(p + ".words[" + std::to_string(i) + "] = rs_start_word" + std::to_string(i) + ";");
  for (ValueType t : ctx.c.pipeline.payloadSized(location))
    out.line(p + "." + sizedMemberGlsl(t) + " = rs_start_" + valueTypeSpelling(t) + ";");
}

// A trace's starting sized members (zero where not given), into locals
// rs_start_<type> before the payload is written.
void startSized(const Stmt& s, const StageContext& ctx, GlslWriter& out) {
  for (ValueType t : ctx.c.pipeline.payloadSized(s.trace.location)) {
    std::string value = sizedZero(t);
    for (const auto& [field, expr] : s.assigns)
      if (sizedMemberField(field) == t) value = emitExpr(expr, ctx);
    out.line(std::string(valueTypeGlsl(t)) + " rs_start_" + valueTypeSpelling(t) + " = " + value +
             ";");
  }
}

}  // namespace

std::string tlasIndex(const TraceArgs& t, const StageContext& ctx) {
  if (t.tlas_index.empty()) return std::to_string(t.tlas) + "u";
  return "(rs_tlas_i % " + std::to_string(ctx.c.scene.tlasCount()) + "u)";
}

std::string tlasOperand(const TraceArgs& t, const StageContext& ctx) {
  if (ctx.c.scene.tlasCount() <= 1) return "rs_tlas";
  if (t.tlas_index.empty()) return "rs_tlas[" + std::to_string(t.tlas) + "]";
  return "rs_tlas[nonuniformEXT" + tlasIndex(t, ctx) + "]";
}

void tlasIndexLocal(const TraceArgs& t, const StageContext& ctx, GlslWriter& out) {
  if (!t.tlas_index.empty()) out.line("uint rs_tlas_i = " + emitExpr(t.tlas_index[0], ctx) + ";");
}

namespace {

// The trace's arguments as locals rs_flags .. rs_tmax: the case's
// expressions, else raygen's launch ray or the rays defaults.
void traceLocals(const TraceArgs& t, const StageContext& ctx, GlslWriter& out) {
  const bool raygen = ctx.stage == Stage::Raygen;
  const Ray& d = ctx.c.rays.defaults;
  auto def = [&](const std::string& launch, const std::string& nested) {
    return raygen ? launch : nested;
  };
  const Arg args[] = {
      {"uint", "rs_flags", &t.flags, def("rs_ray.flags", glslUint(d.flags))},
      {"uint", "rs_cull_mask", &t.cull_mask, def("rs_ray.cull_mask", glslUint(d.cull_mask))},
      {"uint", "rs_sbt_offset", &t.sbt_offset, def("rs_ray.sbt_offset", glslUint(d.sbt_offset))},
      {"uint", "rs_sbt_stride", &t.sbt_stride, def("rs_ray.sbt_stride", glslUint(d.sbt_stride))},
      {"uint", "rs_miss", &t.miss, def("rs_ray.miss", glslUint(d.miss))},
      {"vec3", "rs_origin", &t.origin, def("rs_ray.origin", "")},
      {"float", "rs_tmin", &t.tmin, def("rs_ray.tmin", glslFloat(d.tmin))},
      {"vec3", "rs_direction", &t.direction, def("rs_ray.direction", "")},
      {"float", "rs_tmax", &t.tmax, def("rs_ray.tmax", glslFloat(d.tmax))},
  };
  for (const Arg& a : args) {
    std::string value = a.given->empty() ? a.fallback : emitExpr(a.given->front(), ctx);
    if (value.empty()) {
      out.raw(std::string("#error rayspec: a trace outside raygen needs ") + (a.local + 3) + "\n");
      value = "vec3(0.0)";
    }
    out.line(std::string(a.type) + " " + a.local + " = " + value + ";");
  }
}

// execute: the payload started as a trace starts it, the hit object's
// shader run on it, the result read as a trace's.
void emitExecute(const Stmt& s, const StageContext& ctx, GlslWriter& out) {
  out.open("{  // execute");
  startPayload(s, ctx, out);
  out.line("hitObjectExecuteShaderNV(rs_hit_object, " +
           std::to_string(outgoingLocation(ctx, s.trace.location)) + ");");
  emitPayloadResult(ctx, s.trace.location, out);
  out.close();
}

// reorder: with the hit object, the hint, or both.
std::string reorderCall(const Stmt& s, const StageContext& ctx) {
  std::string args = s.size ? "rs_hit_object" : "";
  for (const auto& [name, value] : s.assigns)
    args += (args.empty() ? "" : ", ") + emitExpr(value, ctx);
  return "reorderThreadNV(" + args + ");";
}

// record_hit: the ray's locals, the attributes stored where
// hitObjectGetAttributesNV reads them (location 0), then
// hitObjectRecordHitNV (the record by offset and stride) or
// hitObjectRecordHitWithIndexNV (by index) into the stage's hit object.
void emitRecordHit(const Stmt& s, const StageContext& ctx, GlslWriter& out) {
  out.open("{  // record_hit");
  traceLocals(s.trace, ctx, out);
  std::string ids;
  for (const auto& [name, value] : s.assigns) {
    const std::string v = emitExpr(value, ctx);
    if (name == "attributes")
      out.line("rs_hit_object_attr = " + v + ";");
    else if (name == "hit_kind" || name == "sbt_index")
      ids += ", " + v;
    else  // the instance, primitive and geometry: int operands
      ids += ", int(" + v + ")";
  }
  const std::string sbt = s.size ? "" : ", rs_sbt_offset, rs_sbt_stride";
  out.line(std::string(s.size ? "hitObjectRecordHitWithIndexNV" : "hitObjectRecordHitNV") +
           "(rs_hit_object, " + tlasOperand(s.trace, ctx) + ids + sbt +
           ", rs_origin, rs_tmin, rs_direction, rs_tmax, 0);");
  out.close();
}

}  // namespace

void emitHitObjectStatement(const Stmt& s, const StageContext& ctx, GlslWriter& out) {
  if (tracesByRayQuery(ctx)) {  // refused before (case/ray_query_inlining.h)
    out.raw("#error rayspec: hit objects have no ray query form\n");
    return;
  }
  switch (s.kind) {
    case Stmt::Kind::ExecuteHitObject:
      emitExecute(s, ctx, out);
      break;
    case Stmt::Kind::RecordMiss:
      out.open("{  // record_miss");
      traceLocals(s.trace, ctx, out);
      out.line(
          "hitObjectRecordMissNV(rs_hit_object, rs_miss, rs_origin, rs_tmin, rs_direction, "
          "rs_tmax);");
      out.close();
      break;
    case Stmt::Kind::RecordEmpty:
      out.line("hitObjectRecordEmptyNV(rs_hit_object);");
      break;
    case Stmt::Kind::RecordHit:
      emitRecordHit(s, ctx, out);
      break;
    case Stmt::Kind::Reorder:
      out.line(reorderCall(s, ctx));
      break;
    default:
      break;
  }
}

void emitTrace(const Stmt& s, const StageContext& ctx, GlslWriter& out) {
  const bool raygen = ctx.stage == Stage::Raygen;
  if (!raygen && ctx.stage != Stage::ClosestHit && ctx.stage != Stage::Miss) {
    out.raw(std::string("#error rayspec: trace is not allowed in ") + stageName(ctx.stage) + "\n");
    return;
  }
  const TraceArgs& t = s.trace;
  out.open("{  // trace");
  traceLocals(t, ctx, out);
  tlasIndexLocal(t, ctx, out);
  if (tracesByRayQuery(ctx)) {  // a ray query loop (glsl/emit_ray_query.h)
    const uint32_t l = s.trace.location;
    if (ctx.inlined)  // a function's payload, not the stage's
      out.line(payloadTypeOf(ctx.c.pipeline, l) + " " + outgoingPayload(l) + ";");
    startPayload(s, ctx, out);
    if (emitRayQueryTrace(s, ctx, out)) emitPayloadResult(ctx, l, out);
    out.close();
    return;
  }
  startPayload(s, ctx, out);
  const uint32_t location = outgoingLocation(ctx, s.trace.location);
  out.line(t.hit_object ? hitObjectTraceCall(tlasOperand(t, ctx), location)
                        : traceCall(ctx, tlasOperand(t, ctx), location));
  emitPayloadResult(ctx, s.trace.location, out);
  out.close();
}

}  // namespace rayspec
