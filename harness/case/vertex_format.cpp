#include "case/vertex_format.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace rayspec {
namespace {

struct FormatInfo {
  VertexEncoding encoding;
  uint32_t bits, components, stride;
};

#define RAYSPEC_VERTEX_FORMAT_INFO(id, name, vk, encoding, bits, components, stride) \
  FormatInfo{VertexEncoding::encoding, bits, components, stride},
constexpr FormatInfo kFormats[] = {RAYSPEC_VERTEX_FORMATS(RAYSPEC_VERTEX_FORMAT_INFO)};
#undef RAYSPEC_VERTEX_FORMAT_INFO

const FormatInfo& info(VertexFormat f) {
  const size_t i = static_cast<size_t>(f);
  return kFormats[i < std::size(kFormats) ? i : 0];
}

constexpr float kHalfMax = 65504.0f;

// Four units of 2^-24: a device's quotient (c * fl(1 / M), or a division
// refined by a fused multiply-add) is within two units in the last place of
// the exact c / M, and the model's within half of one; a unit of a value in
// -1..1 is at most 2^-24 (1 itself is exact, its neighbour below 2^-24 away).
constexpr float kNormalizedDecodeError = 0x1p-22f;

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

// The little-endian bytes of the low `bytes` bytes of `code` (two's
// complement for a negative snorm code).
void putCode(uint8_t* at, int32_t code, uint32_t bytes) {
  const uint32_t bits = static_cast<uint32_t>(code);
  for (uint32_t b = 0; b < bytes; ++b) at[b] = static_cast<uint8_t>(bits >> (8 * b));
}

// One vertex of `f` at `at`: its used components, then w (or alpha) as 1.
void encodeVertex(VertexFormat f, const Vec3& v, uint8_t* at) {
  const FormatInfo& i = info(f);
  const uint32_t unit = i.bits / 8,
                 stored = i.encoding == VertexEncoding::Packed10 ? 0 : i.stride / unit;
  if (i.encoding == VertexEncoding::Packed10) {
    uint32_t word = 3u << 30;  // alpha: its largest code, 1
    for (uint32_t k = 0; k < 3; ++k) word |= static_cast<uint32_t>(vertexCode(f, v[k])) << (10 * k);
    putCode(at, static_cast<int32_t>(word), 4);
    return;
  }
  for (uint32_t k = 0; k < stored; ++k) {
    const float x = k < i.components ? v[k] : k == 3 ? 1.0f : 0.0f;
    if (i.encoding == VertexEncoding::Float) {
      std::memcpy(at + 4 * k, &x, 4);
    } else if (i.encoding == VertexEncoding::Half) {
      const uint16_t h = halfBits(x);
      std::memcpy(at + 2 * k, &h, 2);
    } else {
      putCode(at + unit * k, vertexCode(f, x), unit);
    }
  }
}

// The code of `bytes` little-endian bytes at `at`, sign-extended for snorm.
int32_t getCode(const uint8_t* at, uint32_t bytes, bool sign) {
  uint32_t bits = 0;
  for (uint32_t b = 0; b < bytes; ++b) bits |= uint32_t{at[b]} << (8 * b);
  const uint32_t top = 1u << (8 * bytes - 1);
  if (sign && bytes < 4 && (bits & top)) bits |= ~((top << 1) - 1);
  return static_cast<int32_t>(bits);
}

// The position one vertex of `f` at `at` stands for.
Vec3 decodeVertex(VertexFormat f, const uint8_t* at) {
  const FormatInfo& i = info(f);
  Vec3 out{0.0f, 0.0f, 0.0f};
  for (uint32_t k = 0; k < i.components; ++k) {
    if (i.encoding == VertexEncoding::Float) {
      std::memcpy(&out[k], at + 4 * k, 4);
    } else if (i.encoding == VertexEncoding::Half) {
      out[k] = halfValue(static_cast<uint16_t>(getCode(at + 2 * k, 2, false)));
    } else if (i.encoding == VertexEncoding::Packed10) {
      const uint32_t word = static_cast<uint32_t>(getCode(at, 4, false));
      out[k] = vertexCodeValue(f, static_cast<int32_t>((word >> (10 * k)) & 0x3FF));
    } else {
      const uint32_t unit = i.bits / 8;
      out[k] =
          vertexCodeValue(f, getCode(at + unit * k, unit, i.encoding == VertexEncoding::Snorm));
    }
  }
  return out;
}

}  // namespace

