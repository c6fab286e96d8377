// The callable data types of a case (pipeline.callable_data) in GLSL, the
// callable data variables of each stage, and executeCallableEXT statements:
// a callable's incoming data (location 0, the type of its `call_data:`
// location), one outgoing variable per location a stage calls with
// (rs_callee_<L>, at location L, or L + 1 inside a callable), and the result
// of the stage's last call (`callee`) of the largest type.
#pragma once

#include <cstdint>
#include <string>

#include "glsl/glsl_writer.h"
#include "glsl/stage_context.h"
#include "program/payload_words.h"

namespace rayspec {

// RsCallData (no words, no sized members) or RsCallDataW<N>[_<type>..]
// (glsl/emit_payloads.h dataTypeName).
std::string callDataTypeName(uint32_t words, const SizedMembers& sized = {});
// Location l's callable data type, and that of a call's result (the
// largest words, every location's sized members).
std::string callDataTypeOf(const Pipeline& p, uint32_t location);
std::string resultCallDataType(const Pipeline& p);
// struct RsCallDataW<N>[_<type>..] for each callable data type of the case
// but the plain one, and the result type.
void emitCallDataStructs(const StageContext& ctx, GlslWriter& out);
void emitCallDataVariables(const StageContext& ctx, GlslWriter& out);
// main()'s first lines: the last-call result starts zero.
void emitCallDataStart(const StageContext& ctx, GlslWriter& out);
// A call: its arguments evaluated first, then the data of its location
// written (zero where not given), the call, and the data copied into `callee`.
void emitCall(const Stmt& s, const StageContext& ctx, GlslWriter& out);

}  // namespace rayspec
