// Builders shared by the model's test files (tests/model_*_test.cpp): hand-
// built cases, a model run, and readers of records and ambiguities.
#pragma once

#include <array>
#include <bit>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "case/case.h"
#include "model/model_engine.h"
#include "parse/parse_case.h"
#include "plan/plan.h"
#include "program/ops.h"
#include "results/record_layout.h"

#include <gtest/gtest.h>

namespace rayspec::model_test {

// ---- building cases -------------------------------------------------------

// A case from YAML text; a parse error fails the test (and gives an empty case).
inline Case parseInline(const std::string& yaml, const std::string& name = "model/inline") {
  ParseResult p = parseCaseText(yaml, name + ".yaml", name);
  std::string errors;
  for (const Error& e : p.errors) errors += e.format() + "\n";
  EXPECT_TRUE(p.value.has_value()) << errors;
  return p.value ? *p.value : Case{};
}

// The model's results for a case in one tier.
// The first parse error of `text` with `from` replaced by `to`, as
// "field: message"; "(no error)" when it parses.
inline std::string firstErrorAfter(std::string text, const std::string& from,
                                   const std::string& to) {
  text.replace(text.find(from), from.size(), to);
  const ParseResult p = parseCaseText(text, "model/inline.yaml", "model/inline");
  if (p.errors.empty()) return "(no error)";
  return p.errors[0].loc.field + ": " + p.errors[0].message;
}

// The YAML of a BLAS `square` (under scene.blas): the square [-1, 1]^2 at
// z = 0 of two triangles sharing its diagonal x = y, its geometry's flags
// `flags` (a YAML list).
inline std::string diagonalSquareBlas(const std::string& flags) {
  return "    square:\n"
         "      - triangles:\n"
         "          vertices: [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]]\n"
         "          indices: [0, 1, 2, 0, 2, 3]\n"
         "        flags: " +
         flags + "\n";
}

// One triangle under ray 0 (it hits) and nothing under ray 1 (it misses):
// the scene and rays of a case whose pipeline follows.
inline const char* kTriangleHitAndMiss = R"(scene:
  blas:
    tri:
      - triangles:
          vertices: [[-1, -1, 0], [2, -1, 0], [-1, 2, 0]]
  instances: [{blas: tri}]
rays:
  list:
    - {origin: [0, 0, 1], direction: [0, 0, -1]}
    - {origin: [50, 0, 1], direction: [0, 0, -1]}
)";

inline Results runTier(const Case& c, ModelTier tier, unsigned threads = 2) {
  const Plan plan = derivePlan(c);
  return runOnModel(c, plan, ModelOptions{tier, threads});
}

inline Expr lit(uint32_t v) {
  Expr e;
  e.kind = Expr::Kind::Literal;
  e.type = ValueType::Uint;
  e.literal = {double(v)};
  return e;
}
inline Expr litf(double v) {
  Expr e;
  e.kind = Expr::Kind::Literal;
  e.type = ValueType::Float;
  e.literal = {v};
  return e;
}
inline Expr vec3(double x, double y, double z) {
  Expr e;
  e.kind = Expr::Kind::Literal;
  e.type = ValueType::Vec3;
  e.literal = {x, y, z};
  return e;
}
inline Expr bi(const std::string& n) {
  return builtinExpr(n);
}
inline Expr op(const std::string& n, std::vector<Expr> args) {
  Expr e;
  e.kind = Expr::Kind::Op;
  e.name = n;
  e.op = opNamed(n);
  e.args = std::move(args);
  return e;
}
inline Stmt count(const std::string& n) {
  Stmt s;
  s.kind = Stmt::Kind::Count;
  s.counter = n;
  return s;
}
inline Stmt recordBuiltins(const std::vector<std::string>& fields) {
  Stmt s;
  s.kind = Stmt::Kind::Record;
  for (const auto& f : fields) s.assigns.push_back({f, bi(f)});
  return s;
}
inline Stmt recordExpr(const std::string& f, Expr e) {
  Stmt s;
  s.kind = Stmt::Kind::Record;
  s.assigns.push_back({f, e});
  return s;
}
inline Stmt simple(Stmt::Kind k) {
  Stmt s;
  s.kind = k;
  return s;
}
inline Stmt ifThen(Expr cond, Program then_, Program else_ = {}) {
  Stmt s;
  s.kind = Stmt::Kind::If;
  s.cond = cond;
  s.then_ = then_;
  s.else_ = else_;
  return s;
}
inline Stmt traceStmt() {
  Stmt s;
  s.kind = Stmt::Kind::Trace;
  return s;
}

inline Geometry quad(float z = 0, uint32_t flags = kGeometryOpaque) {
  Geometry g;
  g.vertices = {{-1, -1, z}, {1, -1, z}, {1, 1, z}, {-1, 1, z}};
  g.indices = {0, 1, 2, 0, 2, 3};
  g.flags = flags;
  return g;
}

// n x n cells on [-1,1]^2 at z = 0, two triangles a cell.
inline Geometry grid(int n, uint32_t flags) {
  Geometry g;
  g.flags = flags;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) g.vertices.push_back({-1 + 2.0f * i / n, -1 + 2.0f * j / n, 0});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
      g.indices.insert(g.indices.end(), {a, b, c, a, c, d});
    }
  return g;
}

