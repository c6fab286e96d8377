// The data sections of an exported C file (internal to export/): each the
// C definitions the player (harness/export/player/) reads, from what the Vulkan engine
// computes for the case (scene_section.cpp, pipeline_section.cpp) and what
// the model expects (expectations_section.cpp).
#pragma once

#include <string>

#include "base/result.h"
#include "case/case.h"
#include "plan/plan.h"
#include "results/results.h"
#include "vulkan/pipeline.h"
#include "vulkan/vk_fault_hook.h"

namespace rayspec {

// RS_BLAS_COUNT, rs_geometries, rs_blases, rs_instances, RS_BUILD_FLAGS;
// the geometries laid out as the builds lay them out under `layout`.
std::string sceneSection(const Scene& scene, LayoutFault layout);
// The SPIR-V of every stage (its GLSL in comments), rs_shaders, rs_groups,
// the SBT records, RS_MAX_RECURSION, what the stages need of the device
// (RS_NEEDS_*); raygen alone as a compute shader and its dispatch
// (RS_COMPUTE*) where the case runs it so (Pipeline::from_compute).
std::string pipelineSection(const Case& c, const Plan& plan, const GeneratedPipeline& generated,
                            const CompiledPipeline& compiled);
// rs_rays, the launch size, rs_bindings; the NotSupported error for a
// binding the player does not back.
Result<std::string> launchSection(const Case& c, const Plan& plan,
                                  const CompiledPipeline& compiled);
// rs_images, each with the model's texels; RS_IMAGE_* (the launch's extent,
// the first image binding, the count).
std::string imagesSection(const Case& c, const Plan& plan, const Results& model);
// rs_expected, rs_fields, rs_undefined, the ambiguous rays' replays, rs_counters.
std::string expectationsSection(const Case& c, const Plan& plan, const Results& model);

}  // namespace rayspec
