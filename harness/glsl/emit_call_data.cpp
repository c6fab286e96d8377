#include "glsl/emit_call_data.h"

#include <set>

#include "glsl/emit_expr.h"
#include "glsl/emit_payloads.h"
#include "program/payload_words.h"

namespace rayspec {
namespace {

// RsCallData's members and their zero values (shaders/payload.glsl).
struct Member {
  const char* name;
  const char* zero;
};
constexpr Member kMembers[] = {
    {"color", "vec4(0.0)"}, {"position", "vec3(0.0)"}, {"value", "0u"}, {"normal", "vec3(0.0)"}};

std::string calleeVariable(uint32_t location) {
  return "rs_callee_" + std::to_string(location);
}

// Locations are numbered per stage; inside a callable location 0 is its
// incoming data, so its calls start at 1.
uint32_t calleeLocation(const StageContext& ctx, uint32_t location) {
  return location + (ctx.stage == Stage::Callable ? 1 : 0);
}

// The call's data at `location` into `callee`, member by member; words
// beyond the location's and sized members it lacks are zero.
void copyToCallee(const Pipeline& p, uint32_t location, GlslWriter& out) {
  const std::string from = calleeVariable(location);
  if (callDataTypeOf(p, location) == resultCallDataType(p)) {
    out.line("callee = " + from + ";");
    return;
  }
  for (const Member& m : kMembers)
    out.line(std::string("callee.") + m.name + " = " + from + "." + m.name + ";");
  const uint32_t from_words = p.callDataWords(location);
  for (uint32_t i = 0; i < p.maxCallDataWords(); ++i) {
    const std::string w = "words[" + std::to_string(i) + "]";
    out.line("callee." + w + " = " + (i < from_words ? from + "." + w : std::string("0u")) + ";");
  }
  copySizedMembers("callee", p.allCallDataSized(), from, p.callDataSized(location), out);
}

}  // namespace

std::string callDataTypeName(uint32_t words, const SizedMembers& sized) {
  return dataTypeName("RsCallData", words, sized);
}

std::string callDataTypeOf(const Pipeline& p, uint32_t location) {
  return callDataTypeName(p.callDataWords(location), p.callDataSized(location));
}

std::string resultCallDataType(const Pipeline& p) {
  return callDataTypeName(p.maxCallDataWords(), p.allCallDataSized());
}

void emitCallDataStructs(const StageContext& ctx, GlslWriter& out) {
  const Pipeline& p = ctx.c.pipeline;
  std::set<std::pair<uint32_t, SizedMembers>> types;
  for (uint32_t l = 0; l < p.call_data_words.size(); ++l)
    types.insert({p.callDataWords(l), p.callDataSized(l)});
  types.insert({p.maxCallDataWords(), p.allCallDataSized()});  // the result's
  types.erase({0, {}});
  if (types.empty()) return;
  out.line("");
  out.line(
      "// ---- callable data types of pipeline.callable_data: RsCallData, N more words, sized "
      "members ----");
  for (const auto& [n, sized] : types) {
    out.open("struct " + callDataTypeName(n, sized) + " {");
    out.line("vec4 color;");
    out.line("vec3 position;");
    out.line("uint value;");
    out.line("vec3 normal;");
    out.line("uint pad;");
    if (n) out.line("uint words[" + std::to_string(n) + "];");
    emitSizedMembers(sized, out);
    out.close("};");
  }
}

void emitCallDataVariables(const StageContext& ctx, GlslWriter& out) {
  const Pipeline& p = ctx.c.pipeline;
  if (ctx.stage == Stage::Callable)
    out.line("layout(location = 0) callableDataInEXT " + callDataTypeOf(p, ctx.call_data_location) +
             " call;");
  if (!ctx.uses.call) {
    // callee.* read in a stage that never calls: all zero, as the model has it.
    if (ctx.uses.reads_callee) out.line(resultCallDataType(p) + " callee;  // no call: all zero");
    return;
  }
  for (uint32_t l : ctx.uses.call_locations)
    out.line("layout(location = " + std::to_string(calleeLocation(ctx, l)) + ") callableDataEXT " +
             callDataTypeOf(p, l) + " " + calleeVariable(l) + ";");
  out.line(resultCallDataType(p) + " callee;  // the last call's data");
}

void emitCallDataStart(const StageContext& ctx, GlslWriter& out) {
  if (!ctx.uses.call && !ctx.uses.reads_callee) return;
  for (const Member& m : kMembers) out.line(std::string("callee.") + m.name + " = " + m.zero + ";");
  out.line("callee.pad = 0u;");
  const uint32_t n = ctx.c.pipeline.maxCallDataWords();
  if (n) out.line("for (int i = 0; i < " + std::to_string(n) + "; ++i) callee.words[i] = 0u;");
  copySizedMembers("callee", ctx.c.pipeline.allCallDataSized(), "", {}, out);
}

void emitCall(const Stmt& s, const StageContext& ctx, GlslWriter& out) {
  if (ctx.stage == Stage::AnyHit || ctx.stage == Stage::Intersection) {
    out.raw(std::string("#error rayspec: call is not allowed in ") + stageName(ctx.stage) + "\n");
    return;
  }
  const Pipeline& p = ctx.c.pipeline;
  const uint32_t location = s.call_location, words = p.callDataWords(location);
  auto given = [&](const std::string& field, const std::string& zero) {
    for (const auto& [name, expr] : s.assigns)
      if (name == field) return emitExpr(expr, ctx);
    return zero;
  };
  // No program reads the outgoing variable, so the arguments go straight in.
  out.open("{  // call");
  const std::string d = calleeVariable(location);
  for (const Member& m : kMembers) out.line(d + "." + m.name + " = " + given(m.name, m.zero) + ";");
  out.line(d + ".pad = 0u;");
  for (uint32_t i = 0; i < words; ++i)
    out.line(d + ".words[" + std::to_string(i) + "] = " + given("word" + std::to_string(i), "0u") +
             ";");
  for (ValueType t : p.callDataSized(location))
    out.line(d + "." + sizedMemberGlsl(t) + " = " + given(valueTypeSpelling(t), sizedZero(t)) +
             ";");
  out.line("uint rs_index = " + emitExpr(s.call_index, ctx) + ";");
  out.line("executeCallableEXT(rs_index, " + std::to_string(calleeLocation(ctx, location)) + ");");
  copyToCallee(p, location, out);
  out.close();
}

}  // namespace rayspec
