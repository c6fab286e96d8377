// The permutation check of R-ORDER-UNSPEC (harness/metamorphic/): permuting
// primitives and instances keeps what programs observe, leads ids back, and
// does not move the model's answers on any case file; and the check notices
// an answer that did move.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <set>
#include <string>

#include "metamorphic/compare_permuted.h"
#include "metamorphic/id_observations.h"
#include "metamorphic/permute_case.h"
#include "model/model_engine.h"
#include "parse/parse_case.h"
#include "plan/plan.h"
#include "program/ops.h"
#include "results/record_layout.h"
#include "suite_cases.h"

#include "model_support.h"

namespace rayspec {
namespace {

Case parseCase(const std::string& yaml) {
  return model_test::parseInline(yaml, "metamorphic/m");
}

Results model(const Case& c) {
  return model_test::runTier(c, ModelTier::Exact);
}

// A 4x4 grid of cells (32 triangles) in two instances side by side and a
// third under the right one, two boxes; an any-hit that ignores odd
// primitives and terminates on instance 3 (so that the answer under the right
// half depends on the order: R-ORDER-UNSPEC); 8x4 rays.
const char* kGrid = R"(rules: [R-ORDER-UNSPEC]
scene:
  blas:
    grid:
      - triangles: {grid: {cells: [4, 4], size: [2, 2], center: [0, 0, 0]}}
        flags: []
    boxes:
      - aabbs: [[-1, -1, -2, 1, 1, -1], [-0.5, -0.5, -3, 0.5, 0.5, -2.5]]
  instances:
    - {blas: grid, transform: {translate: [-1, 0, 0]}, custom_index: 7}
    - {blas: grid, transform: {translate: [1, 0, 0]}}
    - {blas: boxes, sbt_offset: 1}
    - {blas: grid, transform: {translate: [1, 0, -0.5]}}
rays:
  grid: {size: [8, 4], origin: [-1.93, -0.95, 1], du: [0.5, 0, 0], dv: [0, 0.45, 0], direction: [0, 0, -1]}
  tmin: 0.001
  tmax: 100
pipeline:
  miss:
    - [count: miss, record: {hit: 0}]
  hit_groups:
    - any_hit:
        - if: {odd: primitive_id}
          then: [ignore]
        - if: {eq: [instance_id, 3]}
          then: [terminate]
      closest_hit: [count: closesthit, record: [hit, instance_id, geometry_index, primitive_id, hit_t, barycentrics, instance_custom_index]]
    - intersection: [report: {t: {add: [{z: object_ray_origin}, 1.5]}, kind: 1}]
      closest_hit: [count: closesthit, record: [hit, instance_id, geometry_index, primitive_id, hit_t]]
outputs:
  counters: [miss, closesthit]
  per_ray: [hit, instance_id, geometry_index, primitive_id, hit_t, barycentrics, instance_custom_index]
)";

TEST(IdObservations, WhatProgramsObserveOfAnId) {
  const Case c = parseCase(kGrid);
  const IdObservations prim = observeId(c.pipeline, kBiPrimitive);
  EXPECT_FALSE(prim.exact);  // recorded as itself: led back
  EXPECT_TRUE(prim.parity);
  EXPECT_EQ(prim.classOf(3), prim.classOf(5));
  EXPECT_NE(prim.classOf(3), prim.classOf(4));
  const IdObservations inst = observeId(c.pipeline, kBiInstance);
  EXPECT_FALSE(inst.parity);
  EXPECT_EQ(inst.equals, (std::vector<uint64_t>{3}));
  EXPECT_EQ(inst.classOf(0), inst.classOf(2));
  EXPECT_NE(inst.classOf(3), inst.classOf(2));
  // The side of a threshold, whichever way it is written.
  Case t = c;
  Expr id = builtinExpr(kBiPrimitive, {});
  Expr three;
  three.literal = {3};
  for (const auto& [name, id_first, threshold] :
       std::vector<std::tuple<std::string, bool, uint64_t>>{{"lt", true, 3},
                                                            {"le", true, 4},
                                                            {"gt", true, 4},
                                                            {"ge", true, 3},
                                                            {"lt", false, 4},
                                                            {"le", false, 3},
                                                            {"gt", false, 3},
                                                            {"ge", false, 4}}) {
    Expr cmp;
    cmp.kind = Expr::Kind::Op;
    cmp.name = name;
    cmp.op = opNamed(name);
    cmp.args = id_first ? std::vector<Expr>{id, three} : std::vector<Expr>{three, id};
    Stmt s;
    s.kind = Stmt::Kind::If;
    s.cond = cmp;
    t.pipeline.raygen = {s};
    t.pipeline.hit_groups.clear();
    EXPECT_EQ(observeId(t.pipeline, kBiPrimitive).below, (std::vector<uint64_t>{threshold}))
        << name << id_first;
  }
  // Arithmetic on the id observes the id itself: nothing may move.
  Expr sum;
  sum.kind = Expr::Kind::Op;
  setOp(sum, Op::Add);
  sum.args = {id, three};
  t.pipeline.raygen[0].cond = sum;
  EXPECT_TRUE(observeId(t.pipeline, kBiPrimitive).exact);
}

// A case of one triangle and one instance is itself under every seed (a
// --permute run of it repeats the plain run: run/case_as_run.h leaves it
// out); one indexed triangle moves its vertex buffer under some seed.
TEST(PermuteCase, OneTriangleMovesNothingButItsIndexedVertices) {
  const std::string head = "rules: [R-ORDER-UNSPEC]\nscene:\n  blas:\n    t: [{triangles: {";
  const std::string tail =
      "}}]\n  instances: [{blas: t}]\nrays:\n  list: [{origin: [0.2, 0.2, 1], direction: [0, "
      "0, -1]}]\npipeline:\n  hit_groups: [{closest_hit: [record: [primitive_id]]}]\noutputs:\n"
      "  per_ray: [primitive_id]\n";
  const Case plain = parseCase(head + "vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]" + tail);
  const Case indexed =
      parseCase(head + "vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]], indices: [0, 1, 2]" + tail);
  bool indexed_moved = false;
  for (uint64_t seed = 0; seed < 8; ++seed) {
    EXPECT_FALSE(permuteCase(plain, seed).movedAnything()) << seed;
    const CasePermutation p = permuteCase(indexed, seed);
    EXPECT_FALSE(p.primitivesMoved() || p.instancesMoved());
    indexed_moved = indexed_moved || p.movedAnything();
  }
  EXPECT_TRUE(indexed_moved);
  EXPECT_TRUE(permuteCase(parseCase(kGrid), 7).movedAnything());
}

TEST(PermuteCase, DeterministicAndKeepsEveryPrimitiveAndInstance) {
  const Case c = parseCase(kGrid);
  const CasePermutation a = permuteCase(c, 7), b = permuteCase(c, 7), d = permuteCase(c, 8);
  EXPECT_EQ(a.instance_of, b.instance_of);
  EXPECT_EQ(a.primitive_of, b.primitive_of);
  EXPECT_NE(a.primitive_of, d.primitive_of);
  EXPECT_TRUE(a.primitivesMoved());
  // Instance 3 is observed (eq): it stays; the others may exchange.
  for (uint64_t seed = 0; seed < 8; ++seed) EXPECT_EQ(permuteCase(c, seed).instance_of[3], 3u);
  bool instances_moved = false;
  for (uint64_t seed = 0; seed < 8; ++seed)
    instances_moved = instances_moved || permuteCase(c, seed).instancesMoved();
  EXPECT_TRUE(instances_moved);
  // Every permuted triangle is an original one, vertex for vertex (winding
  // kept), with the parity of its primitive id; every instance an original.
  const Geometry& g0 = c.scene.blases[0].geometries[0];
  const Geometry& g1 = a.permuted.scene.blases[0].geometries[0];
  ASSERT_EQ(g1.primitiveCount(), g0.primitiveCount());
  std::set<uint32_t> seen;
  for (uint32_t p = 0; p < g1.primitiveCount(); ++p) {
    const uint32_t old = a.primitive_of[0][0][p];
    seen.insert(old);
    EXPECT_EQ(old % 2, p % 2);
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(g1.vertices[g1.indices[p * 3 + k]], g0.vertices[g0.indices[old * 3 + k]])
          << p << " " << k;
  }
  EXPECT_EQ(seen.size(), g0.primitiveCount());
  const auto& boxes0 = c.scene.blases[1].geometries[0].aabbs;
  const auto& boxes1 = a.permuted.scene.blases[1].geometries[0].aabbs;
  for (uint32_t p = 0; p < boxes1.size(); ++p)
    EXPECT_EQ(boxes1[p], boxes0[a.primitive_of[1][0][p]]);
  for (uint32_t i = 0; i < a.instance_of.size(); ++i) {
    EXPECT_EQ(a.permuted.scene.instances[i].transform,
              c.scene.instances[a.instance_of[i]].transform);
    EXPECT_EQ(a.permuted.scene.instances[i].custom_index,
              c.scene.instances[a.instance_of[i]].custom_index);
  }
}

// The check sees an answer that moved: a permuted run whose clear ray is
// edited to another primitive, or to another instance, or to a miss.
TEST(ComparePermuted, NoticesAMovedAnswer) {
  const Case c = parseCase(kGrid);
  const Results original = model(c);
  const CasePermutation p = permuteCase(c, 3);
  const Results permuted = model(p.permuted);
  ASSERT_TRUE(comparePermuted(p, original, permuted).empty());
  std::set<uint32_t> ambiguous;
  for (const RayAmbiguity& a : original.ambiguous) ambiguous.insert(a.ray);
  uint32_t clear_hit = ~0u;
  const uint32_t words = recordWords();
  for (uint32_t ray = 0; ray < 32 && clear_hit == ~0u; ++ray)
    if (!ambiguous.count(ray) &&
        original.records[ray * words + findRecordField("hit")->offset] == 1 &&
        original.records[ray * words + findRecordField("instance_id")->offset] != 2)  // a triangle
      clear_hit = ray;
  ASSERT_NE(clear_hit, ~0u);
  for (const char* field : {"primitive_id", "instance_id", "hit", "hit_t"}) {
    Results edited = permuted;
    uint32_t& w = edited.records[clear_hit * words + findRecordField(field)->offset];
    w = std::string(field) == "hit_t" ? w + 4096 : std::string(field) == "hit" ? 0 : w ^ 2;
    const auto problems = comparePermuted(p, original, edited);
    ASSERT_EQ(problems.size(), 1u) << field;
    EXPECT_NE(problems[0].find("ray " + std::to_string(clear_hit) + ": clear, "), std::string::npos)
        << problems[0];
  }
  // An ambiguous ray answering outside its legal set.
  ASSERT_FALSE(original.ambiguous.empty());
  Results edited = permuted;
  const uint32_t ray = original.ambiguous[0].ray;
  edited.records[ray * words + findRecordField("instance_id")->offset] = 99;
  edited.records[ray * words + findRecordField("hit")->offset] = 1;
  edited.records[ray * words] |=
      1u << recordFieldIndex("hit") | 1u << recordFieldIndex("instance_id");
  const auto problems = comparePermuted(p, original, edited);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].find("not a legal answer"), std::string::npos) << problems[0];
}

