#include "glsl/emit_call_data.h"

#include <set>

#include "glsl/emit_expr.h"
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

// `to` = `from` member by member; words beyond `from_words` are zero.
void copyData(const std::string& to, const std::string& from, uint32_t from_words,
              uint32_t to_words, GlslWriter& out) {
  for (const Member& m : kMembers) out.line(to + "." + m.name + " = " + from + "." + m.name + ";");
  for (uint32_t i = 0; i < to_words; ++i) {
    const std::string w = "words[" + std::to_string(i) + "]";
    out.line(to + "." + w + " = " + (i < from_words ? from + "." + w : std::string("0u")) + ";");
  }
}

}  // namespace

std::string callDataTypeName(uint32_t words) {
  return words == 0 ? "RsCallData" : "RsCallDataW" + std::to_string(words);
}

void emitCallDataStructs(const StageContext& ctx, GlslWriter& out) {
  std::set<uint32_t> counts(ctx.c.pipeline.call_data_words.begin(),
                            ctx.c.pipeline.call_data_words.end());
  counts.erase(0);
  if (counts.empty()) return;
  out.line("");
  out.line(
      "// ---- callable data types of pipeline.callable_data: RsCallData and N more words ----");
  for (uint32_t n : counts) {
    out.open("struct " + callDataTypeName(n) + " {");
    out.line("vec4 color;");
    out.line("vec3 position;");
    out.line("uint value;");
    out.line("vec3 normal;");
    out.line("uint pad;");
    out.line("uint words[" + std::to_string(n) + "];");
    out.close("};");
  }
}

void emitCallDataVariables(const StageContext& ctx, GlslWriter& out) {
  const Pipeline& p = ctx.c.pipeline;
  if (ctx.stage == Stage::Callable)
    out.line("layout(location = 0) callableDataInEXT " +
             callDataTypeName(p.callDataWords(ctx.call_data_location)) + " call;");
  if (!ctx.uses.call) {
    // callee.* read in a stage that never calls: all zero, as the model has it.
    if (ctx.uses.reads_callee)
      out.line(callDataTypeName(p.maxCallDataWords()) + " callee;  // no call: all zero");
    return;
  }
  for (uint32_t l : ctx.uses.call_locations)
    out.line("layout(location = " + std::to_string(calleeLocation(ctx, l)) + ") callableDataEXT " +
             callDataTypeName(p.callDataWords(l)) + " " + calleeVariable(l) + ";");
  out.line(callDataTypeName(p.maxCallDataWords()) + " callee;  // the last call's data");
}

void emitCallDataStart(const StageContext& ctx, GlslWriter& out) {
  if (!ctx.uses.call && !ctx.uses.reads_callee) return;
  for (const Member& m : kMembers) out.line(std::string("callee.") + m.name + " = " + m.zero + ";");
  out.line("callee.pad = 0u;");
  const uint32_t n = ctx.c.pipeline.maxCallDataWords();
  if (n) out.line("for (int i = 0; i < " + std::to_string(n) + "; ++i) callee.words[i] = 0u;");
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
  out.line("uint rs_index = " + emitExpr(s.call_index, ctx) + ";");
  out.line("executeCallableEXT(rs_index, " + std::to_string(calleeLocation(ctx, location)) + ");");
  copyData("callee", d, words, p.maxCallDataWords(), out);
  out.close();
}

}  // namespace rayspec
