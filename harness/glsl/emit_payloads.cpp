#include "glsl/emit_payloads.h"

#include <set>

namespace rayspec {
namespace {

bool receivesPayload(Stage s) {
  return s == Stage::Miss || s == Stage::ClosestHit || s == Stage::AnyHit;
}

// The last trace's result: raygen's `payload`, closest-hit's and miss's `child`.
std::string resultName(const StageContext& ctx) {
  return ctx.stage == Stage::Raygen ? "payload" : "child";
}

}  // namespace

std::string dataTypeName(const std::string& base, uint32_t words, const SizedMembers& sized) {
  if (words == 0 && sized.empty()) return base;
  std::string name = base + "W" + std::to_string(words);
  for (ValueType t : sized) name += std::string("_") + valueTypeSpelling(t);
  return name;
}

std::string payloadTypeName(uint32_t words, const SizedMembers& sized) {
  return dataTypeName("RsPayload", words, sized);
}

std::string payloadTypeOf(const Pipeline& p, uint32_t location) {
  return payloadTypeName(p.payloadWords(location), p.payloadSized(location));
}

std::string resultPayloadType(const Pipeline& p) {
  return payloadTypeName(p.maxPayloadWords(), p.allPayloadSized());
}

std::string sizedZero(ValueType t) {
  return std::string(valueTypeGlsl(t)) + "(0)";
}

void emitSizedMembers(const SizedMembers& sized, GlslWriter& out) {
  for (ValueType t : sized)
    out.line(std::string(valueTypeGlsl(t)) + " " + sizedMemberGlsl(t) + ";");
}

void copySizedMembers(const std::string& to, const SizedMembers& to_members,
                      const std::string& from, const SizedMembers& from_members, GlslWriter& out) {
  for (ValueType t : to_members)
    out.line(to + "." + sizedMemberGlsl(t) + " = " +
             (holdsSized(from_members, t) ? from + "." + sizedMemberGlsl(t) : sizedZero(t)) + ";");
}

void emitPayloadStructs(const StageContext& ctx, GlslWriter& out) {
  const Pipeline& p = ctx.c.pipeline;
  std::set<std::pair<uint32_t, SizedMembers>> types;
  for (uint32_t l = 0; l < p.payload_words.size(); ++l)
    types.insert({p.payloadWords(l), p.payloadSized(l)});
  types.insert({p.maxPayloadWords(), p.allPayloadSized()});  // the result's
  types.erase({0, {}});
  if (types.empty()) return;
  out.line("");
  out.line(
      "// ---- payload types of pipeline.payloads: RsPayload, N more words, sized members ----");
  for (const auto& [n, sized] : types) {
    out.open("struct " + payloadTypeName(n, sized) + " {");
    out.line("vec4 color;");
    out.line("uint value;");
    out.line("uint depth;");
    if (n) out.line("uint words[" + std::to_string(n) + "];");
    emitSizedMembers(sized, out);
    out.close("};");
  }
}

std::string outgoingPayload(uint32_t location) {
  return "rs_payload_" + std::to_string(location);
}

uint32_t outgoingLocation(const StageContext& ctx, uint32_t location) {
  return ctx.stage == Stage::Raygen ? location : location + 1;
}

void emitPayloadVariables(const StageContext& ctx, GlslWriter& out) {
  if (receivesPayload(ctx.stage) || (ctx.rejected && ctx.uses.incoming_payload))
    out.line("layout(location = 0) rayPayloadInEXT " +
             payloadTypeOf(ctx.c.pipeline, ctx.payload_location) + " payload;");
  if (!ctx.uses.trace) {
    // Raygen reads `payload`, closest-hit and miss `child`, even when they
    // never trace (all zero, as the model has it).
    if (ctx.stage == Stage::Raygen || ctx.uses.reads_child)
      out.line(resultPayloadType(ctx.c.pipeline) + " " + resultName(ctx) + ";");
    return;
  }
  // A compute shader's traces are ray query loops: their payloads are plain.
  for (uint32_t l : ctx.uses.trace_locations)
    out.line((ctx.compute ? std::string()
                          : "layout(location = " + std::to_string(outgoingLocation(ctx, l)) +
                                ") rayPayloadEXT ") +
             payloadTypeOf(ctx.c.pipeline, l) + " " + outgoingPayload(l) + ";");
  out.line(resultPayloadType(ctx.c.pipeline) + " " + resultName(ctx) +
           ";  // the last trace's payload");
}

void emitPayloadStart(const StageContext& ctx, GlslWriter& out) {
  const bool raygen = ctx.stage == Stage::Raygen;
  if (!raygen && !ctx.uses.trace && !ctx.uses.reads_child) return;
  const std::string r = resultName(ctx);
  out.line(r + ".color = vec4(0.0);");
  out.line(r + ".value = 0u;");
  out.line(r + ".depth = " + (raygen ? std::string("1u") : "payload.depth + 1u") + ";");
  const uint32_t n = ctx.c.pipeline.maxPayloadWords();
  if (n) out.line("for (int i = 0; i < " + std::to_string(n) + "; ++i) " + r + ".words[i] = 0u;");
  copySizedMembers(r, ctx.c.pipeline.allPayloadSized(), "", {}, out);
}

void emitPayloadResult(const StageContext& ctx, uint32_t location, GlslWriter& out) {
  const std::string r = resultName(ctx), p = outgoingPayload(location);
  const Pipeline& pipe = ctx.c.pipeline;
  const uint32_t n = pipe.payloadWords(location), largest = pipe.maxPayloadWords();
  if (payloadTypeOf(pipe, location) == resultPayloadType(pipe)) {
    out.line(r + " = " + p + ";");
    return;
  }
  out.line(r + ".color = " + p + ".color;");
  out.line(r + ".value = " + p + ".value;");
  out.line(r + ".depth = " + p + ".depth;");
  for (uint32_t i = 0; i < largest; ++i)
    out.line(r + ".words[" + std::to_string(i) +
             "] = " + (i < n ? p + ".words[" + std::to_string(i) + "]" : std::string("0u")) + ";");
  copySizedMembers(r, pipe.allPayloadSized(), p, pipe.payloadSized(location), out);
}

}  // namespace rayspec
