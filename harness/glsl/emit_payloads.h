// The payload types of a case (pipeline.payloads) in GLSL, and the payload
// variables of each stage: the incoming payload of miss, closest-hit and
// any-hit (location 0, the type of its `payload:` location), one outgoing
// payload per location a stage traces with (rs_payload_<L>, at location L in
// raygen and L + 1 elsewhere), and the result of the stage's last trace
// (raygen: `payload`; closest-hit and miss: `child`) of the largest type.
#pragma once

#include <cstdint>
#include <string>

#include "glsl/glsl_writer.h"
#include "glsl/stage_context.h"

namespace rayspec {

// RsPayload (no words) or RsPayloadW<N>.
std::string payloadTypeName(uint32_t words);
// struct RsPayloadW<N> for each word count N > 0 of the case.
void emitPayloadStructs(const StageContext& ctx, GlslWriter& out);
void emitPayloadVariables(const StageContext& ctx, GlslWriter& out);
// main()'s first lines: the last-trace result starts zero (depth: raygen 1,
// else the incoming depth + 1).
void emitPayloadStart(const StageContext& ctx, GlslWriter& out);
// The variable a trace at `location` passes, and its location number here.
std::string outgoingPayload(uint32_t location);
uint32_t outgoingLocation(const StageContext& ctx, uint32_t location);
// After a trace at `location`: its payload into the last-trace result.
void emitPayloadResult(const StageContext& ctx, uint32_t location, GlslWriter& out);

}  // namespace rayspec
