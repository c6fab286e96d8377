#include "vulkan/build_layout.h"

#include <algorithm>
#include <cstring>
#include <functional>

namespace rayspec {
namespace {

// Junk vertex bytes: NaN in float and half formats (an inactive triangle,
// R-INACTIVE); normalized codes have no NaN, so their largest value, 1.0, in
// every component (all ones; an snorm code's top byte 0x7F, little-endian).
void fillVertexJunk(VertexFormat f, uint8_t* at, size_t bytes) {
  const bool snorm = vertexEncoding(f) == VertexEncoding::Snorm;
  const size_t unit = vertexComponentBytes(f);
  for (size_t i = 0; i < bytes; ++i) at[i] = snorm && i % unit == unit - 1 ? 0x7F : 0xFF;
}

// `count` items of `item` bytes from `tight`, each at `stride` bytes from the
// one before, after `skip` junk strides; `junk` fills the rest.
std::vector<uint8_t> spread(const std::vector<uint8_t>& tight, size_t item, size_t stride,
                            size_t skip, const std::function<void(uint8_t*, size_t)>& junk) {
  const size_t count = item ? tight.size() / item : 0;
  std::vector<uint8_t> out((skip + count) * stride);
  junk(out.data(), out.size());
  for (size_t i = 0; i < count; ++i)
    std::memcpy(out.data() + (skip + i) * stride, tight.data() + i * item, item);
  return out;
}

// `bytes` of junk `fill` before `data`.
template <typename T>
std::vector<uint8_t> behindJunk(const T* data, size_t bytes, size_t junk, uint8_t fill) {
  std::vector<uint8_t> out(junk + bytes, fill);
  if (bytes) std::memcpy(out.data() + junk, data, bytes);
  return out;
}

// The indices (uint16 or uint32), behind kJunkOffsetBytes of index 0 where
// offsets are on: a driver that ignores primitiveOffset reads degenerate
// triangles first.
std::vector<uint8_t> indexBytes(const Geometry& g, size_t junk) {
  if (g.indices.empty()) return {};
  if (g.index16) {
    const std::vector<uint16_t> narrow(g.indices.begin(), g.indices.end());
    return behindJunk(narrow.data(), narrow.size() * 2, junk, 0);
  }
  return behindJunk(g.indices.data(), g.indices.size() * 4, junk, 0);
}

}  // namespace

TriangleInputs layTriangles(const Geometry& g, const AsBuild& build, LayoutFault fault) {
  TriangleInputs out;
  const uint32_t tight = vertexStride(g.vertex_format);
  const bool offsets = build.data_offsets;
  out.stride = build.vertex_stride ? build.vertex_stride : tight;
  const uint32_t first = build.first_vertex;
  auto junk = [&g](uint8_t* at, size_t n) {
    fillVertexJunk(g.vertex_format, at, n);
  };
  std::vector<uint8_t> encoded = encodeVertices(g.vertex_format, g.vertices);
  VertexFormatMisread misread{g.vertex_format};  // read right
  if (fault == LayoutFault::FormatMisread)
    misread = vertexFormatMisread(g.vertex_format).value_or(misread);
  misreadBytes(misread, encoded);
  out.vertices = spread(encoded, tight, out.stride, first, junk);
  // As many junk vertices after them: a driver that applies firstVertex twice
  // (lavapipe 25.0.7) reads these, not whatever memory follows, so it answers
  // the same in every run.
  const size_t tail = size_t{first} * out.stride;
  out.vertices.resize(out.vertices.size() + tail);
  junk(out.vertices.data() + out.vertices.size() - tail, tail);
  out.max_vertex = g.vertices.empty() ? 0 : first + static_cast<uint32_t>(g.vertices.size()) - 1;
  // Non-indexed, primitiveOffset moves the vertices; indexed, the indices.
  const size_t junk_bytes = offsets ? kJunkOffsetBytes : 0;
  if (g.indices.empty()) {
    std::vector<uint8_t> moved(junk_bytes + out.vertices.size());
    junk(moved.data(), junk_bytes);
    std::copy(out.vertices.begin(), out.vertices.end(), moved.begin() + junk_bytes);
    out.vertices = std::move(moved);
  }
  out.indices = indexBytes(g, junk_bytes);
  if (g.transform) {
    static_assert(sizeof(VkTransformMatrixKHR) == sizeof(Transform));
    out.transform =
        behindJunk(g.transform->data(), sizeof(Transform), offsets ? kJunkTransformBytes : 0, 0xFF);
  }
  out.range.primitiveCount = g.primitiveCount();
  if (fault != LayoutFault::OffsetsIgnored) {
    out.range.primitiveOffset = static_cast<uint32_t>(junk_bytes);
    out.range.firstVertex = first;
    out.range.transformOffset = offsets && g.transform ? kJunkTransformBytes : 0;
  }
  if (fault == LayoutFault::StrideIgnored) out.stride = tight;
  out.format = misread.format;
  out.stride = misreadStride(g.vertex_format, misread, out.stride);  // never past the buffer
  return out;
}

AabbInputs layAabbs(const Geometry& g, const AsBuild& build, LayoutFault fault) {
  static_assert(sizeof(VkAabbPositionsKHR) == sizeof(std::array<float, 6>));
  constexpr size_t kBox = sizeof(VkAabbPositionsKHR);
  AabbInputs out;
  out.stride = build.aabb_stride ? build.aabb_stride : kBox;
  const size_t skip = build.data_offsets ? kJunkBoxes : 0;
  std::vector<uint8_t> tight(g.aabbs.size() * kBox);
  if (!tight.empty()) std::memcpy(tight.data(), g.aabbs.data(), tight.size());
  out.boxes = spread(tight, kBox, out.stride, skip, [](uint8_t* at, size_t n) {
    std::memset(at, 0xFF, n);  // NaN: an inactive box (R-INACTIVE)
  });
  out.range.primitiveCount = g.primitiveCount();
  if (fault != LayoutFault::OffsetsIgnored)
    out.range.primitiveOffset = static_cast<uint32_t>(skip * out.stride);
  if (fault == LayoutFault::StrideIgnored) out.stride = kBox;
  return out;
}

namespace {
constexpr VkDeviceSize kInstance = sizeof(VkAccelerationStructureInstanceKHR);
constexpr VkDeviceSize kPointer = sizeof(VkDeviceAddress);
}  // namespace

// Directly: [junk instance where offsets are on][level 0][level 1]...
// Pointers: [16 junk bytes where offsets are on][each level's pointers,
// padded to 16][a zeroed instance, the junk pointers' target][slots of an
// instance and a zeroed gap each, the last instance first].
InstanceLayout::InstanceLayout(const AsBuild& build, uint32_t levels, uint32_t count,
                               LayoutFault fault)
    : pointers_(build.instances_as_pointers),
      offsets_(build.data_offsets),
      fault_(fault),
      levels_(levels),
      count_(count) {
  if (pointers_) {
    junk_ = offsets_ ? 16 : 0;
    level_bytes_ = (count * kPointer + 15) / 16 * 16;
    slots_ = junk_ + levels * level_bytes_;
    bytes_ = slots_ + kInstance + VkDeviceSize(levels) * count * 2 * kInstance;
  } else {
    junk_ = offsets_ ? kInstance : 0;
    level_bytes_ = count * kInstance;
    bytes_ = junk_ + levels * level_bytes_;
  }
  bytes_ = std::max<VkDeviceSize>(bytes_, 16);
}

VkDeviceSize InstanceLayout::dataOffset(uint32_t level) const {
  return offsets_ ? 0 : level * level_bytes_;
}

uint32_t InstanceLayout::primitiveOffset(uint32_t level) const {
  if (!offsets_ || fault_ == LayoutFault::OffsetsIgnored) return 0;
  return static_cast<uint32_t>(junk_ + level * level_bytes_);
}

VkDeviceSize InstanceLayout::instanceAt(uint64_t g) const {
  if (!pointers_) return junk_ + g * kInstance;
  const uint64_t last = uint64_t(levels_) * count_ - 1;
  return slots_ + kInstance + (last - g) * 2 * kInstance;
}

std::vector<uint8_t> InstanceLayout::write(
    const std::vector<VkAccelerationStructureInstanceKHR>& all, VkDeviceAddress base) const {
  std::vector<uint8_t> out(bytes_, 0);
  for (uint64_t g = 0; g < all.size() && g < uint64_t(levels_) * count_; ++g)
    std::memcpy(out.data() + instanceAt(g), &all[g], kInstance);
  if (!pointers_) return out;
  auto put = [&out](VkDeviceSize at, VkDeviceAddress value) {
    std::memcpy(out.data() + at, &value, kPointer);
  };
  for (VkDeviceSize at = 0; at < junk_; at += kPointer) put(at, base + slots_);
  for (uint32_t level = 0; level < levels_; ++level)
    for (uint32_t j = 0; j < count_; ++j) {
      const uint32_t k = fault_ == LayoutFault::PointersReversed ? count_ - 1 - j : j;
      put(junk_ + level * level_bytes_ + j * kPointer,
          base + instanceAt(uint64_t(level) * count_ + k));
    }
  return out;
}

}  // namespace rayspec
