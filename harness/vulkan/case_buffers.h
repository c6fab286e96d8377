// The buffers and images behind the descriptor bindings of one case
// (glsl/bindings.h), and turning them back into Results after the trace.
#pragma once

#include <set>
#include <vector>

#include "case/case.h"
#include "plan/plan.h"
#include "results/results.h"
#include "vulkan/cleanup.h"
#include "vulkan/context.h"
#include "vulkan/descriptors.h"
#include "vulkan/memory.h"

namespace rayspec {

// Where a launch's images live on the device: the launch's own extent, or,
// when that is beyond maxImageDimension2D (a ray list is one row of rays),
// the launch's rays in row-major order folded into rows as wide as the
// device allows. The raygen stores ray i at (i % width, i / width)
// (shaders/common.glsl, rs_image_texel), so the texels read back in order
// are the launch's rays in order whatever the extent; launch ids are not
// touched. The NotSupported error when even folded the image does not fit.
struct ImageExtent {
  uint32_t width = 0, height = 0;
};
Result<ImageExtent> imageExtent(uint32_t launch_width, uint32_t launch_height,
                                uint32_t max_dimension);

struct CaseBuffers {
  std::set<uint32_t> bindings;  // the bindings in use
  ImageExtent image_extent;     // of every image
  Buffer rays, records, counters, scene, sbt_tables;
  Buffer records_ref;                  // bound at kBindingRecords: the device address of `records`
  std::vector<StorageImage> images;    // parallel to plan.images
  std::vector<bool> image_float;       // rgba32f (else r32ui)
  std::vector<Buffer> image_readback;  // host copies of the images
};

// The bindings the plan needs (TLAS and rays always; records when
// plan.records; counters when the plan keeps some; scene data when
// plan.scene_data; the SBT tables when plan.sbt_tables; one image each) united with those the
// shaders declare. A Device error for a declared binding nothing can back.
Result<std::set<uint32_t>> caseBindings(const Plan& plan, const std::set<uint32_t>& declared);

// Host buffers filled (rays, scene data, SBT tables) or zeroed (records, counters), and
// the storage images. Only for the bindings given. The NotSupported error
// when the rays do not fit a storage buffer, else the Device error.
Result<CaseBuffers> createCaseBuffers(const VulkanContext& ctx, const Case& c, const Plan& plan,
                                      const std::set<uint32_t>& bindings, Cleanup& cleanup);

// The descriptor items of the bindings (the TLASes, by level, at kBindingTlas).
std::vector<DescriptorItem> descriptorItems(const CaseBuffers& b,
                                            const std::vector<VkAccelerationStructureKHR>& tlases);

// records, counters (by plan.counters name) and images into r, after the
// trace finished.
void readResults(const CaseBuffers& b, const Plan& plan, uint32_t width, uint32_t height,
                 Results& r);

}  // namespace rayspec
