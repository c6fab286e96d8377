// scene: blas (name -> geometries) and instances.
#include <cmath>

#include "case/flag_names.h"
#include "case/transform.h"
#include "parse/parse_parts.h"

namespace rayspec {
namespace {

bool parseTriangleData(YamlReader& r, const YAML::Node& n, const std::string& field, Geometry& g) {
  g.kind = Geometry::Kind::Triangles;
  if (!r.expectMap(n, field,
                   {"grid", "fan", "triangulation", "subdivision", "vertices", "indices",
                    "vertex_format", "index_type"}))
    return false;
  if (const std::optional<bool> generated = parseGeneratedMesh(r, n, field, g)) return *generated;
  if (!r.require(n, field, "vertices")) return false;
  const YAML::Node verts = YamlReader::get(n, "vertices");
  if (!r.expectSeq(verts, field + ".vertices")) return false;
  bool ok = true;
  for (size_t i = 0; i < verts.size(); ++i) {
    auto v = r.numbers<3>(verts[i], field + ".vertices[" + std::to_string(i) + "]", true);
    if (!v) {
      ok = false;
      continue;
    }
    g.vertices.push_back(
        {static_cast<float>((*v)[0]), static_cast<float>((*v)[1]), static_cast<float>((*v)[2])});
  }
  if (!ok) return false;
  const YAML::Node idx = YamlReader::get(n, "indices");
  if (idx.IsDefined()) {
    if (!r.expectSeq(idx, field + ".indices")) return false;
    for (size_t i = 0; i < idx.size(); ++i) {
      const std::string f = field + ".indices[" + std::to_string(i) + "]";
      auto v = r.uint(idx[i], f);
      if (!v) {
        ok = false;
        continue;
      }
      if (*v >= g.vertices.size()) {
        r.error(idx[i], f,
                "index " + std::to_string(*v) + " is past the last vertex (" +
                    std::to_string(g.vertices.size()) + " vertices)");
        ok = false;
      }
      g.indices.push_back(*v);
    }
    if (ok && g.indices.size() % 3 != 0) {
      r.error(idx, field + ".indices", "the index count is not a multiple of 3");
      ok = false;
    }
  } else if (g.vertices.size() % 3 != 0) {
    r.error(verts, field + ".vertices",
            "without indices, the vertex count must be a multiple of 3");
    ok = false;
  }
  return ok;
}

// triangles.vertex_format and index_type (R-VERTEX-FORMAT): every position
// checked against the format and replaced by what the format stores.
bool parseFormats(YamlReader& r, const YAML::Node& n, const std::string& field, Geometry& g) {
  bool ok = true;
  if (const YAML::Node v = YamlReader::get(n, "vertex_format"); v.IsDefined()) {
    const auto name = r.string(v, field + ".vertex_format");
    const auto format = name ? vertexFormatFromName(*name) : std::nullopt;
    if (name && !format)
      r.error(v, field + ".vertex_format",
              "unknown vertex format '" + *name + "' (" + vertexFormatNames() + ")");
    if (!format) return false;
    g.vertex_format = *format;
  }
  if (g.vertex_format != VertexFormat::Float3) {
    g.written = g.vertices;
    for (size_t i = 0; i < g.vertices.size() && ok; ++i)
      if (const std::string problem = vertexFormatProblem(g.vertex_format, g.vertices[i]);
          !problem.empty()) {
        r.error(n, field + ".vertices[" + std::to_string(i) + "]", problem);
        ok = false;
      }
    for (Vec3& v : g.vertices) v = storedVertex(g.vertex_format, v);
  }
  if (const YAML::Node t = YamlReader::get(n, "index_type"); t.IsDefined()) {
    const auto name = r.string(t, field + ".index_type");
    if (!name) return false;
    if (*name != "uint16" && *name != "uint32") {
      r.error(t, field + ".index_type", "unknown index type '" + *name + "' (uint16, uint32)");
      return false;
    }
    g.index16 = *name == "uint16";
    if (g.index16 && g.indices.empty()) {
      r.error(t, field + ".index_type", "uint16 needs indices");
      ok = false;
    }
    if (g.index16 && g.vertices.size() > 65536) {
      r.error(t, field + ".index_type",
              "uint16 indices reach 65536 vertices, the geometry has " +
                  std::to_string(g.vertices.size()));
      ok = false;
    }
  }
  return ok;
}

bool parseTriangles(YamlReader& r, const YAML::Node& n, const std::string& field, Geometry& g) {
  return parseTriangleData(r, n, field, g) && parseFormats(r, n, field, g);
}

bool parseAabbs(YamlReader& r, const YAML::Node& n, const std::string& field, Geometry& g) {
  g.kind = Geometry::Kind::Aabbs;
  if (n.IsMap()) return parseBoxGrid(r, n, field, g);
  if (!r.expectSeq(n, field)) return false;  // none: an empty geometry
  bool ok = true;
  for (size_t i = 0; i < n.size(); ++i) {
    const std::string f = field + "[" + std::to_string(i) + "]";
    auto v = r.numbers<6>(n[i], f, true);
    if (!v) {
      ok = false;
      continue;
    }
    std::array<float, 6> box;
    for (int k = 0; k < 6; ++k) box[k] = static_cast<float>((*v)[k]);
    for (int k = 0; k < 3; ++k)
      if (box[k] > box[k + 3]) {  // false for NaN: inactive boxes are allowed
        r.error(n[i], f, "min is greater than max (component " + std::to_string(k) + ")");
        ok = false;
        break;
      }
    g.aabbs.push_back(box);
  }
  return ok;
}

void parseGeometry(YamlReader& r, const YAML::Node& n, const std::string& field, Geometry& g) {
  g.loc = r.loc(n, field);
  if (!r.expectMap(n, field, {"triangles", "aabbs", "flags", "transform"})) return;
  const bool tri = YamlReader::has(n, "triangles"), box = YamlReader::has(n, "aabbs");
  if (tri == box) {
    r.error(n, field, "a geometry needs exactly one of 'triangles' or 'aabbs'");
    return;
  }
  if (tri)
    parseTriangles(r, YamlReader::get(n, "triangles"), field + ".triangles", g);
  else
    parseAabbs(r, YamlReader::get(n, "aabbs"), field + ".aabbs", g);
  if (auto f = YamlReader::get(n, "flags"); f.IsDefined())
    if (auto bits = r.flags(f, field + ".flags", geometryFlagNames())) g.flags = *bits;
  if (auto t = YamlReader::get(n, "transform"); t.IsDefined()) {
    if (box)
      r.error(t, field + ".transform", "a geometry transform applies to triangles only");
    else
      g.transform = parseTransform(r, t, field + ".transform");
  }
}

void parseBlases(YamlReader& r, const YAML::Node& n, Scene& scene) {
  if (!n.IsMap()) {
    r.error(n, "scene.blas", "expected a map of name -> list of geometries");
    return;
  }
  uint64_t primitives = 0;
  for (auto it = n.begin(); it != n.end(); ++it) {
    Blas b;
    b.name = it->first.IsScalar() ? it->first.Scalar() : "?";
    const std::string field = "scene.blas." + b.name;
    b.loc = r.loc(it->first, field);
    const YAML::Node geoms = it->second;
    if (r.expectSeq(geoms, field)) {
      for (size_t i = 0; i < geoms.size(); ++i) {
        Geometry g;
        const std::string fi = field + "[" + std::to_string(i) + "]";
        parseGeometry(r, geoms[i], fi, g);
        primitives += g.primitiveCount();
        if (primitives > kMaxScenePrimitives) {
          r.error(geoms[i], fi,
                  "the scene's geometries hold more than 2^24 primitives together (a "
                  "limit of every case: docs/robustness.md, Limits)");
          return;
        }
        b.geometries.push_back(std::move(g));
      }
      for (size_t i = 1; i < b.geometries.size(); ++i)
        if (b.geometries[i].kind != b.geometries[0].kind) {
          r.error(geoms[i], field + "[" + std::to_string(i) + "]",
                  "a BLAS holds only triangles or only aabbs, not both");
          break;
        }
    }
    for (const Blas& other : scene.blases)
      if (other.name == b.name) r.error(it->first, field, "duplicate BLAS name '" + b.name + "'");
    scene.blases.push_back(std::move(b));
  }
}

}  // namespace

void parseInstance(YamlReader& r, const YAML::Node& n, const std::string& field, const Scene& scene,
                   Instance& inst) {
  inst.loc = r.loc(n, field);
  if (!r.expectMap(n, field,
                   {"blas", "transform", "mask", "custom_index", "sbt_offset", "flags", "tlas"}) ||
      !r.require(n, field, "blas"))
    return;
  const YAML::Node b = YamlReader::get(n, "blas");
  if (!b.IsNull()) {
    if (auto name = r.string(b, field + ".blas")) {
      bool found = false;
      for (size_t i = 0; i < scene.blases.size(); ++i)
        if (scene.blases[i].name == *name) {
          inst.blas = static_cast<uint32_t>(i);
          found = true;
        }
      if (!found) r.error(b, field + ".blas", "unknown BLAS '" + *name + "'");
    }
  }
  if (auto t = YamlReader::get(n, "transform"); t.IsDefined()) {
    if (auto tr = parseTransform(r, t, field + ".transform")) {
      inst.transform = *tr;
      if (!(std::fabs(linearDeterminant(*tr)) > 0))
        r.error(t, field + ".transform", "the transform is not invertible");
    }
  }
  if (auto m = YamlReader::get(n, "mask"); m.IsDefined())
    if (auto v = r.uint(m, field + ".mask", kVisibilityMask)) inst.mask = *v;
  if (auto m = YamlReader::get(n, "custom_index"); m.IsDefined())
    if (auto v = r.uint(m, field + ".custom_index", kInstanceFieldMask)) inst.custom_index = *v;
  if (auto m = YamlReader::get(n, "sbt_offset"); m.IsDefined())
    if (auto v = r.uint(m, field + ".sbt_offset", kInstanceFieldMask)) inst.sbt_offset = *v;
  if (auto f = YamlReader::get(n, "flags"); f.IsDefined())
    if (auto bits = r.flags(f, field + ".flags", instanceFlagNames())) inst.flags = *bits;
  if (auto t = YamlReader::get(n, "tlas"); t.IsDefined())
    if (auto v = r.uint(t, field + ".tlas", kMaxTlases - 1)) inst.tlas = *v;
}

std::optional<bool> parseSwitch(YamlReader& r, const YAML::Node& n, const std::string& field) {
  const auto text = r.string(n, field);
  if (!text) return std::nullopt;
  if (*text == "true" || *text == "false") return *text == "true";
  r.error(n, field, "expected true or false, not '" + *text + "'");
  return std::nullopt;
}

namespace {

// A field that is one of two words: false for `first`, true for `second`.
std::optional<bool> parseEither(YamlReader& r, const YAML::Node& n, const std::string& field,
                                const char* first, const char* second) {
  const auto text = r.string(n, field);
  if (!text) return std::nullopt;
  if (*text == first || *text == second) return *text == second;
  r.error(n, field, "expected " + std::string(first) + " or " + second + ", not '" + *text + "'");
  return std::nullopt;
}

// The input layout fields of scene.build (vulkan/build_layout.h). Strides
// are checked against the formats once the geometries are known
// (checkStrides); here only what every stride must be: aabb_stride a
// multiple of 8 (VUID-VkAccelerationStructureGeometryAabbsDataKHR-stride-03545)
// and at least one box, both at most kMaxInputStride.
void parseBuildLayout(YamlReader& r, const YAML::Node& n, AsBuild& build) {
  const std::string f = "scene.build";
  if (auto v = YamlReader::get(n, "instances_as_pointers"); v.IsDefined())
    build.instances_as_pointers =
        parseTrueFalse(r, v, f + ".instances_as_pointers").value_or(false);
  if (auto v = YamlReader::get(n, "data_offsets"); v.IsDefined())
    build.data_offsets = parseTrueFalse(r, v, f + ".data_offsets").value_or(false);
  if (auto v = YamlReader::get(n, "first_vertex"); v.IsDefined())
    build.first_vertex = r.uint(v, f + ".first_vertex", kMaxFirstVertex).value_or(0);
  if (auto v = YamlReader::get(n, "vertex_stride"); v.IsDefined())
    build.vertex_stride = r.uint(v, f + ".vertex_stride", kMaxInputStride).value_or(0);
  if (auto v = YamlReader::get(n, "aabb_stride"); v.IsDefined()) {
    build.aabb_stride = r.uint(v, f + ".aabb_stride", kMaxInputStride).value_or(0);
    if (build.aabb_stride && (build.aabb_stride < 24 || build.aabb_stride % 8))
      r.error(v, f + ".aabb_stride",
              std::to_string(build.aabb_stride) +
                  ": at least 24 (one box) and a multiple of 8 "
                  "(VUID-VkAccelerationStructureGeometryAabbsDataKHR-stride-03545)");
  }
}

// scene.build.vertex_stride against every triangle geometry's format: at
// least one vertex, a multiple of its component size
// (VUID-VkAccelerationStructureGeometryTrianglesDataKHR-vertexStride-03735).
void checkStrides(YamlReader& r, const YAML::Node& n, const Scene& scene) {
  const uint32_t stride = scene.build.vertex_stride;
  if (!stride) return;
  for (const Blas& b : scene.blases)
    for (const Geometry& g : b.geometries) {
      if (g.kind != Geometry::Kind::Triangles) continue;
      const uint32_t vertex = vertexStride(g.vertex_format);
      const uint32_t component = vertexComponentBytes(g.vertex_format);
      if (stride >= vertex && stride % component == 0) continue;
      r.error(YamlReader::get(n, "vertex_stride"), "scene.build.vertex_stride",
              std::to_string(stride) + " does not fit " + vertexFormatName(g.vertex_format) +
                  " (BLAS '" + b.name + "'): at least " + std::to_string(vertex) +
                  " bytes and a multiple of " + std::to_string(component));
      return;
    }
}

// One name of scene.build.sparse set in `sparse`; false when it names none.
bool setSparse(const std::string& name, SparseBuffers& sparse) {
#define RAYSPEC_SPARSE_NAMED(id, text) \
  if (name == text) return sparse.id = true;
  RAYSPEC_SPARSE_BUFFERS(RAYSPEC_SPARSE_NAMED)
#undef RAYSPEC_SPARSE_NAMED
  return false;
}

// scene.build.sparse: true or all (every buffer), false or none, one name
// or a list of names (structures, scratch, instances, geometry).
void parseSparse(YamlReader& r, const YAML::Node& v, SparseBuffers& sparse) {
  const std::string f = "scene.build.sparse";
  std::vector<YAML::Node> items;
  if (v.IsSequence())
    for (const YAML::Node& item : v) items.push_back(item);
  else
    items.push_back(v);
  for (const YAML::Node& item : items) {
    const auto name = r.string(item, f);
    if (!name) continue;
    if (*name == "true" || *name == "all")
      sparse = SparseBuffers::every();
    else if (*name != "false" && *name != "none" && !setSparse(*name, sparse))
      r.error(item, f,
              "unknown buffer '" + *name +
                  "' (true, false, all, none, structures, scratch, instances, geometry)");
  }
}

// scene.build.storage: own, shared or reused; not with sparse (whose
// buffers place each structure across a page boundary of its own) nor with
// host queries (whose structures are in host-visible memory).
void parseStorage(YamlReader& r, const YAML::Node& n, AsBuild& build) {
  const std::string f = "scene.build.storage";
  const YAML::Node v = YamlReader::get(n, "storage");
  if (!v.IsDefined()) return;
  const auto name = r.string(v, f);
  if (!name) return;
  if (const auto storage = valueNamed<StructureStorage>(*name))
    build.storage = *storage;
  else
    r.error(v, f,
            "unknown storage '" + *name + "' (" + namesJoined(enumNames<StructureStorage>()) + ")");
  if (build.storage != StructureStorage::Own && build.sparse.structures)
    r.error(v, f, "a shared or reused storage is not combined with scene.build.sparse structures");
  if (build.storage != StructureStorage::Own && build.queries.command == QueryCommand::Host)
    r.error(v, f,
            "a shared or reused storage is device memory: not combined with "
            "scene.build.query_command host");
}

// scene.build: {flags: [..], copy: none | clone | compact, layout fields}
// (R-AS-COPY).
void parseBuild(YamlReader& r, const YAML::Node& n, AsBuild& build) {
  const std::string f = "scene.build";
  if (!r.expectMap(
          n, f,
          {"flags", "copy", "order", "instances_as_pointers", "data_offsets", "first_vertex",
           "vertex_stride", "aabb_stride", "one_by_one", "update_into", "tlas_update", "command",
           "generic", "sparse", "storage", "queries", "query_command"}))
    return;
  parseBuildLayout(r, n, build);
  parseStructureQueries(r, n, build);
  if (auto v = YamlReader::get(n, "command"); v.IsDefined())
    if (const auto name = r.string(v, f + ".command")) {
      if (const auto command = valueNamed<BuildCommand>(*name))
        build.command = *command;
      else
        r.error(v, f + ".command",
                "unknown build command '" + *name + "' (" + namesJoined(enumNames<BuildCommand>()) +
                    ")");
    }
  if (auto v = YamlReader::get(n, "generic"); v.IsDefined())
    if (const auto name = r.string(v, f + ".generic")) {
      if (const auto levels = valueNamed<GenericLevels>(*name))
        build.generic = *levels;
      else
        r.error(v, f + ".generic",
                "unknown levels '" + *name + "' (" + namesJoined(enumNames<GenericLevels>()) + ")");
    }
  if (auto v = YamlReader::get(n, "sparse"); v.IsDefined()) parseSparse(r, v, build.sparse);
  parseStorage(r, n, build);
  if (auto v = YamlReader::get(n, "one_by_one"); v.IsDefined())
    build.one_by_one = parseTrueFalse(r, v, f + ".one_by_one").value_or(false);
  if (auto v = YamlReader::get(n, "update_into"); v.IsDefined())
    build.update_into_other =
        parseEither(r, v, f + ".update_into", "same", "other").value_or(false);
  if (auto v = YamlReader::get(n, "tlas_update"); v.IsDefined())
    build.tlas_rebuilt = parseEither(r, v, f + ".tlas_update", "update", "rebuild").value_or(false);
  if (auto v = YamlReader::get(n, "flags"); v.IsDefined())
    if (auto x = r.flags(v, f + ".flags", buildFlagNames())) {
      if ((*x & kBuildPreferFastTrace) && (*x & kBuildPreferFastBuild))
        r.error(v, f + ".flags",
                "prefer_fast_trace and prefer_fast_build together "
                "(VUID-VkAccelerationStructureBuildGeometryInfoKHR-flags-03796)");
      build.flags = *x;
    }
  const YAML::Node copy = YamlReader::get(n, "copy");
  if (!copy.IsDefined()) return;
  const auto name = r.string(copy, f + ".copy");
  if (!name) return;
  for (AsCopy c : {AsCopy::None, AsCopy::Clone, AsCopy::Compact, AsCopy::Serialize})
    if (*name == asCopyName(c)) {
      build.copy = c;
      return;
    }
  r.error(copy, f + ".copy", "unknown copy '" + *name + "' (none, clone, compact, serialize)");
}

}  // namespace

const char* asCopyName(AsCopy c) {
  return nameOf(c);
}

void parseScene(YamlReader& r, const YAML::Node& n, Scene& scene) {
  if (!r.expectMap(n, "scene", {"blas", "instances", "build", "update", "split"})) return;
  if (auto b = YamlReader::get(n, "build"); b.IsDefined()) parseBuild(r, b, scene.build);
  if (auto b = YamlReader::get(n, "blas"); b.IsDefined() && !b.IsNull()) parseBlases(r, b, scene);
  const YAML::Node insts = YamlReader::get(n, "instances");
  if (insts.IsDefined() && !insts.IsNull() && insts.IsSequence() && insts.size() > kMaxInstances)
    r.error(insts, "scene.instances",
            std::to_string(insts.size()) + " instances: at most 2^20 (docs/robustness.md, Limits)");
  else if (insts.IsDefined() && !insts.IsNull() && r.expectSeq(insts, "scene.instances"))
    for (size_t i = 0; i < insts.size(); ++i) {
      const std::string field = "scene.instances[" + std::to_string(i) + "]";
      if (insts[i].IsMap() && YamlReader::has(insts[i], "grid")) {
        parseInstanceGrid(r, insts[i], field, scene);
        continue;
      }
      Instance inst;
      parseInstance(r, insts[i], field, scene, inst);
      scene.instances.push_back(inst);
    }
  if (auto u = YamlReader::get(n, "update"); u.IsDefined()) parseSceneUpdate(r, u, scene);
  if (auto b = YamlReader::get(n, "build"); b.IsMap()) {
    if (auto o = YamlReader::get(b, "order"); o.IsDefined()) parseBuildOrder(r, o, scene);
    checkStrides(r, b, scene);
    if (scene.build.update_into_other && scene.build.copy != AsCopy::None)
      r.error(YamlReader::get(b, "update_into"), "scene.build.update_into",
              "an update into another structure is not combined with a copy (scene.build.copy)");
  }
}

std::optional<bool> parseTrueFalse(YamlReader& r, const YAML::Node& n, const std::string& field) {
  const auto text = r.string(n, field);
  if (!text) return std::nullopt;
  if (*text == "true" || *text == "false") return *text == "true";
  r.error(n, field, "expected true or false, not '" + *text + "'");
  return std::nullopt;
}

}  // namespace rayspec
