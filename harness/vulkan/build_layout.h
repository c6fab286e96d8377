// How the build inputs of acceleration structures lie in memory
// (scene.build.instances_as_pointers, data_offsets, first_vertex,
// vertex_stride, aabb_stride): the bytes of each geometry's vertices, indices, transform and
// boxes, and of each top level's instances, with the strides, offsets and
// pointers the builds are given. Every layout stands for the same scene; a
// driver that misreads one reads junk instead: NaN (inactive triangles and
// boxes, R-INACTIVE) in vertex and box padding and before offsets, index 0
// before index offsets, zeroed (inactive) instances in instance gaps and
// behind junk pointers. Junk is always inside the buffer, so a misreading
// driver reads wrong values, never out of bounds.
// The planted layout faults (vk_fault_hook.h) give the builds a wrong
// stride, offset or pointer order over the same bytes.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <optional>
#include <vector>

#include "case/case.h"
#include "case/vertex_format_misread.h"
#include "vulkan/vk_fault_hook.h"

namespace rayspec {

// Bytes before the data where scene.build.data_offsets is on.
// primitiveOffset of vertices and indices: a multiple of every vertex format's
// whole size, though the specification asks only for the component size of an
// unpacked format (VUID-VkAccelerationStructureBuildRangeInfoKHR-primitiveOffset-03657):
// the validation layer 1.4.363 asks for the whole size (16 bytes before float3
// vertices: "not a multiple of 12"), and its false error would fail the case.
constexpr uint32_t kJunkOffsetBytes = 48;
#define RAYSPEC_JUNK_OFFSET_FITS(id, name, vk, encoding, bits, components, stride) \
  &&kJunkOffsetBytes % (stride) == 0
static_assert(true RAYSPEC_VERTEX_FORMATS(RAYSPEC_JUNK_OFFSET_FITS),
              "kJunkOffsetBytes must be a multiple of every vertex format's size");
#undef RAYSPEC_JUNK_OFFSET_FITS
constexpr uint32_t kJunkTransformBytes = 48;  // transformOffset: one junk matrix
constexpr uint32_t kJunkBoxes = 2;            // primitiveOffset of boxes, in strides

// One triangle geometry's inputs: the bytes of its vertices, indices (empty:
// none) and transform (empty: none), the vertex format and stride the build
// is told, maxVertex and range (the offsets relative to the start of each
// piece's bytes).
struct TriangleInputs {
  std::vector<uint8_t> vertices, indices, transform;
  VertexFormat format = VertexFormat::Float3;
  uint32_t stride = 0;
  uint32_t max_vertex = 0;
  VkAccelerationStructureBuildRangeInfoKHR range{};
};
TriangleInputs layTriangles(const Geometry& g, const AsBuild& build, LayoutFault fault);

// One AABB geometry's inputs: its boxes, stride and range.
struct AabbInputs {
  std::vector<uint8_t> boxes;
  uint32_t stride = 0;
  VkAccelerationStructureBuildRangeInfoKHR range{};
};
AabbInputs layAabbs(const Geometry& g, const AsBuild& build, LayoutFault fault);

// Where the instances of every top level lie in one buffer: each level's
// `count` instances, level after level, directly (arrayOfPointers false) or
// behind an array of pointers per level (instances in reverse order, each
// followed by a zeroed gap).
class InstanceLayout {
 public:
  InstanceLayout(const AsBuild& build, uint32_t levels, uint32_t count, LayoutFault fault);

  VkDeviceSize bytes() const { return bytes_; }
  bool pointers() const { return pointers_; }
  // Level `level`'s instances.data, as an offset into the buffer, and its
  // range's primitiveOffset.
  VkDeviceSize dataOffset(uint32_t level) const;
  uint32_t primitiveOffset(uint32_t level) const;
  // The buffer's bytes with `all` (levels x count instances) placed, and the
  // pointers holding addresses in the buffer that starts at `base`.
  std::vector<uint8_t> write(const std::vector<VkAccelerationStructureInstanceKHR>& all,
                             VkDeviceAddress base) const;

 private:
  VkDeviceSize instanceAt(uint64_t g) const;  // the g-th instance's place (level * count + j)

  bool pointers_, offsets_;
  LayoutFault fault_;
  uint32_t levels_, count_;
  VkDeviceSize junk_ = 0;         // bytes before the first level's data
  VkDeviceSize level_bytes_ = 0;  // one level's instances or pointers
  VkDeviceSize slots_ = 0;        // pointers: where the junk instance and the slots start
  VkDeviceSize bytes_ = 0;
};

}  // namespace rayspec
