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

std::string payloadTypeName(uint32_t words) {
  return words == 0 ? "RsPayload" : "RsPayloadW" + std::to_string(words);
}

void emitPayloadStructs(const StageContext& ctx, GlslWriter& out) {
  std::set<uint32_t> counts(ctx.c.pipeline.payload_words.begin(),
                            ctx.c.pipeline.payload_words.end());
  counts.erase(0);
  if (counts.empty()) return;
  out.line("");
  out.line("// ---- payload types of pipeline.payloads: RsPayload and N more words ----");
  for (uint32_t n : counts) {
    out.open("struct " + payloadTypeName(n) + " {");
    out.line("vec4 color;");
    out.line("uint value;");
    out.line("uint depth;");
    out.line("uint words[" + std::to_string(n) + "];");
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
             payloadTypeName(ctx.c.pipeline.payloadWords(ctx.payload_location)) + " payload;");
  if (!ctx.uses.trace) {
    // Raygen reads `payload`, closest-hit and miss `child`, even when they
    // never trace (all zero, as the model has it).
    if (ctx.stage == Stage::Raygen || ctx.uses.reads_child)
      out.line(payloadTypeName(ctx.c.pipeline.maxPayloadWords()) + " " + resultName(ctx) + ";");
    return;
  }
  // A compute shader's traces are ray query loops: their payloads are plain.
  for (uint32_t l : ctx.uses.trace_locations)
    out.line((ctx.compute ? std::string()
                          : "layout(location = " + std::to_string(outgoingLocation(ctx, l)) +
                                ") rayPayloadEXT ") +
             payloadTypeName(ctx.c.pipeline.payloadWords(l)) + " " + outgoingPayload(l) + ";");
  out.line(payloadTypeName(ctx.c.pipeline.maxPayloadWords()) + " " + resultName(ctx) +
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
}

void emitPayloadResult(const StageContext& ctx, uint32_t location, GlslWriter& out) {
  const std::string r = resultName(ctx), p = outgoingPayload(location);
  const uint32_t n = ctx.c.pipeline.payloadWords(location),
                 largest = ctx.c.pipeline.maxPayloadWords();
  if (n == largest) {
    out.line(r + " = " + p + ";");
    return;
  }
  out.line(r + ".color = " + p + ".color;");
  out.line(r + ".value = " + p + ".value;");
  out.line(r + ".depth = " + p + ".depth;");
  for (uint32_t i = 0; i < largest; ++i)
    out.line(r + ".words[" + std::to_string(i) +
             "] = " + (i < n ? p + ".words[" + std::to_string(i) + "]" : std::string("0u")) + ";");
}

}  // namespace rayspec
