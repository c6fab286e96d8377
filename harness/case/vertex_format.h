// Vertex formats of triangle geometry (triangles.vertex_format, R-VERTEX-FORMAT):
// how positions are stored in the vertex buffer, and the float position each
// stored value stands for, which is what the model traces. A format with two
// components has z = 0.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "base/vec3.h"

namespace rayspec {

enum class VertexFormat {
  Float3,     // VK_FORMAT_R32G32B32_SFLOAT (default)
  Float2,     // VK_FORMAT_R32G32_SFLOAT
  Half4,      // VK_FORMAT_R16G16B16A16_SFLOAT (w = 1)
  Half2,      // VK_FORMAT_R16G16_SFLOAT
  Snorm16x4,  // VK_FORMAT_R16G16B16A16_SNORM (w = 1): -1..1 in steps of 1/32767
  Snorm16x2,  // VK_FORMAT_R16G16_SNORM
};

const char* vertexFormatName(VertexFormat f);  // float3, float2, half4, half2, snorm16x4, snorm16x2
std::optional<VertexFormat> vertexFormatFromName(const std::string& name);
const std::string& vertexFormatNames();  // "float3, float2, ..." for messages

uint32_t vertexComponents(VertexFormat f);      // 2 or 3 positions used (half4/snorm16x4: 3)
uint32_t vertexStride(VertexFormat f);          // bytes of one vertex
uint32_t vertexComponentBytes(VertexFormat f);  // bytes of one component: 4 or 2

// Why `v` cannot be stored in `f` (empty when it can): a z other than 0 in a
// two-component format, a value outside -1..1 in an snorm format, a finite
// value beyond the half range.
std::string vertexFormatProblem(VertexFormat f, const Vec3& v);

// The position the stored value stands for: v rounded to the format (half:
// to nearest even; snorm: round(v * 32767) / 32767).
Vec3 storedVertex(VertexFormat f, const Vec3& v);

// The vertex buffer bytes of `vertices` in `f` (each stored as storedVertex).
std::vector<uint8_t> encodeVertices(VertexFormat f, const std::vector<Vec3>& vertices);

}  // namespace rayspec