// Every case file, permuted with a few seeds, on the model (exact tier): no
// answer moves.
TEST(ComparePermuted, EveryCaseFileKeepsItsAnswers) {
  namespace fs = std::filesystem;
  int cases = 0, moved = 0;
  for (const CaseFile& f : suiteCases()) {
    ParseResult parsed = loadSuiteCase(f);
    if (!parsed.value) continue;
    const Case& c = *parsed.value;
    const Results original = model(c);
    ASSERT_EQ(original.statusText(), "ok") << c.name;
    ++cases;
    bool any = false;
    for (uint64_t seed : {1u, 2u, 3u}) {
      const CasePermutation p = permuteCase(c, seed);
      // A permutation that moves nothing (one primitive, one instance) is the
      // case itself: nothing about order to check, and a 4M-ray launch to
      // trace again for it.
      if (!p.movedAnything()) continue;
      any = true;
      for (const std::string& problem : comparePermuted(p, original, model(p.permuted)))
        ADD_FAILURE() << c.name << ": " << problem;
    }
    moved += any;
  }
  std::printf("%d case files, %d with primitives or instances permuted\n", cases, moved);
  EXPECT_GT(cases, 0);
  EXPECT_GT(moved, cases / 2);
}

}  // namespace
}  // namespace rayspec

