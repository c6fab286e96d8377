// How a driver that confuses a vertex format reads it (the planted fault
// vertex-format-misread and its model side, vertex-format-confused): the
// format it is told, the packed word with R and B swapped, and the
// positions it traces.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "case/vertex_format_misread.h"

namespace rayspec {
namespace {

TEST(VertexFormatMisread, EveryFormatButFloat3IsConfusedWithOneNoLarger) {
  EXPECT_FALSE(vertexFormatMisread(VertexFormat::Float3));
  for (VertexFormat f : enumValues<VertexFormat>()) {
    const std::optional<VertexFormatMisread> m = vertexFormatMisread(f);
    if (f == VertexFormat::Float3) continue;
    ASSERT_TRUE(m) << vertexFormatName(f);
    EXPECT_LE(vertexStride(m->format), vertexStride(f)) << vertexFormatName(f);
    EXPECT_TRUE(m->format != f || m->swap_red_blue) << vertexFormatName(f);
  }
  EXPECT_EQ(vertexFormatMisread(VertexFormat::Unorm8x4)->format, VertexFormat::Snorm8x4);
  EXPECT_EQ(vertexFormatMisread(VertexFormat::Snorm16x2)->format, VertexFormat::Unorm16x2);
}

TEST(VertexFormatMisread, PackedWordHasRedAndBlueExchanged) {
  std::vector<uint8_t> bytes = encodeVertices(VertexFormat::Unorm10x3, {{1.0f, 0.5f, 0.25f}});
  misreadBytes(*vertexFormatMisread(VertexFormat::Unorm10x3), bytes);
  uint32_t word = 0;
  std::memcpy(&word, bytes.data(), 4);
  EXPECT_EQ(word & 0x3FF, 256u);
  EXPECT_EQ((word >> 10) & 0x3FF, 512u);
  EXPECT_EQ((word >> 20) & 0x3FF, 1023u);
  EXPECT_EQ(word >> 30, 3u);
}

TEST(VertexFormatMisread, TracedPositionsAreTheConfusedFormatsReading) {
  // unorm8 read as snorm8: 0.5 (code 128) wraps to -128, which stands for -1.
  const std::vector<Vec3> unorm =
      misreadVertices(VertexFormat::Unorm8x2, {{0.5f, 0.2f, 0.0f}, {1.0f, 0.0f, 0.0f}});
  EXPECT_EQ(unorm[0][0], -1.0f);
  EXPECT_EQ(unorm[0][1], 51.0f / 127.0f);
  EXPECT_EQ(unorm[1][0], -1.0f / 127.0f);  // 255: -1
  // snorm8 read as unorm8: -1 (code -127 = 0x81) as 129 / 255.
  EXPECT_EQ(misreadVertices(VertexFormat::Snorm8x2, {{-1.0f, 0.0f, 0.0f}})[0][0], 129.0f / 255.0f);
  // float4 read as float3 at 12 bytes: the second vertex begins at the first's w.
  const std::vector<Vec3> f4 =
      misreadVertices(VertexFormat::Float4, {{1.0f, 2.0f, 3.0f}, {4.0f, 5.0f, 6.0f}});
  EXPECT_EQ(f4[0], (Vec3{1.0f, 2.0f, 3.0f}));
  EXPECT_EQ(f4[1], (Vec3{1.0f, 4.0f, 5.0f}));
  const std::vector<Vec3> packed = misreadVertices(VertexFormat::Unorm10x3, {{1.0f, 0.5f, 0.0f}});
  EXPECT_EQ(packed[0], (Vec3{0.0f, 512.0f / 1023.0f, 1.0f}));
  const std::vector<Vec3> right = {{0.25f, -3.0f, 7.0f}};
  EXPECT_EQ(misreadVertices(VertexFormat::Float3, right), right);
}

}  // namespace
}  // namespace rayspec
