// Control flow and locals as GLSL: let, set, array, store, repeat, break,
// continue, switch, invoke, return; and the functions a stage invokes.
#include "glsl/emit_control.h"

#include <set>

#include "glsl/emit_expr.h"
#include "glsl/emit_stmt.h"
#include "glsl/inlined_functions.h"
#include "program/payload_words.h"

namespace rayspec {
namespace {

std::string zeroOf(ValueType t) {
  switch (t) {
    case ValueType::Bool:
      return "false";
    case ValueType::Uint:
      return "0u";
    case ValueType::Float:
      return "0.0";
    default:
      if (isSized(t)) return std::string(glslType(t)) + "(0)";
      return std::string(glslType(t)) + "(0.0)";
  }
}

// An array of a sized type is zero-initialised by its declaration (`= {}`,
// GL_EXT_null_initializer: an OpConstantNull), any other by a loop.
void array(const Stmt& s, GlslWriter& out) {
  const std::string name = localName(s.local), n = std::to_string(s.size) + "u";
  const std::string declared =
      std::string(glslType(s.local_type)) + " " + name + "[" + std::to_string(s.size) + "]";
  if (isSized(s.local_type)) {
    out.line(declared + " = {};");
    return;
  }
  out.line(declared + ";");
  out.line("for (uint rs_z = 0u; rs_z < " + n + "; ++rs_z) " + name +
           "[rs_z] = " + zeroOf(s.local_type) + ";");
}

// A struct local, each member zero (a constructor: no null initialiser).
void structure(const Stmt& s, GlslWriter& out) {
  const std::string type = structTypeName(s.params);
  std::string zeros;
  for (const auto& [member, t] : s.params) zeros += (zeros.empty() ? "" : ", ") + zeroOf(t);
  out.line(type + " " + localName(s.local) + " = " + type + "(" + zeros + ");");
}

// The count and the first value are evaluated once, before the first trip.
void repeat(const Stmt& s, const StageContext& ctx, GlslWriter& out) {
  const std::string id = std::to_string(out.nextId());
  const std::string trips = "rs_trips" + id, from = "rs_from" + id, k = "rs_k" + id;
  out.open("{  // repeat");
  out.line("uint " + trips + " = min(" + emitExpr(s.count, ctx) + ", " +
           std::to_string(kMaxLoopTrips) + "u);");
  out.line("uint " + from + " = " + emitExpr(s.from, ctx) + ";");
  out.open("for (uint " + k + " = 0u; " + k + " < " + trips + "; ++" + k + ") {");
  if (!s.local.empty()) out.line("uint " + localName(s.local) + " = " + from + " + " + k + ";");
  emitProgram(s.then_, ctx, out);
  out.close();
  out.close();
}

// Each case ends with break: no case falls through to the next.
void switchStmt(const Stmt& s, const StageContext& ctx, GlslWriter& out) {
  out.open("switch (" + emitExpr(s.cond, ctx) + ") {");
  for (const Stmt& c : s.then_) {
    out.open("case " + std::to_string(c.size) + "u: {");
    emitProgram(c.then_, ctx, out);
    out.line("break;");
    out.close();
  }
  out.open("default: {");
  emitProgram(s.else_, ctx, out);
  out.line("break;");
  out.close();
  out.close();
}

// A function that takes the caller's query (query: true) gets it first, as
// the rayQueryEXT parameter rs_query: GLSL passes the query object itself
// (glslang: a pointer), so what the function does to it the caller's sees.
void invoke(const Stmt& s, const StageContext& ctx, GlslWriter& out) {
  std::string args = s.query_param ? "rs_query" : "";
  for (const auto& [name, value] : s.assigns)
    args += (args.empty() ? "" : ", ") + emitExpr(value, ctx);
  const std::string extra = inlinedFunctionArgs(ctx);  // an inlined program's interface
  args += args.empty() && !extra.empty() ? extra.substr(2) : extra;
  out.line(functionName(s.local, ctx) + "(" + args + ");");
  afterInlinedInvoke(ctx, out);
}

// Callees first: GLSL wants a function defined (or declared) before its use.
void defineFunctions(const Program& p, const StageContext& ctx, std::set<std::string>& done,
                     GlslWriter& out) {
  for (const Stmt& s : p) {
    if (s.kind != Stmt::Kind::Invoke) {
      defineFunctions(s.then_, ctx, done, out);
      defineFunctions(s.else_, ctx, done, out);
      continue;
    }
    if (done.count(s.local)) continue;
    defineFunctions(s.then_, ctx, done, out);
    done.insert(s.local);
    std::string params = s.query_param ? "rayQueryEXT rs_query" : "";
    for (const auto& [name, type] : s.params)
      params += (params.empty() ? "" : ", ") + std::string(glslType(type)) + " " + localName(name);
    const std::string extra = inlinedFunctionParams(ctx);
    params += params.empty() && !extra.empty() ? extra.substr(2) : extra;
    StageContext body = ctx;
    body.in_function = true;
    out.line("");
    out.open("void " + functionName(s.local, ctx) + "(" + params + ") {");
    emitProgram(s.then_, body, out);
    out.close();
  }
}

}  // namespace

void emitControl(const Stmt& s, const StageContext& ctx, GlslWriter& out) {
  switch (s.kind) {
    case Stmt::Kind::Let:
      for (const auto& [name, value] : s.assigns)
        out.line(std::string(glslType(value.type)) + " " + localName(name) + " = " +
                 emitExpr(value, ctx) + ";");
      return;
    case Stmt::Kind::Set:
      for (const auto& [name, value] : s.assigns)
        out.line(localName(name) + " = " + emitExpr(value, ctx) + ";");
      return;
    case Stmt::Kind::Array:
      array(s, out);
      return;
    case Stmt::Kind::Struct:
      structure(s, out);
      return;
    case Stmt::Kind::Store: {
      if (s.assigns.empty()) return;
      // An array local, or a data array: store: {array: payload.words} -> payload.words[..]
      const std::string array = wordArrayOfStore(s.local) ? s.local : localName(s.local);
      out.line(array + "[" + arrayIndex(array, emitExpr(s.index, ctx)) +
               "] = " + emitExpr(s.assigns[0].second, ctx) + ";");
      return;
    }
    case Stmt::Kind::Repeat:
      repeat(s, ctx, out);
      return;
    case Stmt::Kind::Break:
      out.line("break;");
      return;
    case Stmt::Kind::Continue:
      out.line("continue;");
      return;
    case Stmt::Kind::Return:  // an inlined any-hit that ends accepts
      out.line(ctx.inlined && ctx.stage == Stage::AnyHit && !ctx.in_function ? "return kRsAccept;"
                                                                             : "return;");
      return;
    case Stmt::Kind::Switch:
      switchStmt(s, ctx, out);
      return;
    case Stmt::Kind::Invoke:
      invoke(s, ctx, out);
      return;
    default:
      out.raw("#error rayspec: a case label outside a switch\n");
      return;
  }
}

std::string structTypeName(const std::vector<std::pair<std::string, ValueType>>& members) {
  std::string name = "RsStruct";
  for (const auto& [member, type] : members)
    name += "_" + std::string(valueTypeSpelling(type)) + "_" + member;
  return name;
}

void emitStructTypes(const StageContext& ctx, GlslWriter& out) {
  for (const auto& members : ctx.plan.struct_types) {
    out.line("");
    out.open("struct " + structTypeName(members) + " {");
    for (const auto& [member, type] : members)
      out.line(std::string(glslType(type)) + " m_" + member + ";");
    out.close("};");
  }
}

void emitFunctions(const Program& program, const StageContext& ctx, GlslWriter& out) {
  std::set<std::string> done;
  GlslWriter functions;
  defineFunctions(program, ctx, done, functions);
  if (done.empty()) return;
  out.line("");
  out.line("// ---- functions (pipeline.functions) ----");
  out.raw(functions.text());
}

}  // namespace rayspec
