// scene.update (R-AS-UPDATE): what an update of the built structures moves.
//   update:
//     blas:
//       NAME: [{vertices: [...]}, {aabbs: [...]}, {}]   # one entry a geometry
//     instances:
//       - {instance: 1, transform: ..., mask: .., custom_index: .., sbt_offset: ..}
// or a list of such updates (at most kMaxUpdates), each applied in place to
// what the one before left.
// Triangles get new vertex positions (as many as before), boxes new boxes (as
// many as before), `{}` keeps a geometry; an instance gets a new transform,
// mask, custom index or SBT offset. Counts, indices, flags and the BLAS an
// instance references stay: an update that changed them would be undefined
// (VUID-vkCmdBuildAccelerationStructuresKHR-pInfos-03758 and the like), and
// so would one that made an inactive primitive active or an active one
// inactive (-03663, -03664): new positions that do are an error naming the
// primitive. Positions may otherwise go anywhere: a triangle or box may
// become degenerate or stop being so (both are active).
#include <cmath>

#include "case/flag_names.h"
#include "case/inactive.h"
#include "case/transform.h"
#include "parse/parse_parts.h"

namespace rayspec {
namespace {

// A new position, as the geometry's vertex format stores it.
void setVertex(YamlReader& r, const YAML::Node& n, const std::string& f, Geometry& g, size_t i,
               const Vec3& v) {
  if (const std::string problem = vertexFormatProblem(g.vertex_format, v); !problem.empty()) {
    r.error(n, f, problem);
    return;
  }
  if (!g.written.empty()) g.written[i] = v;
  g.vertices[i] = storedVertex(g.vertex_format, v);
}

// R-AS-UPDATE: the first primitive of `g` whose inactive state (R-INACTIVE)
// differs from `before`'s, an error at `list` (field fl).
void checkActiveStateKept(YamlReader& r, const YAML::Node& list, const std::string& fl,
                          const Geometry& before, const Geometry& g) {
  for (uint32_t p = 0; p < g.primitiveCount(); ++p) {
    const bool was = primitiveInactive(before, p), is = primitiveInactive(g, p);
    if (was == is) continue;
    const std::string what = g.kind == Geometry::Kind::Triangles ? "triangle " : "box ";
    r.error(list, fl,
            what + std::to_string(p) +
                (was ? " was inactive (NaN X) and the update makes it active"
                     : " was active and the update makes it inactive "
                       "(NaN X)") +
                ": an update may not change which primitives are active "
                "(VUID-vkCmdBuildAccelerationStructuresKHR-pInfos-03663, -03664), a rebuild may");
    return;
  }
}

// One geometry's new positions or boxes, the same count as before.
void updateGeometry(YamlReader& r, const YAML::Node& n, const std::string& f, Geometry& g) {
  if (n.IsNull()) return;
  const bool triangles = g.kind == Geometry::Kind::Triangles;
  if (!r.expectMap(n, f, {triangles ? "vertices" : "aabbs"})) return;
  const YAML::Node list = YamlReader::get(n, triangles ? "vertices" : "aabbs");
  if (!list.IsDefined()) return;
  const std::string fl = f + (triangles ? ".vertices" : ".aabbs");
  if (!r.expectSeq(list, fl)) return;
  const size_t count = triangles ? g.vertices.size() : g.aabbs.size();
  if (list.size() != count) {
    r.error(list, fl,
            std::to_string(list.size()) + " entries, but the geometry was built with " +
                std::to_string(count) + " (an update keeps every count)");
    return;
  }
  const Geometry before = g;
  for (size_t i = 0; i < count; ++i) {
    const std::string fi = fl + "[" + std::to_string(i) + "]";
    if (triangles) {
      if (auto v = r.numbers<3>(list[i], fi, true))
        setVertex(r, list[i], fi, g, i,
                  {static_cast<float>((*v)[0]), static_cast<float>((*v)[1]),
                   static_cast<float>((*v)[2])});
    } else if (auto v = r.numbers<6>(list[i], fi, true)) {
      for (int k = 0; k < 6; ++k) g.aabbs[i][k] = static_cast<float>((*v)[k]);
    }
  }
  checkActiveStateKept(r, list, fl, before, g);
}

void updateBlases(YamlReader& r, const YAML::Node& n, const std::string& field, Scene& after) {
  if (!n.IsMap()) {
    r.error(n, field + ".blas", "expected a map: BLAS name -> one entry per geometry");
    return;
  }
  for (const auto& kv : n) {
    const std::string name = kv.first.as<std::string>("");
    const std::string f = field + ".blas." + name;
    Blas* blas = nullptr;
    for (Blas& b : after.blases)
      if (b.name == name) blas = &b;
    if (!blas) {
      r.error(kv.first, f, "unknown BLAS '" + name + "'");
      continue;
    }
    if (!r.expectSeq(kv.second, f)) continue;
    if (kv.second.size() != blas->geometries.size()) {
      r.error(kv.second, f,
              std::to_string(kv.second.size()) + " entries, but the BLAS has " +
                  std::to_string(blas->geometries.size()) +
                  " geometries (one entry each, {} "
                  "keeps one)");
      continue;
    }
    for (size_t i = 0; i < kv.second.size(); ++i)
      updateGeometry(r, kv.second[i], f + "[" + std::to_string(i) + "]", blas->geometries[i]);
  }
}

void updateInstances(YamlReader& r, const YAML::Node& n, const std::string& field, Scene& after) {
  const std::string f = field + ".instances";
  if (!r.expectSeq(n, f)) return;
  for (size_t i = 0; i < n.size(); ++i) {
    const std::string fi = f + "[" + std::to_string(i) + "]";
    if (!r.expectMap(n[i], fi, {"instance", "transform", "mask", "custom_index", "sbt_offset"}) ||
        !r.require(n[i], fi, "instance"))
      continue;
    const YAML::Node at = YamlReader::get(n[i], "instance");
    const auto index = r.uint(at, fi + ".instance");
    if (!index) continue;
    if (*index >= after.instances.size()) {
      r.error(at, fi + ".instance",
              "instance " + std::to_string(*index) + ", but the scene has " +
                  std::to_string(after.instances.size()));
      continue;
    }
    // The instance's own reader, on a map that names its BLAS as before.
    Instance& inst = after.instances[*index];
    YAML::Node fields = YAML::Clone(n[i]);
    fields.remove("instance");
    fields["blas"] = YAML::Node(YAML::NodeType::Null);
    Instance moved = inst;
    parseInstance(r, fields, fi, after, moved);
    moved.blas = inst.blas;
    moved.flags = inst.flags;
    moved.tlas = inst.tlas;
    moved.loc = inst.loc;
    inst = moved;
  }
}

// One update (`field`: its place in the file), applied to `scene`.
void parseOneUpdate(YamlReader& r, const YAML::Node& n, const std::string& field, Scene& scene) {
  if (!r.expectMap(n, field, {"blas", "instances"})) return;
  Scene after = scene;
  if (auto b = YamlReader::get(n, "blas"); b.IsDefined()) updateBlases(r, b, field, after);
  if (auto i = YamlReader::get(n, "instances"); i.IsDefined()) updateInstances(r, i, field, after);
  after.build.flags |= kBuildAllowUpdate;
  scene.build.flags |= kBuildAllowUpdate;
  Scene before = scene;
  before.earlier.clear();
  after.earlier.push_back(std::make_shared<const Scene>(std::move(before)));
  scene = std::move(after);
}

}  // namespace

void parseSceneUpdate(YamlReader& r, const YAML::Node& n, Scene& scene) {
  if (!n.IsSequence()) {
    parseOneUpdate(r, n, "scene.update", scene);
    return;
  }
  if (n.size() == 0 || n.size() > kMaxUpdates) {
    r.error(
        n, "scene.update",
        std::to_string(n.size()) + " updates: a list holds 1 to " + std::to_string(kMaxUpdates));
    return;
  }
  for (size_t k = 0; k < n.size(); ++k)
    parseOneUpdate(r, n[k], "scene.update[" + std::to_string(k) + "]", scene);
}

// scene.build.order: [update, copy, update, ...]: each update of scene.update
// once, in its order, and the copy (scene.build.copy) once where it runs.
void parseBuildOrder(YamlReader& r, const YAML::Node& n, Scene& scene) {
  const std::string f = "scene.build.order";
  if (!r.expectSeq(n, f)) return;
  uint32_t updates = 0, copies = 0;
  std::optional<uint32_t> before_copy;
  for (size_t i = 0; i < n.size(); ++i) {
    const auto step = r.string(n[i], f + "[" + std::to_string(i) + "]");
    if (!step) return;
    if (*step == "update") {
      ++updates;
    } else if (*step == "copy") {
      ++copies;
      before_copy = updates;
    } else {
      r.error(n[i], f + "[" + std::to_string(i) + "]",
              "unknown step '" + *step + "' (update, copy)");
      return;
    }
  }
  const bool copied = scene.build.copy != AsCopy::None;
  if (updates != scene.updates() || copies != (copied ? 1u : 0u)) {
    r.error(n, f,
            "names " + std::to_string(updates) + " update(s) and " + std::to_string(copies) +
                " copy, but the scene has " + std::to_string(scene.updates()) +
                " update(s) (scene.update) and " + (copied ? "one copy" : "no copy") +
                " (scene.build.copy): name each once");
    return;
  }
  if (scene.build.copy == AsCopy::Serialize && before_copy && *before_copy < updates) {
    r.error(n, f,
            "an update after a serialize copy: a deserialized structure counts as never built "
            "with ALLOW_UPDATE (VUID-vkCmdBuildAccelerationStructuresKHR-pInfos-03667); copy "
            "last");
    return;
  }
  scene.build.updates_before_copy = before_copy;
}

}  // namespace rayspec
