// The build input layouts (vulkan/build_layout.h): where the bytes of
// vertices, indices, transforms, boxes and instances lie, the strides and
// offsets the builds are given, the junk a misreading driver would read,
// and what each planted layout fault changes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "vulkan/build_layout.h"

namespace rayspec {
namespace {

constexpr uint32_t kJunkVertices = 2;

Geometry layoutTriangle(bool indexed) {
  Geometry g;
  g.vertices = {{-1, -1, 0}, {1, -1, 0}, {-1, 1, 0}};
  if (indexed) g.indices = {2, 1, 0};
  g.transform = Transform{1, 0, 0, 5, 0, 1, 0, 0, 0, 0, 1, 0};
  return g;
}

float floatAt(const std::vector<uint8_t>& bytes, size_t at) {
  float f = 0;
  std::memcpy(&f, bytes.data() + at, 4);
  return f;
}

TEST(BuildLayout, TightByDefault) {
  const TriangleInputs t = layTriangles(layoutTriangle(false), AsBuild{}, LayoutFault::None);
  EXPECT_EQ(t.stride, 12u);
  EXPECT_EQ(t.vertices.size(), 36u);
  EXPECT_EQ(t.max_vertex, 2u);
  EXPECT_EQ(t.range.primitiveCount, 1u);
  EXPECT_EQ(t.range.primitiveOffset, 0u);
  EXPECT_EQ(t.range.firstVertex, 0u);
  EXPECT_EQ(t.transform.size(), 48u);
}

// Vertex i at primitiveOffset + (firstVertex + i) * stride, NaN everywhere else.
TEST(BuildLayout, StridedVerticesAtOffsetsBehindNaN) {
  AsBuild b;
  b.data_offsets = true;
  b.first_vertex = kJunkVertices;
  b.vertex_stride = 20;
  const TriangleInputs t = layTriangles(layoutTriangle(false), b, LayoutFault::None);
  EXPECT_EQ(t.stride, 20u);
  EXPECT_EQ(t.range.primitiveOffset, kJunkOffsetBytes);
  EXPECT_EQ(t.range.firstVertex, kJunkVertices);
  EXPECT_EQ(t.max_vertex, kJunkVertices + 2);
  EXPECT_EQ(t.range.transformOffset, kJunkTransformBytes);
  const size_t v1 = kJunkOffsetBytes + (kJunkVertices + 1) * 20;
  EXPECT_EQ(floatAt(t.vertices, v1), 1.0f);
  EXPECT_EQ(floatAt(t.vertices, v1 + 4), -1.0f);
  EXPECT_TRUE(std::isnan(floatAt(t.vertices, v1 + 12))) << "padding";
  EXPECT_TRUE(std::isnan(floatAt(t.vertices, 0))) << "before the offset";
  EXPECT_TRUE(std::isnan(floatAt(t.vertices, kJunkOffsetBytes))) << "junk vertex";
  EXPECT_TRUE(std::isnan(floatAt(t.transform, 0))) << "junk matrix";
  EXPECT_EQ(floatAt(t.transform, kJunkTransformBytes + 12), 5.0f);
}

// Indexed: primitiveOffset moves the indices (behind index 0), firstVertex the vertices.
TEST(BuildLayout, IndexedOffsetsMoveTheIndices) {
  AsBuild b;
  b.data_offsets = true;
  b.first_vertex = kJunkVertices;
  const TriangleInputs t = layTriangles(layoutTriangle(true), b, LayoutFault::None);
  // No byte offset before the vertices; junk vertices before and after them
  // (a driver applying firstVertex twice reads the ones after).
  EXPECT_EQ(t.vertices.size(), (2 * kJunkVertices + 3) * 12u);
  EXPECT_TRUE(std::isnan(floatAt(t.vertices, (kJunkVertices + 3) * 12))) << "junk after the data";
  ASSERT_EQ(t.indices.size(), kJunkOffsetBytes + 12u);
  uint32_t first = 1, junk = 1;
  std::memcpy(&first, t.indices.data() + kJunkOffsetBytes, 4);
  std::memcpy(&junk, t.indices.data(), 4);
  EXPECT_EQ(first, 2u);
  EXPECT_EQ(junk, 0u);
}

TEST(BuildLayout, FaultsTellTheBuildsTheWrongLayout) {
  AsBuild b;
  b.data_offsets = true;
  b.first_vertex = kJunkVertices;
  b.vertex_stride = 24;
  b.aabb_stride = 32;
  const TriangleInputs stride = layTriangles(layoutTriangle(false), b, LayoutFault::StrideIgnored);
  EXPECT_EQ(stride.stride, 12u);
  EXPECT_EQ(stride.range.firstVertex, kJunkVertices) << "only the stride";
  const TriangleInputs offsets =
      layTriangles(layoutTriangle(false), b, LayoutFault::OffsetsIgnored);
  EXPECT_EQ(offsets.stride, 24u);
  EXPECT_EQ(offsets.range.primitiveOffset, 0u);
  EXPECT_EQ(offsets.range.firstVertex, 0u);
  EXPECT_EQ(offsets.range.transformOffset, 0u);
  Geometry boxes;
  boxes.kind = Geometry::Kind::Aabbs;
  boxes.aabbs = {{0, 0, 0, 1, 1, 1}, {2, 0, 0, 3, 1, 1}};
  const AabbInputs a = layAabbs(boxes, b, LayoutFault::None);
  EXPECT_EQ(a.stride, 32u);
  EXPECT_EQ(a.range.primitiveOffset, kJunkBoxes * 32);
  EXPECT_EQ(a.boxes.size(), (kJunkBoxes + 2) * 32u);
  EXPECT_EQ(floatAt(a.boxes, (kJunkBoxes + 1) * 32), 2.0f);
  EXPECT_TRUE(std::isnan(floatAt(a.boxes, (kJunkBoxes + 1) * 32 + 24))) << "padding";
  EXPECT_EQ(layAabbs(boxes, b, LayoutFault::StrideIgnored).stride, 24u);
  EXPECT_EQ(layAabbs(boxes, b, LayoutFault::OffsetsIgnored).range.primitiveOffset, 0u);
}

// vertex-format-misread: the build is told a confused format over the
// same bytes (unorm10x3: its R and B fields swapped in the bytes).
TEST(BuildLayout, FormatMisreadTellsTheBuildAnotherFormat) {
  Geometry g;
  g.vertices = {{0.25f, 0.5f, 1.0f}, {0, 0, 0}, {1, 0, 0}};
  g.vertex_format = VertexFormat::Unorm8x4;
  const TriangleInputs right = layTriangles(g, AsBuild{}, LayoutFault::None);
  EXPECT_EQ(right.format, VertexFormat::Unorm8x4);
  const TriangleInputs unorm = layTriangles(g, AsBuild{}, LayoutFault::FormatMisread);
  EXPECT_EQ(unorm.format, VertexFormat::Snorm8x4);
  EXPECT_EQ(unorm.vertices, right.vertices) << "the same bytes";
  EXPECT_EQ(unorm.stride, 4u);
  g.vertex_format = VertexFormat::Float4;
  const TriangleInputs float4 = layTriangles(g, AsBuild{}, LayoutFault::FormatMisread);
  EXPECT_EQ(float4.format, VertexFormat::Float3);
  EXPECT_EQ(float4.stride, 12u) << "float3's vertex size";
  EXPECT_EQ(float4.vertices.size(), 48u);
  g.vertex_format = VertexFormat::Unorm10x3;
  const TriangleInputs packed = layTriangles(g, AsBuild{}, LayoutFault::FormatMisread);
  EXPECT_EQ(packed.format, VertexFormat::Unorm10x3);
  uint32_t word = 0;
  std::memcpy(&word, packed.vertices.data(), 4);
  EXPECT_EQ(word & 0x3FF, 1023u) << "z in R's bits";
  EXPECT_EQ((word >> 10) & 0x3FF, 512u) << "y stays";
  EXPECT_EQ((word >> 20) & 0x3FF, 256u) << "x in B's bits";
  EXPECT_EQ(word >> 30, 3u);
  g.vertex_format = VertexFormat::Half3;
  const TriangleInputs half3 = layTriangles(g, AsBuild{}, LayoutFault::FormatMisread);
  EXPECT_EQ(half3.format, VertexFormat::Half2);
  EXPECT_EQ(half3.stride, 4u) << "half2's vertex size";
  g.vertex_format = VertexFormat::Float3;
  EXPECT_EQ(layTriangles(g, AsBuild{}, LayoutFault::FormatMisread).format, VertexFormat::Float3);
}

std::vector<VkAccelerationStructureInstanceKHR> numberedInstances(uint32_t n) {
  std::vector<VkAccelerationStructureInstanceKHR> out(n);
  for (uint32_t i = 0; i < n; ++i) {
    out[i].instanceCustomIndex = i + 1;
    out[i].accelerationStructureReference = 0x1000 + i;
  }
  return out;
}

// The instance a level's j-th pointer (after the range's offset) points at.
uint32_t pointedCustomIndex(const InstanceLayout& l, const std::vector<uint8_t>& bytes,
                            VkDeviceAddress base, uint32_t level, uint32_t j) {
  VkDeviceAddress p = 0;
  std::memcpy(&p, bytes.data() + l.dataOffset(level) + l.primitiveOffset(level) + j * 8, 8);
  EXPECT_EQ((p - base) % 16, 0u) << "an instance 16-byte aligned";
  VkAccelerationStructureInstanceKHR inst{};
  std::memcpy(&inst, bytes.data() + (p - base), sizeof inst);
  return inst.instanceCustomIndex;
}

TEST(BuildLayout, PointersReachEveryInstanceOfEachLevel) {
  AsBuild b;
  b.instances_as_pointers = true;
  b.data_offsets = true;
  const VkDeviceAddress base = 0x10000;
  const InstanceLayout l(b, 2, 3, LayoutFault::None);
  EXPECT_TRUE(l.pointers());
  const std::vector<uint8_t> bytes = l.write(numberedInstances(6), base);
  ASSERT_EQ(bytes.size(), l.bytes());
  for (uint32_t level = 0; level < 2; ++level) {
    EXPECT_EQ(l.primitiveOffset(level) % 16, 0u);
    EXPECT_NE(l.primitiveOffset(level), 0u);
    for (uint32_t j = 0; j < 3; ++j)
      EXPECT_EQ(pointedCustomIndex(l, bytes, base, level, j), level * 3 + j + 1);
  }
  // The junk pointer before the offset reaches a zeroed (inactive) instance.
  VkDeviceAddress junk = 0;
  std::memcpy(&junk, bytes.data(), 8);
  VkAccelerationStructureInstanceKHR inst{};
  std::memcpy(&inst, bytes.data() + (junk - base), sizeof inst);
  EXPECT_EQ(inst.accelerationStructureReference, 0u);
  // Reversed order: the first instance lies last.
  VkAccelerationStructureInstanceKHR last{};
  std::memcpy(&last, bytes.data() + bytes.size() - 2 * sizeof last, sizeof last);
  EXPECT_EQ(last.instanceCustomIndex, 1u);
  const InstanceLayout reversed(b, 2, 3, LayoutFault::PointersReversed);
  const std::vector<uint8_t> wrong = reversed.write(numberedInstances(6), base);
  EXPECT_EQ(pointedCustomIndex(reversed, wrong, base, 1, 0), 6u);
}

TEST(BuildLayout, DirectInstancesBehindAJunkInstance) {
  AsBuild b;
  b.data_offsets = true;
  const InstanceLayout l(b, 2, 3, LayoutFault::None);
  EXPECT_FALSE(l.pointers());
  const std::vector<uint8_t> bytes = l.write(numberedInstances(6), 0);
  EXPECT_EQ(l.dataOffset(1), 0u);
  EXPECT_EQ(l.primitiveOffset(1), 64u + 3 * 64);
  VkAccelerationStructureInstanceKHR inst{};
  std::memcpy(&inst, bytes.data() + l.primitiveOffset(1), sizeof inst);
  EXPECT_EQ(inst.instanceCustomIndex, 4u);
  EXPECT_EQ(InstanceLayout(b, 2, 3, LayoutFault::OffsetsIgnored).primitiveOffset(1), 0u);
  const InstanceLayout tight(AsBuild{}, 2, 3, LayoutFault::None);
  EXPECT_EQ(tight.dataOffset(1), 3u * 64);
  EXPECT_EQ(tight.primitiveOffset(1), 0u);
  EXPECT_EQ(tight.bytes(), 6u * 64);
}

}  // namespace
}  // namespace rayspec