namespace rayspec {
namespace {

// intersection/ordering lists one scene in 20 orders (instances, boxes,
// triangles). On the model every variant must give the same closest hits,
// report return values and exact counters: order may move only what the
// informational counters count.
TEST(OrderingSweep, EveryOrderGivesTheSameAnswers) {
  const std::vector<CaseFile> variants = findCases(kSuiteCases, "intersection/ordering");
  ASSERT_GE(variants.size(), 20u);
  const std::vector<std::string> fields = {"hit", "hit_t", "hit_kind", "instance_custom_index",
                                           "value"};
  std::vector<uint32_t> first_records;
  std::map<std::string, uint64_t> first_counters;
  for (const CaseFile& f : variants) {
    const ParseResult parsed = loadSuiteCase(f);
    ASSERT_TRUE(parsed.value) << f.name;
    const Results r = model(*parsed.value);
    ASSERT_TRUE(r.ambiguous.empty())
        << f.name << ": the scene has no ties, edges or faces on its rays";
    std::vector<uint32_t> records;
    for (size_t ray = 0; ray * recordWords() < r.records.size(); ++ray)
      for (const std::string& name : fields) {
        const RecordField* field = findRecordField(name);
        for (uint32_t w = 0; w < field->words; ++w)
          records.push_back(r.records[ray * recordWords() + field->offset + w]);
      }
    const std::map<std::string, uint64_t> counters = {{"miss", r.counters.at("miss")},
                                                      {"closesthit", r.counters.at("closesthit")}};
    if (first_records.empty()) {
      first_records = records;
      first_counters = counters;
      continue;
    }
    EXPECT_EQ(records, first_records) << f.name << " answers differently from " << variants[0].name;
    EXPECT_EQ(counters, first_counters) << f.name;
  }
}

}  // namespace
}  // namespace rayspec
