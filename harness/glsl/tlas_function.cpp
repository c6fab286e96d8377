#include "glsl/tlas_function.h"

#include "glsl/emit_payloads.h"
#include "glsl/inlined_levels.h"

namespace rayspec {
namespace {

const char* const kTraceParams =
    "uint rs_flags, uint rs_cull_mask, uint rs_sbt_offset, uint rs_sbt_stride, uint rs_miss, "
    "vec3 rs_origin, float rs_tmin, vec3 rs_direction, float rs_tmax";
const char* const kTraceArgs =
    "rs_flags, rs_cull_mask, rs_sbt_offset, rs_sbt_stride, rs_miss, rs_origin, rs_tmin, "
    "rs_direction, rs_tmax";
const char* const kQueryParams =
    "uint rs_flags, uint rs_cull_mask, vec3 rs_origin, float rs_tmin, vec3 rs_direction, "
    "float rs_tmax";
const char* const kQueryArgs = "rs_flags, rs_cull_mask, rs_origin, rs_tmin, rs_direction, rs_tmax";

// The parameter: with several top levels the caller may pass an element
// indexed per invocation, and only a parameter qualified nonuniformEXT makes
// the function's load of it NonUniform (glslang decorates that load), as
// the Vulkan environment for SPIR-V requires of a resource not dynamically
// uniform.
std::string tlasParam(const StageContext& ctx) {
  return ctx.c.scene.tlasCount() > 1 ? "nonuniformEXT accelerationStructureEXT rs_as"
                                     : "accelerationStructureEXT rs_as";
}

std::string traceFunction(uint32_t location) {
  return "rs_trace_through_" + std::to_string(location);
}

}  // namespace

void emitTlasFunctions(const StageContext& ctx, GlslWriter& out) {
  if (!ctx.c.pipeline.tlas_function) return;
  const bool traces = ctx.uses.trace && !tracesByRayQuery(ctx);
  if (!traces && !ctx.uses.ray_query) return;
  out.line("");
  out.line("// ---- pipeline.tlas_function: the top level passed to a function ----");
  if (traces)
    for (uint32_t l : ctx.uses.trace_locations) {
      const std::string at = std::to_string(outgoingLocation(ctx, l));
      out.open("void " + traceFunction(outgoingLocation(ctx, l)) + "(" + tlasParam(ctx) + ", " +
               kTraceParams + ") {");
      out.line(std::string("traceRayEXT(rs_as, ") + kTraceArgs + ", " + at + ");");
      out.close();
    }
  if (!ctx.uses.ray_query) return;
  out.open("void rs_query_through(rayQueryEXT rs_q, " + tlasParam(ctx) + ", " + kQueryParams +
           ") {");
  out.line(std::string("rayQueryInitializeEXT(rs_q, rs_as, ") + kQueryArgs + ");");
  out.close();
}

std::string traceCall(const StageContext& ctx, const std::string& tlas, uint32_t location) {
  if (ctx.c.pipeline.tlas_function)
    return traceFunction(location) + "(" + tlas + ", " + kTraceArgs + ");";
  return "traceRayEXT(" + tlas + ", " + kTraceArgs + ", " + std::to_string(location) + ");";
}

std::string hitObjectTraceCall(const std::string& tlas, uint32_t location) {
  return "hitObjectTraceRayNV(rs_hit_object, " + tlas + ", " + kTraceArgs + ", " +
         std::to_string(location) + ");";
}

std::string queryInitCall(const StageContext& ctx, const std::string& query,
                          const std::string& tlas) {
  const std::string args = query + ", " + tlas + ", " + kQueryArgs + ");";
  return (ctx.c.pipeline.tlas_function ? "rs_query_through(" : "rayQueryInitializeEXT(") + args;
}

}  // namespace rayspec
