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
#include "program/payload_words.h"

namespace rayspec {

// A data type's name keyed by the whole type: `base` with no words and no
// sized members, else base + "W<N>" and "_<type>" for each member
// (RsPayloadW2_int8_f16vec4).
std::string dataTypeName(const std::string& base, uint32_t words, const SizedMembers& sized = {});
// RsPayload (no words, no sized members) or RsPayloadW<N>[_<type>..].
std::string payloadTypeName(uint32_t words, const SizedMembers& sized = {});
// Location l's payload type, and the type of a trace's result (the largest
// words, every location's sized members).
std::string payloadTypeOf(const Pipeline& p, uint32_t location);
std::string resultPayloadType(const Pipeline& p);
// A data type's sized members as struct members (`int8_t rs_int8;`), and
// `to`.member = `from`.member for each member of `to_members` (zero where
// `from_members` lacks it).
void emitSizedMembers(const SizedMembers& sized, GlslWriter& out);
void copySizedMembers(const std::string& to, const SizedMembers& to_members,
                      const std::string& from, const SizedMembers& from_members, GlslWriter& out);
// A sized type's zero in GLSL: int8_t(0), f16vec4(0).
std::string sizedZero(ValueType t);
// struct RsPayloadW<N>[_<type>..] for each payload type of the case but the
// plain one, and the result type.
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
