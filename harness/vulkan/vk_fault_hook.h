// The Vulkan side's fault-injection hooks (test only). The planted faults
// device-lost, out-of-device-memory and pipeline-refused (vulkan/
// device_errors.h) make one Vulkan call fail on purpose; they reach the
// Vulkan side through injectVkError and nothing else, and vkCall
// (vulkan/vk_check.h, with vkAnswer) is the one place that obeys it. The layout faults
// reach it through injectLayoutFault, read by vulkan/scene_builder.cpp
// (which lays its inputs out by vulkan/build_layout.h with it) and, for
// deferred-handle-early alone, vulkan/deferred_operation.cpp. A product run never sets
// either. docs/layout-and-conventions.md, "The fault seam", lists every such hook.
#pragma once

#include <vulkan/vulkan.h>

#include <optional>
#include <string>
#include <vector>

#include "base/enum_names.h"

namespace rayspec {

struct InjectedVkError {
  std::string call;  // the Vulkan function whose calls fail ("" none)
  VkResult result = VK_SUCCESS;
};

// Every later call of e.call in this process is not made and answers
// e.result, until cleared (injectVkError({})).
void injectVkError(const InjectedVkError& e);

// The answer that stands for a call of `call`; none: make the call.
std::optional<VkResult> injectedVkError(const char* call);

// The planted layout faults: the builds are given a wrong stride, offset or
// pointer order over input bytes laid out as scene.build asks
// (vulkan/build_layout.h), as a driver that misreads them would read them.
//   stride-ignored     vertexStride / AABB stride of the tightly packed data
//   offsets-ignored    primitiveOffset, firstVertex, transformOffset all 0
//   pointers-reversed  each level's instance pointers in reverse order
//   vertex-format-misread  vertices read in a confused format (unorm as
//                      snorm and back, float2 as half4 and back, float4 as
//                      float3, half3 as half2, snorm16x3 as snorm16x2,
//                      half2 as unorm16x2,
//                      unorm10x3's R and B swapped: build_layout.h)
//   build-writes-past-size  after the BLAS builds, 4 bytes of the first guard
//                      after a structure's reported size overwritten, as a
//                      build that ran past it (R-AS-MEMORY, memory_guards.h)
//   sparse-page-lost   scene.build.sparse geometry or instances: once each
//                      such buffer is filled, its second page is bound to a
//                      new allocation, zeroed, as a driver that lost that
//                      binding would show it (vulkan/sparse_buffer.h)
//   creation-clears-memory  scene.build.storage reused: each structure
//                      created over a built one zeroes its memory, as a
//                      vkCreateAccelerationStructureKHR that wrote it would
//                      (R-AS-CREATE)
// and the query faults, the answers of scene.build.queries
// (vulkan/structure_queries.h) given wrong, as a device would give them:
//   compacted-size-too-large  the compacted size 256 bytes past the size the
//                      structure was created with (R-AS-QUERY-COMPACTED)
//   structure-size-too-large  the size query likewise (R-AS-QUERY-SIZE)
//   query-availability-lost   availability read 0 after the wait
//                      (R-AS-QUERY-AVAILABILITY)
//   serialized-uuid-wrong     the serialized header's driverUUID with its
//                      first byte flipped (R-AS-SERIAL-HEADER)
//   pointer-count-off  the bottom-level pointers query one more than the
//                      header's handle count (R-AS-SERIAL-POINTERS)
// and a pipeline fault, read by vulkan/deferred_operation.cpp alone:
//   deferred-handle-early  a pipeline created through a deferred operation
//                      is taken as its output slot held it before the
//                      operation wrote it, as a harness that reads the handle
//                      before the operation completes sees it on a driver
//                      that writes it at completion (R-DEFERRED)
#define RAYSPEC_LAYOUT_FAULTS(X)                      \
  X(None, "")                          /* no fault */ \
  X(StrideIgnored, "stride-ignored")   /* tight */    \
  X(OffsetsIgnored, "offsets-ignored") /* zeros */    \
  X(PointersReversed, "pointers-reversed")            \
  X(FormatMisread, "vertex-format-misread")           \
  X(WritesPastSize, "build-writes-past-size")         \
  X(CreationClears, "creation-clears-memory")         \
  X(SparsePageLost, "sparse-page-lost")               \
  X(CompactedTooLarge, "compacted-size-too-large")    \
  X(SizeTooLarge, "structure-size-too-large")         \
  X(AvailabilityLost, "query-availability-lost")      \
  X(UuidWrong, "serialized-uuid-wrong")               \
  X(PointerCountOff, "pointer-count-off")             \
  X(DeferredHandleEarly, "deferred-handle-early")
enum class LayoutFault { RAYSPEC_LAYOUT_FAULTS(RAYSPEC_ENUMERATOR) };
RAYSPEC_ENUM_NAMES(LayoutFault, RAYSPEC_LAYOUT_FAULTS);

// Every later build in this process lays its inputs out with fault f, until
// cleared (injectLayoutFault(LayoutFault::None)).
void injectLayoutFault(LayoutFault f);
LayoutFault injectedLayoutFault();

// The layout fault named `name` (none: not one).
std::optional<LayoutFault> layoutFault(const std::string& name);
const std::vector<std::string>& layoutFaultNames();

}  // namespace rayspec
