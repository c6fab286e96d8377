#include "case/vertex_format_misread.h"

#include <cstring>

namespace rayspec {

std::optional<VertexFormatMisread> vertexFormatMisread(VertexFormat f) {
  using F = VertexFormat;
  switch (f) {
    case F::Float2:
      return VertexFormatMisread{F::Half4};
    case F::Half4:
      return VertexFormatMisread{F::Float2};
    case F::Half2:
      return VertexFormatMisread{F::Unorm16x2};
    case F::Float4:
      return VertexFormatMisread{F::Float3};
    case F::Half3:
      return VertexFormatMisread{F::Half2};
    case F::Unorm16x4:
      return VertexFormatMisread{F::Snorm16x4};
    case F::Unorm16x2:
      return VertexFormatMisread{F::Snorm16x2};
    case F::Snorm16x4:
      return VertexFormatMisread{F::Unorm16x4};
    case F::Snorm16x2:
      return VertexFormatMisread{F::Unorm16x2};
    case F::Unorm8x4:
      return VertexFormatMisread{F::Snorm8x4};
    case F::Unorm8x2:
      return VertexFormatMisread{F::Snorm8x2};
    case F::Snorm8x4:
      return VertexFormatMisread{F::Unorm8x4};
    case F::Snorm8x2:
      return VertexFormatMisread{F::Unorm8x2};
    case F::Snorm16x3:
      return VertexFormatMisread{F::Snorm16x2};
    case F::Unorm10x3:
      return VertexFormatMisread{F::Unorm10x3, true};
    case F::Float3:  // no other format has its 12 bytes
      break;
  }
  return std::nullopt;
}

void misreadBytes(const VertexFormatMisread& m, std::vector<uint8_t>& bytes) {
  if (!m.swap_red_blue) return;
  for (size_t at = 0; at + 4 <= bytes.size(); at += 4) {
    uint32_t w = 0;
    std::memcpy(&w, bytes.data() + at, 4);
    const uint32_t red = w & 0x3FF, blue = (w >> 20) & 0x3FF;
    w = (w & ~0x3FF003FFu) | (red << 20) | blue;
    std::memcpy(bytes.data() + at, &w, 4);
  }
}

uint32_t misreadStride(VertexFormat f, const VertexFormatMisread& m, uint32_t stride) {
  return vertexStride(m.format) < vertexStride(f) ? vertexStride(m.format) : stride;
}

std::vector<Vec3> misreadVertices(VertexFormat f, const std::vector<Vec3>& vertices) {
  const std::optional<VertexFormatMisread> m = vertexFormatMisread(f);
  if (!m) return vertices;
  std::vector<uint8_t> bytes = encodeVertices(f, vertices);
  misreadBytes(*m, bytes);
  return decodeVertices(m->format, bytes, misreadStride(f, *m, vertexStride(f)), vertices.size());
}

}  // namespace rayspec
