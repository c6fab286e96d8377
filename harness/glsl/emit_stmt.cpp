#include "glsl/emit_stmt.h"

#include <algorithm>
#include <cctype>

#include "glsl/emit_call_data.h"
#include "glsl/emit_control.h"
#include "glsl/emit_expr.h"
#include "glsl/emit_payloads.h"
#include "glsl/emit_query.h"
#include "glsl/emit_trace.h"
#include "glsl/inlined_functions.h"
#include "glsl/inlined_levels.h"
#include "program/payload_words.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

std::string upper(const std::string& s) {
  std::string u = s;
  for (char& ch : u) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  return u;
}

std::string quoted(const std::string& s) {
  return "\"" + s + "\"";
}

void count(const Stmt& s, const StageContext& ctx, GlslWriter& out) {
  const auto& names = ctx.plan.counters;
  auto it = std::find(names.begin(), names.end(), s.counter);
  if (it == names.end()) {
    out.line("// count " + quoted(s.counter) + ": not kept by the plan");
    return;
  }
  out.line("rs_count(" + std::to_string(it - names.begin()) + "u);  // count " + quoted(s.counter));
}

void record(const Stmt& s, const StageContext& ctx, GlslWriter& out) {
  for (const auto& [field, value] : s.assigns) {
    const int index = recordFieldIndex(field);
    if (index < 0 || !ctx.uses.record_fields.count(index)) {
      out.line("// record " + field + ": not kept by the plan");
      continue;
    }
    const RecordField& f = recordFields()[index];
    const char* fn = f.type == FieldType::Uint ? "rs_record_uint"
                     : f.words == 1            ? "rs_record_float"
                     : f.words == 2            ? "rs_record_vec2"
                     : f.words == 3            ? "rs_record_vec3"
                                               : "rs_record_vec4";
    std::string v = emitExpr(value, ctx);
    if (f.type == FieldType::Uint && value.type == ValueType::Bool) v = "uint(" + v + ")";
    out.line(std::string(fn) + "(" + fieldOffsetMacro(field) + ", " + fieldBitMacro(field) + ", " +
             v + ");");
  }
}

// payload.x = ... / call.x = ..., in the order written.
void assignFields(const Stmt& s, const std::string& target, const StageContext& ctx,
                  GlslWriter& out) {
  for (const auto& [field, value] : s.assigns) {
    const auto word = payloadWordField(field);   // word3 -> words[3]
    const auto sized = sizedMemberField(field);  // int8 -> rs_int8
    const std::string member = word    ? "words[" + std::to_string(*word) + "]"
                               : sized ? sizedMemberGlsl(*sized)
                                       : field;
    out.line(target + "." + member + " = " + emitExpr(value, ctx) + ";");
  }
}

// A report in an intersection inlined in raygen: the group's report function
// (glsl/emit_ray_query.cpp); an any-hit that terminated ends the shader.
void reportInlined(const Stmt& s, const StageContext& ctx, GlslWriter& out) {
  out.open("{  // report");
  out.line(
      "const bool rs_accepted = " + atLevel("rs_report_" + std::to_string(ctx.group), ctx.level) +
      "(rs_ah_payload, " + emitExpr(s.t, ctx) + ", " + emitExpr(s.hit_kind, ctx) + ", rs_attr);");
  out.line("if (rs_q_done) return;");
  if (!s.then_.empty() || !s.else_.empty()) {
    out.open("if (rs_accepted) {");
    emitProgram(s.then_, ctx, out);
    if (!s.else_.empty()) {
      out.reopen("} else {");
      emitProgram(s.else_, ctx, out);
    }
    out.close();
  }
  out.close();
}

