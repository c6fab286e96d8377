#include "case/vertex_format.h"

#include <cmath>
#include <cstring>
#include <limits>

#include "base/enum_names.h"

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

// IEEE 754 binary16 bits of f, rounded to nearest even (overflow: infinity).
// Written out because not every compiler here has _Float16 on x86.
uint16_t halfBits(float f) {
  uint32_t x = 0;
  std::memcpy(&x, &f, 4);
  const uint32_t sign = (x >> 16) & 0x8000, exp = (x >> 23) & 0xFF;
  uint32_t mant = x & 0x7FFFFF;
  if (exp == 0xFF) return static_cast<uint16_t>(sign | 0x7C00 | (mant ? 0x200 : 0));
  const int e = int(exp) - 127 + 15;
  if (e >= 0x1F) return static_cast<uint16_t>(sign | 0x7C00);
  uint32_t shift = 13, base = uint32_t(e) << 10;
  if (e <= 0) {  // a subnormal half: h x 2^-24
    if (e < -10) return static_cast<uint16_t>(sign);
    mant |= 0x800000;
    shift = uint32_t(14 - e);
    base = 0;
  }
  uint32_t half = base | (mant >> shift);
  const uint32_t rest = mant & ((1u << shift) - 1), halfway = 1u << (shift - 1);
  if (rest > halfway || (rest == halfway && (half & 1))) ++half;  // a carry is still right
  return static_cast<uint16_t>(sign | half);
}

float halfValue(uint16_t h) {
  const uint32_t exp = (h >> 10) & 0x1F, mant = h & 0x3FF;
  float f = 0.0f;
  if (exp == 0)
    f = std::ldexp(static_cast<float>(mant), -24);
  else if (exp == 0x1F)
    f = mant ? std::numeric_limits<float>::quiet_NaN() : std::numeric_limits<float>::infinity();
  else
    f = std::ldexp(static_cast<float>(mant | 0x400), int(exp) - 25);
  return (h & 0x8000) ? -f : f;
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
  static const std::string names = namesJoined(kFormats);
  return names;
}

uint32_t vertexComponents(VertexFormat f) {
  return info(f).components;
}
uint32_t vertexStride(VertexFormat f) {
  return info(f).stride;
}
uint32_t vertexComponentBytes(VertexFormat f) {
  return isHalf(f) || isSnorm(f) ? 2 : 4;
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
      out[k] = halfValue(halfBits(v[k]));
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
        const uint16_t h = halfBits(w ? 1.0f : v[k]);
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
