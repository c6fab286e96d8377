// How a driver that confuses a vertex format reads it: the planted fault
// vertex-format-misread, on both sides of the seam. The Vulkan side tells
// the builds the confused format over the same bytes (vulkan/build_layout.h,
// a layout fault of vulkan/vk_fault_hook.h); the model side traces the
// positions such a build would (fault/mutate_structures.cpp), so that the
// claims of R-VERTEX-FORMAT are proven without a device. Nothing else reads
// it.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "case/vertex_format.h"

namespace rayspec {

// Unorm codes are read as snorm and snorm as unorm of the same width; float2
// as half4 and back, half2 as unorm16x2 (the same bytes a vertex); float4 as
// float3, half3 as half2 and snorm16x3 as snorm16x2, at that format's vertex size (each vertex
// after the first begins inside an earlier one); unorm10x3 with its R and B fields swapped. float3:
// nullopt, read right (no other format has its size).
struct VertexFormatMisread {
  VertexFormat format;         // the format the build is told
  bool swap_red_blue = false;  // the packed word's bits 0..9 and 20..29 exchanged
};
std::optional<VertexFormatMisread> vertexFormatMisread(VertexFormat f);

// The vertex bytes as the confused build is given them: each packed word's R
// and B fields exchanged where m says so, else unchanged.
void misreadBytes(const VertexFormatMisread& m, std::vector<uint8_t>& bytes);

// The stride the confused build steps by: the confused format's own vertex
// size where it is smaller than the real one, else `stride`.
uint32_t misreadStride(VertexFormat f, const VertexFormatMisread& m, uint32_t stride);

// The positions a build that misreads f traces for `vertices` (as f stores
// them, tightly packed); `vertices` themselves where f is read right.
std::vector<Vec3> misreadVertices(VertexFormat f, const std::vector<Vec3>& vertices);

}  // namespace rayspec
