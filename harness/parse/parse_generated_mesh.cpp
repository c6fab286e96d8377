// The generated meshes of a `triangles` map: grid, fan, triangulation,
// subdivision; the
// generated boxes of an `aabbs` map and instances of a `scene.instances` entry.
#include "case/box_grid.h"
#include "case/subdivision.h"
#include "case/triangle_fan.h"
#include "case/triangle_grid.h"
#include "case/triangulation.h"
#include "parse/parse_parts.h"

namespace rayspec {
namespace {

constexpr uint64_t kMaxCells = 1u << 22;

// cells: [x, y] with 1 <= x * y <= 2^22.
std::optional<std::array<uint32_t, 2>> parseCells(YamlReader& r, const YAML::Node& cells,
                                                  const std::string& f) {
  if (!cells.IsSequence() || cells.size() != 2) {
    r.error(cells, f, "expected [x, y] cell counts");
    return std::nullopt;
  }
  auto cx = r.uint(cells[0], f + "[0]", 4096);
  auto cy = r.uint(cells[1], f + "[1]", 4096);
  if (!cx || !cy) return std::nullopt;
  if (*cx == 0 || *cy == 0 || uint64_t(*cx) * *cy > kMaxCells) {
    r.error(cells, f, "cell counts must be at least 1, at most 2^22 cells in all");
    return std::nullopt;
  }
  return std::array<uint32_t, 2>{*cx, *cy};
}

std::optional<std::array<double, 3>> parseCenter(YamlReader& r, const YAML::Node& m,
                                                 const std::string& f) {
  if (!YamlReader::has(m, "center")) return std::array<double, 3>{0, 0, 0};
  return r.numbers<3>(YamlReader::get(m, "center"), f + ".center");
}

bool parseGrid(YamlReader& r, const YAML::Node& grid, const std::string& f, Geometry& g) {
  if (!r.expectMap(grid, f, {"cells", "size", "center"}) ||
      !(r.require(grid, f, "cells") & r.require(grid, f, "size")))
    return false;
  auto cells = parseCells(r, YamlReader::get(grid, "cells"), f + ".cells");
  auto size = r.numbers<2>(YamlReader::get(grid, "size"), f + ".size");
  auto center = parseCenter(r, grid, f);
  if (!cells || !size || !center) return false;
  makeTriangleGrid((*cells)[0], (*cells)[1], *size, *center, g);
  return true;
}

bool parseFan(YamlReader& r, const YAML::Node& fan, const std::string& f, Geometry& g) {
  if (!r.expectMap(fan, f, {"triangles", "radius", "center", "seed"}) ||
      !r.require(fan, f, "triangles"))
    return false;
  FanSpec spec;
  auto n = r.uint(YamlReader::get(fan, "triangles"), f + ".triangles", 1u << 20);
  if (!n) return false;
  if (*n < 3) {
    r.error(YamlReader::get(fan, "triangles"), f + ".triangles",
            "a closed fan needs at least 3 triangles");
    return false;
  }
  spec.triangles = *n;
  if (YamlReader::has(fan, "radius")) {
    auto radius = r.number(YamlReader::get(fan, "radius"), f + ".radius");
    if (!radius) return false;
    if (!(*radius > 0)) {
      r.error(YamlReader::get(fan, "radius"), f + ".radius", "the radius must be positive");
      return false;
    }
    spec.radius = *radius;
  }
  auto center = parseCenter(r, fan, f);
  if (!center) return false;
  spec.center = *center;
  if (YamlReader::has(fan, "seed")) {
    auto seed = r.uint(YamlReader::get(fan, "seed"), f + ".seed");
    if (!seed) return false;
    spec.seed = *seed;
  }
  makeTriangleFan(spec, g);
  return true;
}

bool parseTriangulation(YamlReader& r, const YAML::Node& m, const std::string& f, Geometry& g) {
  if (!r.expectMap(m, f, {"cells", "size", "center", "seed", "jitter"}) ||
      !(r.require(m, f, "cells") & r.require(m, f, "size") & r.require(m, f, "seed")))
    return false;
  TriangulationSpec spec;
  auto cells = parseCells(r, YamlReader::get(m, "cells"), f + ".cells");
  auto size = r.numbers<2>(YamlReader::get(m, "size"), f + ".size");
  auto center = parseCenter(r, m, f);
  auto seed = r.uint(YamlReader::get(m, "seed"), f + ".seed");
  if (!cells || !size || !center || !seed) return false;
  if (YamlReader::has(m, "jitter")) {
    auto jitter = r.number(YamlReader::get(m, "jitter"), f + ".jitter");
    if (!jitter) return false;
    if (!(*jitter >= 0 && *jitter <= 0.25)) {
      r.error(YamlReader::get(m, "jitter"), f + ".jitter",
              "jitter must be in [0, 0.25] (of a cell)");
      return false;
    }
    spec.jitter = *jitter;
  }
  spec.cells_x = (*cells)[0];
  spec.cells_y = (*cells)[1];
  spec.size = *size;
  spec.center = *center;
  spec.seed = *seed;
  makeTriangulation(spec, g);
  return true;
}

// subdivision: {triangles: N, size: [w, h], center, relief, seed}.
bool parseSubdivision(YamlReader& r, const YAML::Node& m, const std::string& f, Geometry& g) {
  if (!r.expectMap(m, f, {"triangles", "size", "center", "relief", "seed"}) ||
      !(r.require(m, f, "triangles") & r.require(m, f, "size") & r.require(m, f, "seed")))
    return false;
  SubdivisionSpec spec;
  auto n = r.uint(YamlReader::get(m, "triangles"), f + ".triangles", 1u << 20);
  auto size = r.numbers<2>(YamlReader::get(m, "size"), f + ".size");
  auto center = parseCenter(r, m, f);
  auto seed = r.uint(YamlReader::get(m, "seed"), f + ".seed");
  std::optional<double> relief = 0.0;
  if (YamlReader::has(m, "relief")) relief = r.number(YamlReader::get(m, "relief"), f + ".relief");
  if (!n || !size || !center || !seed || !relief) return false;
  if (!((*size)[0] > 0 && (*size)[1] > 0 && *relief >= 0)) {
    r.error(m, f, "size must be positive and relief not negative");
    return false;
  }
  spec.triangles = *n;
  spec.size = *size;
  spec.center = *center;
  spec.relief = *relief;
  spec.seed = *seed;
  if (Result<void> made = makeSubdivision(spec, g); !made) {
    r.error(YamlReader::get(m, "triangles"), f + ".triangles", made.error().message);
    return false;
  }
  return true;
}

}  // namespace

bool parseBoxGrid(YamlReader& r, const YAML::Node& n, const std::string& field, Geometry& g) {
  g.kind = Geometry::Kind::Aabbs;
  const std::string f = field + ".grid";
  if (!r.expectMap(n, field, {"grid"}) || !r.require(n, field, "grid")) return false;
  const YAML::Node grid = YamlReader::get(n, "grid");
  if (!r.expectMap(grid, f, {"cells", "size", "center", "height"}) ||
      !(r.require(grid, f, "cells") & r.require(grid, f, "size") & r.require(grid, f, "height")))
    return false;
  auto cells = parseCells(r, YamlReader::get(grid, "cells"), f + ".cells");
  auto size = r.numbers<2>(YamlReader::get(grid, "size"), f + ".size");
  auto center = parseCenter(r, grid, f);
  auto height = r.number(YamlReader::get(grid, "height"), f + ".height");
  if (!cells || !size || !center || !height) return false;
  if (!((*size)[0] > 0 && (*size)[1] > 0 && *height >= 0)) {
    r.error(grid, f, "size must be positive and height not negative");
    return false;
  }
  makeBoxGrid((*cells)[0], (*cells)[1], *size, *center, *height, g);
  return true;
}

void parseInstanceGrid(YamlReader& r, const YAML::Node& n, const std::string& field, Scene& scene) {
  const std::string f = field + ".grid";
  const YAML::Node grid = YamlReader::get(n, "grid");
  if (!r.expectMap(n, field, {"grid"}) ||
      !r.expectMap(grid, f, {"cells", "spacing", "origin", "instance"}) ||
      !(r.require(grid, f, "cells") & r.require(grid, f, "spacing") &
        r.require(grid, f, "instance")))
    return;
  auto cells = parseCells(r, YamlReader::get(grid, "cells"), f + ".cells");
  auto spacing = r.numbers<2>(YamlReader::get(grid, "spacing"), f + ".spacing");
  std::optional<std::array<double, 3>> origin = std::array<double, 3>{0, 0, 0};
  if (YamlReader::has(grid, "origin"))
    origin = r.numbers<3>(YamlReader::get(grid, "origin"), f + ".origin");
  if (!cells || !spacing || !origin) return;
  const uint64_t total = scene.instances.size() + uint64_t((*cells)[0]) * (*cells)[1];
  if (total > kMaxInstances) {
    r.error(grid, f + ".cells",
            std::to_string(total) + " instances: at most 2^20 (docs/robustness.md, Limits)");
    return;
  }
  Instance proto;
  const YAML::Node inst = YamlReader::get(grid, "instance");
  parseInstance(r, inst, f + ".instance", scene, proto);
  if (YamlReader::has(inst, "transform") || YamlReader::has(inst, "custom_index")) {
    r.error(inst, f + ".instance",
            "a grid's instances take their translation and custom index from the grid");
    return;
  }
  appendInstanceGrid(proto, (*cells)[0], (*cells)[1], *spacing, *origin, scene.instances);
}

std::optional<bool> parseGeneratedMesh(YamlReader& r, const YAML::Node& n, const std::string& field,
                                       Geometry& g) {
  const char* names[] = {"grid", "fan", "triangulation", "subdivision"};
  int given = 0;
  const char* name = nullptr;
  for (const char* k : names)
    if (YamlReader::has(n, k)) {
      ++given;
      name = k;
    }
  if (!given) return std::nullopt;
  if (given > 1 || YamlReader::has(n, "vertices") || YamlReader::has(n, "indices")) {
    r.error(n, field,
            "a generated mesh (grid, fan, triangulation or subdivision) is one of them alone, "
            "without vertices "
            "or indices");
    return false;
  }
  const std::string f = field + "." + name;
  const YAML::Node m = YamlReader::get(n, name);
  if (name == std::string("grid")) return parseGrid(r, m, f, g);
  if (name == std::string("fan")) return parseFan(r, m, f, g);
  if (name == std::string("subdivision")) return parseSubdivision(r, m, f, g);
  return parseTriangulation(r, m, f, g);
}

}  // namespace rayspec
