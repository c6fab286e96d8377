// The scene of a generated case: BLASes of triangles (explicit, in any
// vertex format, or a mesh shape) or boxes, instances over them, and the
// hit-group ranges their SBT offsets reach. Every geometry and instance is
// kept (CaseGenerator::Blas::data, instances_) for the updates and the
// aimed rays.
#include <cmath>
#include <cstdio>

#include "case/transform.h"
#include "case/triangle_fan.h"
#include "case/triangle_grid.h"
#include "case/triangulation.h"
#include "fuzz/case_generator.h"

namespace rayspec {

double CaseGenerator::eighths(double lo, double hi) {
  return std::round(rng_.range(lo, hi) * 8.0) / 8.0;
}

std::string CaseGenerator::num(double v) {
  if (std::isnan(v)) return ".nan";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  std::string s = buf;
  if (s.find_first_of(".en") == std::string::npos) s += ".0";
  return s;
}

std::string CaseGenerator::vec3(double lo, double hi) {
  const double x = eighths(lo, hi), y = eighths(lo, hi), z = eighths(lo, hi);
  return "[" + num(x) + ", " + num(y) + ", " + num(z) + "]";
}

namespace {

std::string point(const Vec3& v) {
  return "[" + CaseGenerator::num(v[0]) + ", " + CaseGenerator::num(v[1]) + ", " +
         CaseGenerator::num(v[2]) + "]";
}

std::string numbers(const Transform& m) {
  std::string s;
  for (size_t i = 0; i < m.size(); ++i) s += (i ? ", " : "") + CaseGenerator::num(m[i]);
  return "[" + s + "]";
}

}  // namespace

// 1 to 4 triangles, indexed or not, one vertex NaN now and then (the
// triangles through it inactive), in a vertex format drawn for them.
void CaseGenerator::explicitTriangles(Geometry& g) {
  const size_t triangles = 1 + pick(4);
  const bool indexed = chance(0.4);
  const size_t vertices = indexed ? triangles + 2 : 3 * triangles;
  const std::string format = drawFormat(g);
  const size_t nan_vertex =
      chance(0.15) && !vertexNormalized(g.vertex_format) ? pick(vertices) : vertices;
  std::string v;
  for (size_t i = 0; i < vertices; ++i) {
    Vec3 p = drawVertex(g.vertex_format);
    if (i == nan_vertex) p[0] = NAN;
    g.vertices.push_back(p);
    v += (i ? ", " : "") + point(p);
  }
  out_ += "      - triangles:\n          vertices: [" + v + "]\n";
  features_.insert(indexed ? "indexed" : "non-indexed");
  if (indexed) {
    std::string idx;
    for (size_t t = 0; t < triangles; ++t) {
      const uint64_t a = pick(vertices), b = (a + 1 + pick(vertices - 1)) % vertices;
      uint64_t c = pick(vertices);
      while (c == a || c == b) c = (c + 1) % vertices;
      for (uint64_t i : {a, b, c}) g.indices.push_back(uint32_t(i));
      idx += std::string(t ? ", " : "") + std::to_string(a) + ", " + std::to_string(b) + ", " +
             std::to_string(c);
    }
    out_ += "          indices: [" + idx + "]\n";
    if (chance(0.3)) out_ += "          index_type: uint16\n";
  }
  out_ += format;
}

// Explicit triangles, or now and then a mesh shape of shared edges and
// closed vertices (a fan, a grid, a seeded triangulation) for aimed rays to
// meet where floating point decides; a geometry transform now and then.
bool CaseGenerator::triangleGeometry(Geometry& g) {
  const uint64_t shape = chance(0.25) ? 1 + pick(3) : 0;
  const double cx = eighths(-1, 1), cy = eighths(-1, 1), cz = eighths(-1, 1);
  const std::string center = "[" + num(cx) + ", " + num(cy) + ", " + num(cz) + "]";
  if (shape == 0) {
    explicitTriangles(g);
  } else if (shape == 1) {
    const FanSpec fan{uint32_t(3 + pick(6)), eighths(0.5, 2), {cx, cy, cz}, pick(4)};
    makeTriangleFan(fan, g);
    out_ += "      - triangles: {fan: {triangles: " + std::to_string(fan.triangles) +
            ", radius: " + num(fan.radius) + ", center: " + center +
            ", seed: " + std::to_string(fan.seed) + "}}\n";
  } else {
    const uint32_t x = uint32_t(1 + pick(4)), y = uint32_t(1 + pick(4));
    const std::array<double, 2> size{eighths(1, 3), eighths(1, 3)};
    const std::string common = "cells: [" + std::to_string(x) + ", " + std::to_string(y) +
                               "], size: [" + num(size[0]) + ", " + num(size[1]) +
                               "], center: " + center;
    if (shape == 2) {
      makeTriangleGrid(x, y, size, {cx, cy, cz}, g);
      out_ += "      - triangles: {grid: {" + common + "}}\n";
    } else {
      const TriangulationSpec t{x, y, size, {cx, cy, cz}, 1 + pick(1000), 0.25};
      makeTriangulation(t, g);
      out_ += "      - triangles: {triangulation: {" + common +
              ", seed: " + std::to_string(t.seed) + "}}\n";
    }
  }
  if (shape) features_.insert("mesh-shape");
  if (chance(0.15)) {
    features_.insert("geometry-transform");
    Transform m;
    transform(m);
    if (m != kIdentity) {
      g.transform = m;
      out_ += "        transform: " + numbers(m) + "\n";
    }
  }
  return shape != 0;
}

std::array<float, 6> CaseGenerator::drawBox() {
  std::array<float, 6> box;
  for (int k = 0; k < 3; ++k) {
    box[k] = float(eighths(-2, 1.5));
    box[3 + k] = box[k] + float(eighths(0.25, 1.5));
  }
  return box;
}

// 1 to 3 boxes, one with a NaN minimum x now and then (inactive).
void CaseGenerator::aabbGeometry(Geometry& g) {
  g.kind = Geometry::Kind::Aabbs;
  const size_t boxes = 1 + pick(3);
  std::string b;
  for (size_t i = 0; i < boxes; ++i) {
    std::array<float, 6> box = drawBox();
    if (chance(0.12)) box[0] = NAN;
    g.aabbs.push_back(box);
    std::string text;
    for (float v : box) text += (text.empty() ? "" : ", ") + num(v);
    b += std::string(i ? ", " : "") + "[" + text + "]";
  }
  out_ += "      - aabbs: [" + b + "]\n";
}

void CaseGenerator::blasList() {
  const size_t count = 1 + pick(3);
  if (count > 1) features_.insert("several-blas");
  out_ += "  blas:\n";
  for (size_t i = 0; i < count; ++i) {
    Blas blas{"b" + std::to_string(i), chance(0.4), 1 + pick(3), {}, {}};
    if (blas.geometries > 1) features_.insert("several-geometries");
    features_.insert(blas.aabbs ? "aabbs" : "triangles");
    out_ += "    " + blas.name + ":\n";
    for (size_t k = 0; k < blas.geometries; ++k) {
      Geometry g;
      bool shaped = false;
      if (blas.aabbs)
        aabbGeometry(g);
      else
        shaped = triangleGeometry(g);
      blas.shaped.push_back(shaped);
      std::string flags;
      if (chance(0.5)) flags = "opaque";
      if (chance(0.7)) flags += std::string(flags.empty() ? "" : ", ") + "no_duplicate_any_hit";
      if (flags.find("opaque") != 0) features_.insert("non-opaque-geometry");
      out_ += "        flags: [" + flags + "]\n";
      blas.data.push_back(std::move(g));
    }
    blas_.push_back(blas);
  }
}

// translate * rotate * scale, each drawn; scales non-uniform, negative ones
// mirror. `m`: the matrix the case parser makes of it.
std::string CaseGenerator::transform(Transform& m) {
  m = kIdentity;
  if (chance(0.2)) return "identity";
  TransformParts parts;
  const double tx = eighths(-2, 2), ty = eighths(-2, 2), tz = eighths(-2, 2);
  parts.translate = {tx, ty, tz};
  std::string t = "{translate: [" + num(tx) + ", " + num(ty) + ", " + num(tz) + "]";
  if (chance(0.6)) {
    features_.insert("rotation");
    double a[3] = {eighths(-1, 1), eighths(-1, 1), eighths(-1, 1)};
    if (a[0] == 0 && a[1] == 0 && a[2] == 0) a[2] = 1;
    parts.axis = {a[0], a[1], a[2]};
    parts.degrees = eighths(-180, 180);
    t += ", rotate: {axis: [" + num(a[0]) + ", " + num(a[1]) + ", " + num(a[2]) +
         "], degrees: " + num(parts.degrees) + "}";
  }
  if (chance(0.6)) {
    double s[3];
    for (double& v : s) {
      v = eighths(0.5, 2);
      if (chance(0.2)) {
        v = -v;
        features_.insert("mirror");
      }
    }
    if (s[0] != s[1] || s[1] != s[2]) features_.insert("non-uniform-scale");
    parts.scale = {s[0], s[1], s[2]};
    t += ", scale: [" + num(s[0]) + ", " + num(s[1]) + ", " + num(s[2]) + "]";
  }
  m = composeTransform(parts);
  return t + "}";
}

std::string CaseGenerator::instanceFlags() {
  static const std::vector<std::string> kFlags = {
      "triangle_facing_cull_disable", "triangle_flip_facing", "force_opaque", "force_no_opaque"};
  if (!chance(0.35)) return "";
  features_.insert("instance-flags");
  const size_t a = pick(kFlags.size());
  std::string flags = kFlags[a];
  const size_t b = pick(kFlags.size());
  // force_opaque and force_no_opaque together are invalid
  // (VUID-VkAccelerationStructureInstanceKHR-flags).
  if (b != a && a + b != 5 && chance(0.4)) flags += ", " + kFlags[b];
  return flags;
}

// A custom index: small, or anywhere in its 24 bits.
static uint64_t customIndex(CaseGenerator& g, std::set<std::string>& features) {
  if (g.chance(0.5)) return g.pick(1000);
  features.insert("custom-index-24");
  return 0x10000 + g.pick((1u << 24) - 0x10000);
}

void CaseGenerator::instance() {
  if (chance(0.06)) {
    out_ += "    - {blas: null}\n";
    instances_.emplace_back();
    return;
  }
  const size_t b = pick(blas_.size());
  const Blas& blas = blas_[b];
  // A range of hit groups of its own, or one an earlier instance of the same BLAS reaches.
  size_t first = hit_groups_;
  std::vector<size_t> same;
  for (size_t r = 0; r < ranges_.size(); ++r)
    if (ranges_[r].blas == b) same.push_back(r);
  if (!same.empty() && chance(0.4)) {
    first = ranges_[oneOf(same)].first;
  } else {
    ranges_.push_back({first, blas.geometries, blas.aabbs, b});
    for (size_t g = 0; g < blas.geometries; ++g) group_aabbs_.push_back(blas.aabbs);
    hit_groups_ += blas.geometries;
  }
  if (first) features_.insert("sbt-offset");
  Placed placed{b, kIdentity};
  std::string line = "    - {blas: " + blas.name + ", transform: " + transform(placed.transform);
  if (chance(0.35)) {
    features_.insert("instance-mask");
    line += ", mask: " +
            std::to_string(chance(0.5) ? oneOf<int>({1, 2, 3, 0x80, 0xFE}) : int(1 + pick(255)));
  }
  line += ", custom_index: " + std::to_string(customIndex(*this, features_)) +
          ", sbt_offset: " + std::to_string(first);
  const std::string flags = instanceFlags();
  if (!flags.empty()) line += ", flags: [" + flags + "]";
  out_ += line + "}\n";
  instances_.push_back(placed);
}

void CaseGenerator::scene() {
  out_ += "scene:\n";
  buildLayout();
  blasList();
  out_ += "  instances:\n";
  const size_t count = 1 + pick(4);
  for (size_t i = 0; i < count; ++i) instance();
  if (hit_groups_ == 0) {  // every instance inactive: one group all the same
    group_aabbs_.push_back(false);
    hit_groups_ = 1;
  }
  updates();
}

}  // namespace rayspec
