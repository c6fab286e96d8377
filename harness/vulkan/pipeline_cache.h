// A VkPipelineCache per driver, kept between runs: <dir>/<vendor>-<device>-
// <pipelineCacheUUID>-<driver version>.bin (ids in hex), loaded when a device is made and saved
// when it is destroyed: merged with what the file holds then (other workers
// save theirs too), under a lock on <file>.lock, and written whole under a
// temporary name, then renamed, so that no reader sees half a file. A file is input
// like any other: over 256 MiB, or with a header that is not this device's
// (vendor, device, pipelineCacheUUID), it is not given to the driver. Not
// used where each case gets a device of its own (lavapipe: Mesa's shader
// cache already keeps its pipelines, vulkan_engine.h devicePerCase).
#pragma once

#include <vulkan/vulkan.h>

#include <string>

namespace rayspec {

struct VulkanContext;

// Process-wide, set before the first device ("" : no pipeline cache).
void setPipelineCacheDir(const std::string& dir);

// A pipeline cache holding what the file had (if any); VK_NULL_HANDLE when
// no folder is set or the driver refuses one.
VkPipelineCache openPipelineCache(const VulkanContext& ctx);
// Saves and destroys it (nothing when VK_NULL_HANDLE).
void closePipelineCache(const VulkanContext& ctx, VkPipelineCache cache);

}  // namespace rayspec
