// pipeline.layout: empty (R-EMPTY-LAYOUT; glsl/bindings.h): no descriptor
// set. The case's buffers and its top level are reached through their
// device addresses, listed in a table whose own address every shader of the
// pipeline gets as two specialization constants.
#pragma once

#include <vulkan/vulkan.h>

#include <vector>

#include "vulkan/cleanup.h"
#include "vulkan/context.h"
#include "vulkan/descriptors.h"
#include "vulkan/pipeline.h"

namespace rayspec {

// A host buffer of one uint64 a binding (0 up to the largest item's): the
// device address of each item's buffer, or of its one top level. Storage
// images have no address: an error (the parser refuses them first).
Result<VkDeviceAddress> createAddressTable(const VulkanContext& ctx,
                                           const std::vector<DescriptorItem>& items,
                                           Cleanup& cleanup);

// Every shader of `compiled` given the table's address (kTableLowConstantId,
// kTableHighConstantId) beside its own specialization constants.
void specializeTableAddress(CompiledPipeline& compiled, VkDeviceAddress table);

}  // namespace rayspec
