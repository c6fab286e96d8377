#include "glsl/emit_compute.h"

#include <string>

#include "glsl/glsl_literal.h"

namespace rayspec {

std::array<uint32_t, 3> computeGroups(const std::array<uint32_t, 3>& launch) {
  const uint64_t invocations = uint64_t{launch[0]} * launch[1] * launch[2];
  if (invocations == 0) return {0, 0, 0};
  const uint64_t groups = (invocations + kComputeGroupSize - 1) / kComputeGroupSize;
  const uint64_t x = groups < kComputeMaxGroupsX ? groups : kComputeMaxGroupsX;
  return {static_cast<uint32_t>(x), static_cast<uint32_t>((groups + x - 1) / x), 1};
}

void emitComputeLaunch(const StageContext& raygen, GlslWriter& out) {
  const std::array<uint32_t, 3> size = raygen.c.rays.launchSize();
  out.line("layout(local_size_x = " + std::to_string(kComputeGroupSize) + ") in;");
  out.line("// The launch this dispatch stands for (glsl/emit_compute.h).");
  out.line("const uvec3 rs_launch_size = uvec3(" + glslUint(size[0]) + ", " + glslUint(size[1]) +
           ", " + glslUint(size[2]) + ");");
  out.line("uvec3 rs_launch_id;");
  out.line("#define RS_LAUNCH_ID rs_launch_id");
  out.line("#define RS_LAUNCH_SIZE rs_launch_size");
}

void emitComputeShaderRecord(const StageContext& raygen, GlslWriter& out) {
  if (!raygen.uses.shader_record) return;
  const std::vector<uint32_t>& data = raygen.c.pipeline.raygen_data;
  const uint32_t words = std::max<uint32_t>(raygen.c.pipeline.sbt_record_data / 4, 1);
  std::string table = "const uint kRsRaygenRecord[" + std::to_string(words) + "] = uint[](";
  for (uint32_t w = 0; w < words; ++w)
    table += (w ? ", " : "") + glslUint(w < data.size() ? data[w] : 0u);
  out.line("// Raygen's shader record data (pipeline.raygen_data).");
  out.line(table + ");");
  out.line("uint rs_shader_record_uint(uint i) { return kRsRaygenRecord[i]; }");
  out.line("float rs_shader_record_float(uint i) { return uintBitsToFloat(kRsRaygenRecord[i]); }");
}

void emitComputeLaunchId(const StageContext& raygen, GlslWriter& out) {
  const std::array<uint32_t, 3> size = raygen.c.rays.launchSize();
  out.line("const uint rs_invocation = gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * " +
           std::string("gl_NumWorkGroups.x * ") + glslUint(kComputeGroupSize) + ";");
  out.line("if (rs_invocation >= " + glslUint(size[0] * size[1] * size[2]) + ") return;");
  out.line("rs_launch_id = uvec3(rs_invocation % " + glslUint(size[0]) + ", rs_invocation / " +
           glslUint(size[0]) + " % " + glslUint(size[1]) + ", rs_invocation / " +
           glslUint(size[0] * size[1]) + ");");
}

}  // namespace rayspec
