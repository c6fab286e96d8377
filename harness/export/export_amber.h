// `rayspec export CASE --format amber`: the case as an Amber script in the
// subset of AmberScript the Khronos CTS's ray tracing scripts use
// (external/vulkancts/data/vulkan/amber/ray_tracing/*.amber): SHADER ...
// SPIRV-HEX, ACCELERATION_STRUCTURE BOTTOM_LEVEL (GEOMETRY TRIANGLES / AABBS)
// and TOP_LEVEL (BOTTOM_LEVEL_INSTANCE), BUFFER, PIPELINE raytracing
// (SHADER_GROUP, SHADER_BINDING_TABLE, BIND), RUN ... RAYGEN, EXPECT. Design:
//
//  - The same facts as the C export (export_c.h), from the same functions:
//    the GLSL and its SPIR-V (compilePipeline; the GLSL in comments), the
//    build inputs as the builds lay them out (layTriangles, layAabbs), the
//    instances, the SBT records (sbt_layout.h), the rays (packRays), the
//    scene data (packSceneData), the bindings (caseBindings). One
//    difference: the record words are bound as a storage buffer
//    (Plan::records_bound, shaders/common.glsl RS_RECORDS_BOUND), since a
//    script cannot hand a shader a buffer's address.
//  - The expectations are the judge's where an EXPECT can hold them: each
//    judged ray's written mask and each field it compares (integers EQ,
//    floats EQ within the field's tolerance on the ray, widened by its bounds:
//    compare_parts.h fieldTolerance), R-UB rays left out, each counter EQ or
//    between GE and LE (expected_values.h). The float fields are read from a
//    COPY of the record buffer declared float (Amber reads a buffer by its
//    data type, and a COPY takes the bytes as they are).
//  - Refused, the construct named: what the C export refuses, with the same
//    reason and message; then what the subset cannot express
//    (amber_support.cpp): "export: case uses X, which an Amber script cannot
//    express".
#pragma once

#include <string>

#include "base/result.h"
#include "case/case.h"
#include "plan/plan.h"
#include "results/results.h"

namespace rayspec {

// The script an export writes and how its header says to run it.
inline constexpr const char* kAmberScriptFile = "repro.amber";
inline constexpr const char* kAmberRunLine = "amber -v 1.2 repro.amber";

// The script of case c, its expectations from `model` (the model's exact
// tier run of c); NotSupported naming the construct for a case it refuses,
// the ShaderCompile error of a stage that does not compile.
Result<std::string> exportCaseAsAmber(const Case& c, const Plan& plan, const Results& model);

}  // namespace rayspec
