// Vertex formats of triangle geometry (triangles.vertex_format, R-VERTEX-FORMAT):
// how positions are stored in the vertex buffer, and the float position each
// stored value stands for, which is what the model traces. A format with two
// components has z = 0; a fourth component (w, alpha) is written as 1 and
// never read by a build.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "base/enum_names.h"
#include "base/vec3.h"

namespace rayspec {

// How a component is stored. Normalized codes stand for, per the Vulkan
// specification's "Fixed-Point Data Conversions", unorm: c / (2^b - 1) and
// snorm: max(c / (2^(b-1) - 1), -1).
enum class VertexEncoding {
  Float,    // IEEE binary32
  Half,     // IEEE binary16
  Snorm,    // two's complement b-bit code
  Unorm,    // unsigned b-bit code
  Packed10  // three unsigned 10-bit codes, R in bits 0..9, G 10..19, B 20..29, A (2 bits) 30..31
};

// One row per format, the one place each fact about it is written:
//   X(Enumerator, "name", VkFormat without VK_FORMAT_, encoding, bits per
//     component, components a build reads (2 or 3), bytes of one vertex)
// The VkFormat column is a bare token, pasted by the Vulkan side alone
// (vulkan/acceleration_structure.cpp), so this layer needs no Vulkan header.
#define RAYSPEC_VERTEX_FORMATS(X)                                         \
  X(Float3, "float3", R32G32B32_SFLOAT, Float, 32, 3, 12) /* default */   \
  X(Float2, "float2", R32G32_SFLOAT, Float, 32, 2, 8)                     \
  X(Half4, "half4", R16G16B16A16_SFLOAT, Half, 16, 3, 8)                  \
  X(Half2, "half2", R16G16_SFLOAT, Half, 16, 2, 4)                        \
  X(Snorm16x4, "snorm16x4", R16G16B16A16_SNORM, Snorm, 16, 3, 8)          \
  X(Snorm16x2, "snorm16x2", R16G16_SNORM, Snorm, 16, 2, 4)                \
  X(Float4, "float4", R32G32B32A32_SFLOAT, Float, 32, 3, 16)              \
  X(Half3, "half3", R16G16B16_SFLOAT, Half, 16, 3, 6)                     \
  X(Unorm16x4, "unorm16x4", R16G16B16A16_UNORM, Unorm, 16, 3, 8)          \
  X(Unorm16x2, "unorm16x2", R16G16_UNORM, Unorm, 16, 2, 4)                \
  X(Snorm8x4, "snorm8x4", R8G8B8A8_SNORM, Snorm, 8, 3, 4)                 \
  X(Snorm8x2, "snorm8x2", R8G8_SNORM, Snorm, 8, 2, 2)                     \
  X(Unorm8x4, "unorm8x4", R8G8B8A8_UNORM, Unorm, 8, 3, 4)                 \
  X(Unorm8x2, "unorm8x2", R8G8_UNORM, Unorm, 8, 2, 2)                     \
  X(Unorm10x3, "unorm10x3", A2B10G10R10_UNORM_PACK32, Packed10, 10, 3, 4) \
  X(Snorm16x3, "snorm16x3", R16G16B16_SNORM, Snorm, 16, 3, 6)
enum class VertexFormat { RAYSPEC_VERTEX_FORMATS(RAYSPEC_ENUMERATOR) };
RAYSPEC_ENUM_NAMES(VertexFormat, RAYSPEC_VERTEX_FORMATS);

const char* vertexFormatName(VertexFormat f);  // float3, float2, half4, ...
std::optional<VertexFormat> vertexFormatFromName(const std::string& name);
const std::string& vertexFormatNames();  // "float3, float2, ..." for messages

VertexEncoding vertexEncoding(VertexFormat f);
uint32_t vertexComponentBits(VertexFormat f);   // 32, 16, 10 or 8
uint32_t vertexComponents(VertexFormat f);      // 2 or 3 positions used (x4 formats: 3)
uint32_t vertexStride(VertexFormat f);          // bytes of one vertex
uint32_t vertexComponentBytes(VertexFormat f);  // the unit a stride is a multiple of
                                                // (packed: the whole 4-byte word)
bool vertexNormalized(VertexFormat f);          // snorm, unorm or packed unorm codes

// The largest code of a normalized format: 2^b - 1 (unorm), 2^(b-1) - 1
// (snorm); 0 for float and half.
uint32_t vertexMaxCode(VertexFormat f);

// Why `v` cannot be stored in `f` (empty when it can): a z other than 0 in a
// two-component format, a value outside -1..1 (snorm) or 0..1 (unorm) or NaN
// in a normalized format, a finite value beyond the half range.
std::string vertexFormatProblem(VertexFormat f, const Vec3& v);

// The code a normalized format stores for v (the nearest one); v as the
// format allows (vertexFormatProblem empty).
int32_t vertexCode(VertexFormat f, float v);
// The value a normalized code stands for, rounded to float once.
float vertexCodeValue(VertexFormat f, int32_t code);

// The position the stored value stands for: v rounded to the format (half:
// to nearest even; normalized: the nearest code's value, vertexCodeValue).
Vec3 storedVertex(VertexFormat f, const Vec3& v);

// How far, per component, a device's decoded position may lie from
// storedVertex: 0 for float and half (exact in float); for normalized codes
// the quotient c / (2^b - 1) is not a float, and a device may compute it
// another way (a reciprocal multiply, a fused multiply-add) with a result a
// few units in the last place from the model's correctly rounded one.
float vertexDecodeError(VertexFormat f);

// The vertex buffer bytes of `vertices` in `f` (each stored as storedVertex).
std::vector<uint8_t> encodeVertices(VertexFormat f, const std::vector<Vec3>& vertices);

// The positions `count` vertices of `f` stand for, vertex i at byte
// i * stride of `bytes` (as a build reads them; a vertex past the end of
// `bytes`: NaN). decodeVertices(f, encodeVertices(f, v), vertexStride(f),
// v.size()) is storedVertex of each.
std::vector<Vec3> decodeVertices(VertexFormat f, const std::vector<uint8_t>& bytes, size_t stride,
                                 size_t count);

}  // namespace rayspec
