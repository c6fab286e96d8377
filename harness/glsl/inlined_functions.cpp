#include "glsl/inlined_functions.h"

#include "glsl/emit_call_data.h"
#include "glsl/emit_payloads.h"
#include "glsl/inlined_levels.h"

namespace rayspec {
namespace {

// The shader's name as part of an identifier: hit1.any_hit -> hit1_any_hit.
std::string identifier(const std::string& shader) {
  std::string s = shader;
  for (char& ch : s)
    if (ch == '.') ch = '_';
  return s;
}

// The program's interface inlined (glsl/emit_ray_query.cpp: its function's
// parameters and the locals it declares), as {type, name}.
std::vector<std::pair<std::string, std::string>> inlinedInterface(const StageContext& ctx) {
  const Pipeline& p = ctx.c.pipeline;
  const std::string payload = "inout " + payloadTypeOf(p, 0);
  const std::string attribute = ctx.attributeStruct() ? "RsAttr" : "vec2";
  std::vector<std::pair<std::string, std::string>> v;
  switch (ctx.stage) {
    case Stage::Intersection:
      return {{payload, "rs_ah_payload"}, {"inout " + attribute, "rs_attr"}};
    case Stage::AnyHit:
      return {{payload, "payload"},
              {attribute, "rs_attr"},
              {"float", "rs_hit_t"},
              {"uint", "rs_hit_kind"},
              {"inout uint", "rs_ah_verdict"}};
    case Stage::ClosestHit:
      v = {{payload, "payload"},
           {attribute, "rs_attr"},
           {"float", "rs_hit_t"},
           {"uint", "rs_hit_kind"}};
      break;
    default:
      v = {{payload, "payload"}};
      break;
  }
  if (ctx.uses.trace || ctx.uses.reads_child)
    v.push_back({"inout " + resultPayloadType(p), "child"});
  if (ctx.uses.call || ctx.uses.reads_callee)
    v.push_back({"inout " + resultCallDataType(p), "callee"});
  return v;
}

}  // namespace

std::string functionName(const std::string& name, const StageContext& ctx) {
  const std::string plain = "rs_fn_" + name;
  return ctx.inlined ? atLevel(plain + "_" + identifier(ctx.name), ctx.level) : plain;
}

std::string inlinedFunctionParams(const StageContext& ctx) {
  if (!ctx.inlined) return "";
  std::string s;
  for (const auto& [type, name] : inlinedInterface(ctx)) s += ", " + type + " " + name;
  return s;
}

std::string inlinedFunctionArgs(const StageContext& ctx) {
  if (!ctx.inlined) return "";
  std::string s;
  for (const auto& [type, name] : inlinedInterface(ctx)) s += ", " + name;
  return s;
}

void afterInlinedInvoke(const StageContext& ctx, GlslWriter& out) {
  if (!ctx.inlined) return;
  if (ctx.stage == Stage::AnyHit)
    out.line(std::string("if (rs_ah_verdict != kRsAccept) return") +
             (ctx.in_function ? ";" : " rs_ah_verdict;"));
  if (ctx.stage == Stage::Intersection) out.line("if (rs_q_done) return;");
}

std::string inlinedVerdict(bool ignore, const StageContext& ctx) {
  const std::string verdict = ignore ? "kRsIgnore" : "kRsTerminate";
  if (ctx.in_function) return "rs_ah_verdict = " + verdict + "; return;";
  return "return " + verdict + ";";
}

}  // namespace rayspec