void report(const Stmt& s, const StageContext& ctx, GlslWriter& out) {
  const std::string bary = ctx.attributeStruct() ? "rs_attr.bary" : "rs_attr";
  out.line(bary + " = " +
           (s.attribute.empty() ? std::string("vec2(0.0)") : emitExpr(s.attribute[0], ctx)) + ";");
  // Words the report does not give are zero.
  for (uint32_t i = 0; i < ctx.attribute_words; ++i) {
    std::string value = "0u";
    for (const auto& [name, e] : s.assigns)
      if (payloadWordField(name) == i) value = emitExpr(e, ctx);
    out.line("rs_attr.words[" + std::to_string(i) + "] = " + value + ";");
  }
  for (ValueType t : ctx.attribute_sized) {  // and sized members
    std::string value = sizedZero(t);
    for (const auto& [name, e] : s.assigns)
      if (sizedMemberField(name) == t) value = emitExpr(e, ctx);
    out.line("rs_attr." + sizedMemberGlsl(t) + " = " + value + ";");
  }
  if (ctx.inlined) {
    reportInlined(s, ctx, out);
    return;
  }
  const std::string call =
      "reportIntersectionEXT(" + emitExpr(s.t, ctx) + ", " + emitExpr(s.hit_kind, ctx) + ")";
  if (s.then_.empty() && s.else_.empty()) {
    out.line(call + ";");
    return;
  }
  out.open("if (" + call + ") {");
  emitProgram(s.then_, ctx, out);
  if (!s.else_.empty()) {
    out.reopen("} else {");
    emitProgram(s.else_, ctx, out);
  }
  out.close();
}

void ifStmt(const Stmt& s, const StageContext& ctx, GlslWriter& out) {
  out.open("if (" + emitExpr(s.cond, ctx) + ") {");
  emitProgram(s.then_, ctx, out);
  if (!s.else_.empty()) {
    out.reopen("} else {");
    emitProgram(s.else_, ctx, out);
  }
  out.close();
}

void light(const Stmt& s, GlslWriter& out) {
  if (s.light != "point" && s.light != "spot" && s.light != "directional") {
    out.raw("#error rayspec: unknown light " + quoted(s.light) + "\n");
    return;
  }
  out.line("call.color = rs_light_" + s.light + "(call.position, call.normal);");
}

void terminator(const Stmt& s, const StageContext& ctx, GlslWriter& out) {
  const bool ignore = s.kind == Stmt::Kind::Ignore;
  if (ctx.stage != Stage::AnyHit) {
    out.raw(std::string("#error rayspec: ") + (ignore ? "ignore" : "terminate") +
            " is only allowed in any_hit\n");
    return;
  }
  if (ctx.inlined)  // the any-hit function's verdict (glsl/emit_ray_query.h)
    out.line(inlinedVerdict(ignore, ctx));
  else
    out.line(ignore ? "ignoreIntersectionEXT;" : "terminateRayEXT;");
}

}  // namespace

std::string fieldOffsetMacro(const std::string& field) {
  return "RS_FIELD_" + upper(field);
}
std::string fieldBitMacro(const std::string& field) {
  return "RS_BIT_" + upper(field);
}

void emitProgram(const Program& program, const StageContext& ctx, GlslWriter& out) {
  for (const Stmt& s : program) {
    switch (s.kind) {
      case Stmt::Kind::Count:
        count(s, ctx, out);
        break;
      case Stmt::Kind::Record:
        record(s, ctx, out);
        break;
      case Stmt::Kind::SetPayload:
        assignFields(s, "payload", ctx, out);
        break;
      case Stmt::Kind::SetCall:
        assignFields(s, "call", ctx, out);
        break;
      case Stmt::Kind::Ignore:
      case Stmt::Kind::Terminate:
        terminator(s, ctx, out);
        break;
      case Stmt::Kind::Report:
        report(s, ctx, out);
        break;
      case Stmt::Kind::Trace:
        emitTrace(s, ctx, out);
        break;
      case Stmt::Kind::Call:
        emitCall(s, ctx, out);
        break;
      case Stmt::Kind::ExecuteHitObject:
      case Stmt::Kind::RecordMiss:
      case Stmt::Kind::RecordEmpty:
      case Stmt::Kind::RecordHit:
      case Stmt::Kind::Reorder:
        emitHitObjectStatement(s, ctx, out);
        break;
      case Stmt::Kind::Light:
        light(s, out);
        break;
      case Stmt::Kind::If:
        ifStmt(s, ctx, out);
        break;
      case Stmt::Kind::RayQuery:
      case Stmt::Kind::RayQueries:
      case Stmt::Kind::RestartQuery:
      case Stmt::Kind::Candidates:
      case Stmt::Kind::Confirm:
      case Stmt::Kind::Generate:
      case Stmt::Kind::TerminateQuery:
        emitQueryStatement(s, ctx, out);
        break;
      default:
        emitControl(s, ctx, out);
        break;
    }
  }
}

}  // namespace rayspec