const char* vertexFormatName(VertexFormat f) {
  return nameOf(f);
}

std::optional<VertexFormat> vertexFormatFromName(const std::string& name) {
  return valueNamed<VertexFormat>(name);
}

const std::string& vertexFormatNames() {
  static const std::string names = namesJoined(enumNames<VertexFormat>());
  return names;
}

VertexEncoding vertexEncoding(VertexFormat f) {
  return info(f).encoding;
}
uint32_t vertexComponentBits(VertexFormat f) {
  return info(f).bits;
}
uint32_t vertexComponents(VertexFormat f) {
  return info(f).components;
}
uint32_t vertexStride(VertexFormat f) {
  return info(f).stride;
}
uint32_t vertexComponentBytes(VertexFormat f) {
  return info(f).encoding == VertexEncoding::Packed10 ? info(f).stride : info(f).bits / 8;
}
bool vertexNormalized(VertexFormat f) {
  const VertexEncoding e = info(f).encoding;
  return e == VertexEncoding::Snorm || e == VertexEncoding::Unorm || e == VertexEncoding::Packed10;
}

uint32_t vertexMaxCode(VertexFormat f) {
  if (!vertexNormalized(f)) return 0;
  const uint32_t bits = info(f).encoding == VertexEncoding::Snorm ? info(f).bits - 1 : info(f).bits;
  return (1u << bits) - 1;
}

std::string vertexFormatProblem(VertexFormat f, const Vec3& v) {
  const std::string name = vertexFormatName(f);
  if (vertexComponents(f) == 2 && v[2] != 0.0f) return name + " stores x and y only: z must be 0";
  const VertexEncoding e = vertexEncoding(f);
  for (uint32_t k = 0; k < vertexComponents(f); ++k) {
    if (std::isnan(v[k])) {  // float and half keep a NaN (an inactive triangle), codes cannot
      if (vertexNormalized(f)) return name + " cannot store NaN";
      continue;
    }
    if (e == VertexEncoding::Snorm && !(v[k] >= -1.0f && v[k] <= 1.0f))
      return name + " stores -1 to 1 only";
    if ((e == VertexEncoding::Unorm || e == VertexEncoding::Packed10) &&
        !(v[k] >= 0.0f && v[k] <= 1.0f))
      return name + " stores 0 to 1 only";
    if (e == VertexEncoding::Half && std::isfinite(v[k]) && std::fabs(v[k]) > kHalfMax)
      return name + " stores at most 65504 in magnitude";
  }
  return "";
}

int32_t vertexCode(VertexFormat f, float v) {
  // In double: v * M is exact there, so the nearest code is never decided by
  // a rounding of the product.
  return static_cast<int32_t>(std::lround(static_cast<double>(v) * vertexMaxCode(f)));
}

float vertexCodeValue(VertexFormat f, int32_t code) {
  const float value = static_cast<float>(code) / static_cast<float>(vertexMaxCode(f));
  return std::max(value, -1.0f);  // snorm's most negative code stands for -1 too
}

Vec3 storedVertex(VertexFormat f, const Vec3& v) {
  Vec3 out{0.0f, 0.0f, 0.0f};
  for (uint32_t k = 0; k < vertexComponents(f); ++k) {
    if (vertexEncoding(f) == VertexEncoding::Half)
      out[k] = halfValue(halfBits(v[k]));
    else if (vertexNormalized(f))
      out[k] = vertexCodeValue(f, vertexCode(f, v[k]));
    else
      out[k] = v[k];
  }
  return out;
}

float vertexDecodeError(VertexFormat f) {
  return vertexNormalized(f) ? kNormalizedDecodeError : 0.0f;
}

std::vector<uint8_t> encodeVertices(VertexFormat f, const std::vector<Vec3>& vertices) {
  const uint32_t stride = vertexStride(f);
  std::vector<uint8_t> bytes(vertices.size() * stride, 0);
  for (size_t i = 0; i < vertices.size(); ++i)
    encodeVertex(f, vertices[i], bytes.data() + i * stride);
  return bytes;
}

std::vector<Vec3> decodeVertices(VertexFormat f, const std::vector<uint8_t>& bytes, size_t stride,
                                 size_t count) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<Vec3> out(count, Vec3{nan, nan, nan});
  for (size_t i = 0; i < count; ++i)
    if (i * stride + vertexStride(f) <= bytes.size())
      out[i] = decodeVertex(f, bytes.data() + i * stride);
  return out;
}

}  // namespace rayspec