inline Ray downRay(float x, float y, float z = 5) {
  Ray r;
  r.origin = {x, y, z};
  r.direction = {0, 0, -1};
  r.tmin = 0.001f;
  r.tmax = 100;
  return r;
}

// A case with one BLAS "b" of the given geometries, one identity instance,
// a miss recording hit 0 and one hit group recording the usual fields.
inline Case baseCase(std::vector<Geometry> geoms, std::vector<Ray> rays, uint32_t width = 0) {
  Case c;
  c.name = "model-test";
  Blas b;
  b.name = "b";
  b.geometries = std::move(geoms);
  c.scene.blases.push_back(b);
  c.scene.instances.push_back(Instance{});
  c.scene.instances[0].blas = 0;
  c.rays.width = width ? width : static_cast<uint32_t>(rays.size());
  c.rays.height = static_cast<uint32_t>(rays.size()) / c.rays.width;
  c.rays.rays = std::move(rays);
  c.rays.defaults.tmin = 0.001f;
  c.rays.defaults.tmax = 100;
  c.pipeline.raygen = {traceStmt()};
  c.pipeline.miss = {{count("miss"), recordExpr("hit", lit(0))}};
  HitGroup g;
  g.closest_hit =
      Program{count("closesthit"), recordBuiltins({"hit", "primitive_id", "hit_t", "hit_kind",
                                                   "instance_id", "geometry_index"})};
  c.pipeline.hit_groups = {g};
  c.outputs.counters = {"miss",         "closesthit",    "anyhit", "ignored",
                        "far_accepted", "near_accepted", "calls"};
  c.outputs.per_ray = {"hit",      "primitive_id", "hit_t",
                       "hit_kind", "instance_id",  "geometry_index",
                       "value",    "depth",        "ray_tmax"};
  return c;
}

inline void checkAll(Case& c) {
  auto check = [&](Program& p, Stage s) {
    auto err = checkProgram(p, s, c.outputs.counters, c.outputs.per_ray);
    ASSERT_FALSE(err) << stageName(s) << ": " << err->message;
  };
  check(c.pipeline.raygen, Stage::Raygen);
  for (auto& m : c.pipeline.miss) check(m, Stage::Miss);
  for (auto& g : c.pipeline.hit_groups) {
    if (g.closest_hit) check(*g.closest_hit, Stage::ClosestHit);
    if (g.any_hit) check(*g.any_hit, Stage::AnyHit);
    if (g.intersection) check(*g.intersection, Stage::Intersection);
  }
  for (auto& k : c.pipeline.callables) check(k, Stage::Callable);
}

inline Results run(Case& c, ModelTier tier, unsigned threads = 2) {
  checkAll(c);
  Plan plan = derivePlan(c);
  ModelOptions o;
  o.tier = tier;
  o.threads = threads;
  return runOnModel(c, plan, o);
}

inline uint32_t word(const Results& r, uint32_t ray, const char* field, uint32_t k = 0) {
  return r.records[static_cast<size_t>(ray) * recordWords() + findRecordField(field)->offset + k];
}
inline float fword(const Results& r, uint32_t ray, const char* field, uint32_t k = 0) {
  return std::bit_cast<float>(word(r, ray, field, k));
}
inline bool written(const Results& r, uint32_t ray, const char* field) {
  return (r.records[static_cast<size_t>(ray) * recordWords()] >> recordFieldIndex(field)) & 1u;
}

inline const ModelTier kTiers[] = {ModelTier::Fast, ModelTier::Robust, ModelTier::Exact};

// The ambiguity of ray `ray`; nullptr when the ray is not ambiguous.
inline const RayAmbiguity* ambiguityOf(const Results& r, uint32_t ray) {
  for (const RayAmbiguity& a : r.ambiguous)
    if (a.ray == ray) return &a;
  return nullptr;
}

inline std::map<uint32_t, const RayAmbiguity*> byRay(const Results& r) {
  std::map<uint32_t, const RayAmbiguity*> m;
  for (const RayAmbiguity& a : r.ambiguous) m[a.ray] = &a;
  return m;
}

// The legal hit answers of an ambiguous ray as (instance, geometry, primitive); miss: {~0u, ~0u,
// ~0u}.
inline std::set<std::array<uint32_t, 3>> legal(const RayAmbiguity& a) {
  std::set<std::array<uint32_t, 3>> s;
  for (const Candidate& k : a.candidates)
    s.insert(k.hit ? std::array<uint32_t, 3>{k.instance, k.geometry, k.primitive}
                   : std::array<uint32_t, 3>{~0u, ~0u, ~0u});
  return s;
}

inline std::array<uint32_t, 3> answer(const Results& r, uint32_t ray) {
  if (word(r, ray, "hit") != 1) return {~0u, ~0u, ~0u};
  return {word(r, ray, "instance_id"), word(r, ray, "geometry_index"),
          word(r, ray, "primitive_id")};
}

inline Geometry boxes(std::vector<std::array<float, 6>> aabbs, uint32_t flags = kGeometryOpaque) {
  Geometry g;
  g.kind = Geometry::Kind::Aabbs;
  g.aabbs = std::move(aabbs);
  g.flags = flags;
  return g;
}

}  // namespace rayspec::model_test
