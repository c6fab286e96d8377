// The scene of a generated case: BLASes of triangles or boxes, instances
// over them, and the hit-group ranges their SBT offsets reach.
#include <cmath>
#include <cstdio>

#include "fuzz/case_generator.h"

namespace rayspec {

double CaseGenerator::eighths(double lo, double hi) {
  return std::round(rng_.range(lo, hi) * 8.0) / 8.0;
}

std::string CaseGenerator::num(double v) {
  if (std::isnan(v)) return ".nan";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  std::string s = buf;
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

std::string CaseGenerator::vec3(double lo, double hi) {
  const double x = eighths(lo, hi), y = eighths(lo, hi), z = eighths(lo, hi);
  return "[" + num(x) + ", " + num(y) + ", " + num(z) + "]";
}

// 1 to 4 triangles, indexed or not, one vertex NaN now and then (the
// triangles through it inactive).
void CaseGenerator::triangleGeometry() {
  const size_t triangles = 1 + pick(4);
  const bool indexed = chance(0.4);
  const size_t vertices = indexed ? triangles + 2 : 3 * triangles;
  const size_t nan_vertex = chance(0.15) ? pick(vertices) : vertices;
  if (nan_vertex < vertices) features_.insert("nan-vertex");
  std::string v;
  for (size_t i = 0; i < vertices; ++i) {
    std::string p =
        "[" + num(eighths(-2, 2)) + ", " + num(eighths(-2, 2)) + ", " + num(eighths(-1, 1)) + "]";
    if (i == nan_vertex) p = "[.nan, " + num(eighths(-2, 2)) + ", 0.0]";
    v += (i ? ", " : "") + p;
  }
  out_ += "      - triangles:\n          vertices: [" + v + "]\n";
  features_.insert(indexed ? "indexed" : "non-indexed");
  if (indexed) {
    std::string idx;
    for (size_t t = 0; t < triangles; ++t) {
      const uint64_t a = pick(vertices), b = (a + 1 + pick(vertices - 1)) % vertices;
      uint64_t c = pick(vertices);
      while (c == a || c == b) c = (c + 1) % vertices;
      idx += std::string(t ? ", " : "") + std::to_string(a) + ", " + std::to_string(b) + ", " +
             std::to_string(c);
    }
    out_ += "          indices: [" + idx + "]\n";
    if (chance(0.3)) out_ += "          index_type: uint16\n";
  }
}

// 1 to 3 boxes, one with a NaN minimum x now and then (inactive).
void CaseGenerator::aabbGeometry() {
  const size_t boxes = 1 + pick(3);
  std::string b;
  for (size_t i = 0; i < boxes; ++i) {
    double lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
      lo[k] = eighths(-2, 1.5);
      hi[k] = lo[k] + eighths(0.25, 1.5);
    }
    const bool nan = chance(0.12);
    if (nan) features_.insert("nan-box");
    b += std::string(i ? ", " : "") + "[" + (nan ? std::string(".nan") : num(lo[0])) + ", " +
         num(lo[1]) + ", " + num(lo[2]) + ", " + num(hi[0]) + ", " + num(hi[1]) + ", " +
         num(hi[2]) + "]";
  }
  out_ += "      - aabbs: [" + b + "]\n";
}

void CaseGenerator::blasList() {
  const size_t count = 1 + pick(3);
  if (count > 1) features_.insert("several-blas");
  out_ += "  blas:\n";
  for (size_t i = 0; i < count; ++i) {
    Blas blas{"b" + std::to_string(i), chance(0.4), 1 + pick(3)};
    if (blas.geometries > 1) features_.insert("several-geometries");
    features_.insert(blas.aabbs ? "aabbs" : "triangles");
    out_ += "    " + blas.name + ":\n";
    for (size_t g = 0; g < blas.geometries; ++g) {
      if (blas.aabbs)
        aabbGeometry();
      else
        triangleGeometry();
      std::string flags;
      if (chance(0.5)) flags = "opaque";
      if (chance(0.7)) flags += std::string(flags.empty() ? "" : ", ") + "no_duplicate_any_hit";
      if (flags.find("opaque") != 0) features_.insert("non-opaque-geometry");
      out_ += "        flags: [" + flags + "]\n";
    }
    blas_.push_back(blas);
  }
}

// translate * rotate * scale, each drawn; scales non-uniform, negative ones
// mirror.
std::string CaseGenerator::transform() {
  if (chance(0.2)) return "identity";
  std::string t = "{translate: " + vec3(-2, 2);
  if (chance(0.6)) {
    features_.insert("rotation");
    std::string axis = vec3(-1, 1);
    if (axis == "[0.0, 0.0, 0.0]") axis = "[0.0, 0.0, 1.0]";
    t += ", rotate: {axis: " + axis + ", degrees: " + num(eighths(-180, 180)) + "}";
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
    t += ", scale: [" + num(s[0]) + ", " + num(s[1]) + ", " + num(s[2]) + "]";
  }
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

void CaseGenerator::instance() {
  if (chance(0.06)) {
    features_.insert("inactive-instance");
    out_ += "    - {blas: null}\n";
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
  std::string line = "    - {blas: " + blas.name + ", transform: " + transform();
  if (chance(0.35)) {
    features_.insert("instance-mask");
    line += ", mask: " + std::to_string(oneOf<int>({1, 2, 3, 0x80, 0xFE}));
  }
  line +=
      ", custom_index: " + std::to_string(pick(1000)) + ", sbt_offset: " + std::to_string(first);
  const std::string flags = instanceFlags();
  if (!flags.empty()) line += ", flags: [" + flags + "]";
  out_ += line + "}\n";
}

void CaseGenerator::scene() {
  out_ += "scene:\n";
  blasList();
  out_ += "  instances:\n";
  const size_t count = 1 + pick(4);
  for (size_t i = 0; i < count; ++i) instance();
  if (hit_groups_ == 0) {  // every instance inactive: one group all the same
    group_aabbs_.push_back(false);
    hit_groups_ = 1;
  }
}

}  // namespace rayspec
