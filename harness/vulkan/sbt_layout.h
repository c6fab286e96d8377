// The shader binding table layout: a pure computation (no Vulkan calls), so
// it can be unit-tested with any device's numbers.
//
// Group order in the pipeline, and so in the handle array of
// vkGetRayTracingShaderGroupHandlesKHR:
//   groups 0 .. R-1          raygens (R = 1 + other raygens); group
//                            pipeline.raygen_group is the one the raygen
//                            region's record selects
//   groups R .. R+M-1        miss shaders, in case order        (M = miss count)
//   then the H hit groups and the C callables, each in case order
// (a pipeline linked from libraries orders them otherwise: pipeline.h's
// RayTracingPipeline::group_index maps this order to its own).
//
// Every record is the group handle followed by K = pipeline.sbt_record_data
// bytes of shader record data (0..32, default 32; zero unless the case gives
// data), then the region's padding P (pipeline.sbt_padding, default 0): the
// stride of the miss, hit and callable regions is
// alignUp(handleSize + K + P, handleAlignment), so with K = P = 0 it is the
// handle size (when that is a multiple of the alignment). The raygen region
// holds one record, alignUp(handleSize + K, handleAlignment) bytes: its
// stride equals its size. Regions start at multiples of
// shaderGroupBaseAlignment in the order raygen, miss, hit, callable.
// An empty region has offset, stride and size 0 (device address 0).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/result.h"
#include "case/case.h"
#include "vulkan/vulkan_engine.h"

namespace rayspec {

constexpr uint32_t kSbtRecordDataBytes = kMaxShaderRecordDataBytes;  // at most 8 words

struct SbtLimits {
  uint32_t handle_size = 32;
  uint32_t handle_alignment = 32;
  uint32_t base_alignment = 64;
  uint32_t max_stride = 4096;  // maxShaderGroupStride
};
// A device's (its DeviceInfo's ray tracing pipeline properties).
SbtLimits sbtLimits(const DeviceInfo& d);

struct SbtRegion {
  uint64_t offset = 0, stride = 0, size = 0;  // bytes from the table start
  uint32_t count = 0;                         // records
};

struct SbtLayout {
  SbtRegion raygen, miss, hit, callable;
  uint64_t total_size = 0;  // bytes; the table's address must be base-aligned
};

// Pipeline group index of each shader / group (see the order above).
uint32_t sbtGroupCount(const Pipeline& p);
uint32_t sbtMissGroup(const Pipeline& p, uint32_t miss_index);
uint32_t sbtHitGroup(const Pipeline& p, uint32_t hit_group_index);
uint32_t sbtCallableGroup(const Pipeline& p, uint32_t callable_index);

// The records of each region: the case's list, or when it gives none, one
// record per shader / group in order (the case format's default).
std::vector<SbtRecord> sbtMissRecords(const Pipeline& p);
std::vector<SbtRecord> sbtHitRecords(const Pipeline& p);
std::vector<SbtRecord> sbtCallableRecords(const Pipeline& p);

// alignUp(handle_size + record_data + padding, handle_alignment).
uint64_t sbtStride(const SbtLimits& limits, uint32_t record_data, uint32_t padding);

SbtLayout computeSbtLayout(const SbtLimits& limits, const Pipeline& p);

// Checks the layout against the rules of vkCmdTraceRaysKHR (strides multiple of
// the handle alignment and <= maxShaderGroupStride, offsets multiple of the
// base alignment, raygen size == stride); the error names the rule.
Result<void> checkSbtLayout(const SbtLayout& layout, const SbtLimits& limits);

// The table bytes (layout.total_size): per record the handle of its group
// (handles: sbtGroupCount(p) * handle_size bytes, as the device returns them),
// then its data words; all-zero records stay zero, and so does the padding.
// An error for a group index out of range or more data words than the
// record holds (pipeline.sbt_record_data / 4).
Result<std::vector<uint8_t>> writeSbt(const SbtLayout& layout, const SbtLimits& limits,
                                      const Pipeline& p, const std::vector<uint8_t>& handles);

}  // namespace rayspec
