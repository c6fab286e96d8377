// The scene of an exported Amber script: each bottom level's triangles or
// boxes as rayspec's builds lay them out (float32x3 vertices, packed: the
// only layout amber_support.cpp lets through), the top level's instances.
#include <cstring>

#include "export/amber_sections.h"
#include "vulkan/build_layout.h"

namespace rayspec {
namespace {

// The floats of a packed input, `per_line` a line.
std::string floatLines(const std::vector<uint8_t>& bytes, size_t per_line) {
  std::string out;
  const size_t count = bytes.size() / 4;
  for (size_t i = 0; i < count; ++i) {
    float v;
    std::memcpy(&v, &bytes[4 * i], 4);
    out +=
        (i % per_line ? " " : "    ") + amberFloat(v) + (i % per_line == per_line - 1 ? "\n" : "");
  }
  return out;
}

std::string geometryFlags(uint32_t flags) {
  if (!flags) return "";
  std::string out = "    FLAGS";
  if (flags & 0x1) out += " OPAQUE";
  if (flags & 0x2) out += " NO_DUPLICATE_ANY_HIT";
  return out + "\n";
}

std::string geometryText(const Geometry& g, const AsBuild& build) {
  if (g.kind == Geometry::Kind::Aabbs)
    return "  GEOMETRY AABBS\n" + geometryFlags(g.flags) +
           floatLines(layAabbs(g, build, LayoutFault::None).boxes, 6) + "  END\n";
  return "  GEOMETRY TRIANGLES\n" + geometryFlags(g.flags) +
         floatLines(layTriangles(g, build, LayoutFault::None).vertices, 3) + "  END\n";
}

std::string instanceText(const Instance& i) {
  std::string out = "  BOTTOM_LEVEL_INSTANCE blas" + std::to_string(*i.blas) + "\n    INDEX " +
                    std::to_string(i.custom_index & kInstanceFieldMask) + "\n    OFFSET " +
                    std::to_string(i.sbt_offset & kInstanceFieldMask) + "\n    MASK " +
                    std::to_string(i.mask & kVisibilityMask) + "\n";
  if (const uint32_t flags = i.flags & kInstanceFlagsMask)
    out += "    FLAGS " + std::to_string(flags) + "\n";
  out += "    TRANSFORM\n";
  for (size_t row = 0; row < 3; ++row) {
    out += "     ";
    for (size_t col = 0; col < 4; ++col) out += " " + amberFloat(i.transform[4 * row + col]);
    out += "\n";
  }
  return out + "    END\n  END\n";
}

}  // namespace

std::string amberScene(const Scene& scene) {
  std::string out;
  for (size_t b = 0; b < scene.blases.size(); ++b) {
    out += "# bottom level " + std::to_string(b) + ": " + scene.blases[b].name + "\n" +
           "ACCELERATION_STRUCTURE BOTTOM_LEVEL blas" + std::to_string(b) + "\n";
    for (const Geometry& g : scene.blases[b].geometries) out += geometryText(g, scene.build);
    out += "END\n\n";
  }
  out += "ACCELERATION_STRUCTURE TOP_LEVEL tlas\n";
  for (const Instance& i : scene.instances) out += instanceText(i);
  return out + "END\n\n";
}

}  // namespace rayspec
