#include <cstring>

#include "export/c_text.h"
#include "export/export_sections.h"
#include "vulkan/acceleration_structure.h"
#include "vulkan/build_layout.h"

namespace rayspec {
namespace {

const char* indexType(const Geometry& g) {
  return g.indices.empty() ? "VK_INDEX_TYPE_NONE_KHR"
         : g.index16       ? "VK_INDEX_TYPE_UINT16"
                           : "VK_INDEX_TYPE_UINT32";
}

// The byte array `name` (NULL and 0 where there are none).
std::string bytesField(const std::string& name, const std::vector<uint8_t>& bytes) {
  return bytes.empty() ? "NULL" : name;
}

std::string rangeText(const VkAccelerationStructureBuildRangeInfoKHR& r) {
  return "{" + std::to_string(r.primitiveCount) + ", " + std::to_string(r.primitiveOffset) + ", " +
         std::to_string(r.firstVertex) + ", " + std::to_string(r.transformOffset) + "}";
}

// One geometry's inputs as the engine's build lays them out (layTriangles),
// its arrays into `arrays` and its rs_geometry initialiser returned.
std::string triangleEntry(const Geometry& g, const AsBuild& build, LayoutFault layout,
                          const std::string& prefix, std::string& arrays) {
  const TriangleInputs in = layTriangles(g, build, layout);
  arrays += cByteArray(prefix + "_vertices", in.vertices);
  if (!in.indices.empty()) arrays += cByteArray(prefix + "_indices", in.indices);
  if (!in.transform.empty()) arrays += cByteArray(prefix + "_transform", in.transform);
  return "  {VK_GEOMETRY_TYPE_TRIANGLES_KHR, (VkFormat)" +
         std::to_string(vkVertexFormat(in.format)) + ", " + cString(vertexFormatName(in.format)) +
         ", " + std::to_string(in.stride) + ", " + std::to_string(in.max_vertex) + ", " +
         indexType(g) + ", " + std::to_string(g.flags) + ", " + prefix + "_vertices, " +
         bytesField(prefix + "_indices", in.indices) + ", " +
         bytesField(prefix + "_transform", in.transform) + ", " +
         std::to_string(in.vertices.size()) + ", " + std::to_string(in.indices.size()) + ", " +
         std::to_string(in.transform.size()) + ", " + rangeText(in.range) + "},\n";
}

// One AABB geometry's boxes as the engine's build lays them out (layAabbs):
// rs_geometry's vertex fields hold them.
std::string aabbEntry(const Geometry& g, const AsBuild& build, LayoutFault layout,
                      const std::string& prefix, std::string& arrays) {
  const AabbInputs in = layAabbs(g, build, layout);
  arrays += cByteArray(prefix + "_boxes", in.boxes);
  return "  {VK_GEOMETRY_TYPE_AABBS_KHR, VK_FORMAT_UNDEFINED, \"aabbs\", " +
         std::to_string(in.stride) + ", 0, VK_INDEX_TYPE_NONE_KHR, " + std::to_string(g.flags) +
         ", " + prefix + "_boxes, NULL, NULL, " + std::to_string(in.boxes.size()) + ", 0, 0, " +
         rangeText(in.range) + "},\n";
}

std::string geometryEntry(const Geometry& g, const AsBuild& build, LayoutFault layout,
                          const std::string& prefix, std::string& arrays) {
  return g.kind == Geometry::Kind::Aabbs ? aabbEntry(g, build, layout, prefix, arrays)
                                         : triangleEntry(g, build, layout, prefix, arrays);
}

std::string instanceEntry(const Instance& inst) {
  std::string out = "  {{";
  for (size_t k = 0; k < inst.transform.size(); ++k)
    out += (k ? ", " : "") + cFloat(inst.transform[k]);
  return out + "}, " + std::to_string(inst.custom_index & kInstanceFieldMask) + "u, " +
         std::to_string(inst.mask & kVisibilityMask) + "u, " +
         std::to_string(inst.sbt_offset & kInstanceFieldMask) + "u, " +
         std::to_string(inst.flags & kInstanceFlagsMask) + "u, " +
         (inst.blas ? std::to_string(*inst.blas) + "u" : std::string("RS_NONE")) + "},\n";
}

}  // namespace

std::string sceneSection(const Scene& scene, LayoutFault layout) {
  std::string arrays, geometries, blases;
  uint32_t first = 0;
  size_t most = 1;
  for (size_t b = 0; b < scene.blases.size(); ++b) {
    const Blas& blas = scene.blases[b];
    for (size_t g = 0; g < blas.geometries.size(); ++g)
      geometries +=
          geometryEntry(blas.geometries[g], scene.build, layout,
                        "rs_blas" + std::to_string(b) + "_geometry" + std::to_string(g), arrays);
    const uint32_t count = static_cast<uint32_t>(blas.geometries.size());
    blases += "  {" + std::to_string(first) + ", " + std::to_string(count) + "},  /* " + blas.name +
              " */\n";
    first += count;
    most = std::max<size_t>(most, count);
  }
  std::string instances;
  for (const Instance& inst : scene.instances) instances += instanceEntry(inst);
  return "/* The scene: each bottom level's triangles or boxes, laid out as rayspec's builds\n"
         "   lay them out, and the top level's instances. */\n" +
         arrays + "static const rs_geometry rs_geometries[] = {\n" + geometries + "};\n" +
         "static const rs_blas rs_blases[] = {\n" + blases + "};\n" +
         "static const rs_instance rs_instances[] = {\n" + instances + "};\n" +
         "#define RS_BLAS_COUNT " + std::to_string(scene.blases.size()) + "\n" +
         "#define RS_MAX_GEOMETRIES " + std::to_string(most) + "\n" + "#define RS_INSTANCE_COUNT " +
         std::to_string(scene.instances.size()) + "\n" + "#define RS_BUILD_FLAGS " +
         std::to_string(scene.build.flags) + "u\n\n";
}

}  // namespace rayspec
