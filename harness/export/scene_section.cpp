#include <cctype>
#include <cstring>
#include <set>

#include "case/build_order.h"
#include "export/c_text.h"
#include "export/export_sections.h"
#include "vulkan/acceleration_structure.h"
#include "vulkan/build_layout.h"
#include "vulkan/structure_queries.h"

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
         (inst.blas ? std::to_string(*inst.blas) + "u" : std::string("RS_NONE")) + ", " +
         std::to_string(inst.tlas) + "u},\n";
}

// The scene as first built, then after each update (scene.update): the
// last is `scene` itself.
std::vector<const Scene*> statesOf(const Scene& scene) {
  std::vector<const Scene*> states;
  for (const auto& e : scene.earlier) states.push_back(e.get());
  states.push_back(&scene);
  return states;
}

// The name prefix of state k's arrays: the scene as first built has none.
std::string statePrefix(size_t k) {
  return k ? "rs_update" + std::to_string(k) + "_" : "rs_";
}

// Every state's geometries, bottom levels (each state's after the one
// before) and instances, as C arrays.
struct SceneTables {
  std::string arrays, geometries, blases, instances;
  size_t most = 1;
};

void addState(const Scene& state, size_t k, const std::vector<bool>& reached, const AsBuild& build,
              LayoutFault layout, uint32_t& first, SceneTables& t) {
  for (size_t b = 0; b < state.blases.size(); ++b) {
    const Blas& blas = state.blases[b];
    for (size_t g = 0; g < blas.geometries.size(); ++g)
      t.geometries += geometryEntry(
          blas.geometries[g], build, layout,
          statePrefix(k) + "blas" + std::to_string(b) + "_geometry" + std::to_string(g), t.arrays);
    const uint32_t count = static_cast<uint32_t>(blas.geometries.size());
    t.blases += "  {" + std::to_string(first) + ", " + std::to_string(count) + ", " +
                (reached[b] ? "1" : "0") + "},  /* " + blas.name + (k ? ", update " : "") +
                (k ? std::to_string(k) : "") + " */\n";
    first += count;
    t.most = std::max<size_t>(t.most, count);
  }
  for (const Instance& inst : state.instances) t.instances += instanceEntry(inst);
}

// RS_COPY, RS_COPY_AT, RS_UPDATE_INTO_OTHER, RS_TLAS_REBUILT: the order of
// the builds, updates and copy as the Vulkan engine runs them.
std::string operationDefines(const Scene& scene) {
  const AsBuild& b = scene.build;
  std::string copy = asCopyName(b.copy);
  for (char& ch : copy) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  return "#define RS_COPY RS_COPY_" + copy + "\n#define RS_COPY_AT " +
         std::to_string(copyAt(scene)) + "u\n#define RS_UPDATE_INTO_OTHER " +
         (b.update_into_other ? "1" : "0") + "\n#define RS_TLAS_REBUILT " +
         (b.tlas_rebuilt ? "1" : "0") + "\n";
}

// rs_queries, rs_query_count (the device queries in the case's order), RS_QUERY_AT,
// RS_NEEDS_MAINTENANCE1, and rs_referenced: per top level, per BLAS, whether
// its active instances reference the BLAS when the queries are asked.
std::string queryTables(const Scene& scene, const std::vector<const Scene*>& states) {
  std::string queries;
  for (StructureQuery q : scene.build.queries.queries)
    queries += "  (VkQueryType)" + std::to_string(vkQueryType(q)) + ",  /* " + nameOf(q) + " */\n";
  std::string referenced;
  const size_t at = queryAt(scene);
  for (const std::set<uint32_t>& level : referencedBlases(*states[std::min(at, scene.updates())])) {
    referenced += " ";
    for (uint32_t b = 0; b < scene.blases.size(); ++b) referenced += level.count(b) ? " 1," : " 0,";
    referenced += "\n";
  }
  return "static const VkQueryType rs_queries[] = {\n" + (queries.empty() ? "  0\n" : queries) +
         "};\nstatic const uint32_t rs_query_count = " +
         std::to_string(scene.build.queries.queries.size()) + ";\n#define RS_QUERY_AT " +
         std::to_string(at) + "u\n#define RS_NEEDS_MAINTENANCE1 " +
         (scene.build.queries.needsMaintenance1() ? "1" : "0") +
         "\nstatic const uint8_t rs_referenced[] = {\n" + referenced + "};\n";
}

}  // namespace

std::string sceneSection(const Scene& scene, LayoutFault layout) {
  const std::vector<const Scene*> states = statesOf(scene);
  const std::vector<bool> reached = reachedBlases(*states.front());
  SceneTables t;
  uint32_t first = 0;
  for (size_t k = 0; k < states.size(); ++k)
    addState(*states[k], k, reached, scene.build, layout, first, t);
  return "/* The scene: each bottom level's triangles or boxes, laid out as rayspec's builds\n"
         "   lay them out, and the instances of the top levels; the same again for each\n"
         "   update (scene.update), in order. */\n" +
         t.arrays + "static const rs_geometry rs_geometries[] = {\n" + t.geometries + "};\n" +
         "static const rs_blas rs_blases[] = {\n" + t.blases + "};\n" +
         "static const rs_instance rs_instances[] = {\n" + t.instances + "};\n" +
         "#define RS_BLAS_COUNT " + std::to_string(scene.blases.size()) + "\n" +
         "#define RS_MAX_GEOMETRIES " + std::to_string(t.most) + "\n" +
         "#define RS_INSTANCE_COUNT " + std::to_string(scene.instances.size()) +
         "\n#define RS_TLAS_COUNT " + std::to_string(scene.tlasCount()) +
         "u\n#define RS_STATE_COUNT " + std::to_string(states.size()) +
         "u\n#define RS_BUILD_FLAGS " + std::to_string(buildFlags(scene.build)) + "u\n" +
         operationDefines(scene) + queryTables(scene, states) + "\n";
}

}  // namespace rayspec
