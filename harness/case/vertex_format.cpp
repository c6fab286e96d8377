#include "case/vertex_format.h"

#include <cmath>
#include <cstring>

namespace rayspec {
namespace {

struct FormatInfo {
  VertexFormat format;
  const char* name;
  uint32_t components, stride;
};

const FormatInfo kFormats[] = {
    {VertexFormat::Float3, "float3", 3, 12},      {VertexFormat::Float2, "float2", 2, 8},
    {VertexFormat::Half4, "half4", 3, 8},         {VertexFormat::Half2, "half2", 2, 4},
    {VertexFormat::Snorm16x4, "snorm16x4", 3, 8}, {VertexFormat::Snorm16x2, "snorm16x2", 2, 4},
};

const FormatInfo& info(VertexFormat f) {
  for (const FormatInfo& i : kFormats)
    if (i.format == f) return i;
  return kFormats[0];
}

bool isHalf(VertexFormat f) {
  return f == VertexFormat::Half4 || f == VertexFormat::Half2;
}
bool isSnorm(VertexFormat f) {
  return f == VertexFormat::Snorm16x4 || f == VertexFormat::Snorm16x2;
}

constexpr float kHalfMax = 65504.0f;

int16_t snormBits(float v) {
  return static_cast<int16_t>(std::lround(v * 32767.0f));
}

}  // namespace

const char* vertexFormatName(VertexFormat f) {
  return info(f).name;
}

std::optional<VertexFormat> vertexFormatFromName(const std::string& name) {
  for (const FormatInfo& i : kFormats)
    if (name == i.name) return i.format;
  return std::nullopt;
}

const std::string& vertexFormatNames() {
  static const std::string names = [] {
    std::string s;
    for (const FormatInfo& i : kFormats) s += (s.empty() ? "" : ", ") + std::string(i.name);
    return s;
  }();
  return names;
}

uint32_t vertexComponents(VertexFormat f) {
  return info(f).components;
}
uint32_t vertexStride(VertexFormat f) {
  return info(f).stride;
}

std::string vertexFormatProblem(VertexFormat f, const Vec3& v) {
  if (vertexComponents(f) == 2 && v[2] != 0.0f)
    return std::string(vertexFormatName(f)) + " stores x and y only: z must be 0";
  for (uint32_t k = 0; k < vertexComponents(f); ++k) {
    if (std::isnan(v[k])) {  // half keeps a NaN (an inactive triangle), snorm cannot
      if (isSnorm(f)) return std::string(vertexFormatName(f)) + " cannot store NaN";
      continue;
    }
    if (isSnorm(f) && !(v[k] >= -1.0f && v[k] <= 1.0f))
      return std::string(vertexFormatName(f)) + " stores -1 to 1 only";
    if (isHalf(f) && std::isfinite(v[k]) && std::fabs(v[k]) > kHalfMax)
      return std::string(vertexFormatName(f)) + " stores at most 65504 in magnitude";
  }
  return "";
}

Vec3 storedVertex(VertexFormat f, const Vec3& v) {
  Vec3 out{0.0f, 0.0f, 0.0f};
  for (uint32_t k = 0; k < vertexComponents(f); ++k) {
    if (isHalf(f))
      out[k] = static_cast<float>(static_cast<_Float16>(v[k]));
    else if (isSnorm(f))
      out[k] = std::max(snormBits(v[k]) / 32767.0f, -1.0f);
    else
      out[k] = v[k];
  }
  return out;
}

std::vector<uint8_t> encodeVertices(VertexFormat f, const std::vector<Vec3>& vertices) {
  const uint32_t stride = vertexStride(f);
  std::vector<uint8_t> bytes(vertices.size() * stride, 0);
  for (size_t i = 0; i < vertices.size(); ++i) {
    uint8_t* at = bytes.data() + i * stride;
    const Vec3& v = vertices[i];
    for (uint32_t k = 0; k < stride / (isHalf(f) || isSnorm(f) ? 2 : 4); ++k) {
      const bool w = k == 3;  // the fourth component of half4 / snorm16x4: 1
      if (isHalf(f)) {
        const _Float16 h = static_cast<_Float16>(w ? 1.0f : v[k]);
        std::memcpy(at + 2 * k, &h, 2);
      } else if (isSnorm(f)) {
        const int16_t s = w ? int16_t(32767) : snormBits(v[k]);
        std::memcpy(at + 2 * k, &s, 2);
      } else {
        std::memcpy(at + 4 * k, &v[k], 4);
      }
    }
  }
  return bytes;
}

}  // namespace rayspec
