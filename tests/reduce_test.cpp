// The reduction's pieces without a device: delta debugging on synthetic
// tests, the document's sites and their edits, the failure signature.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "parse/parse_case.h"
#include "reduce/delta_debug.h"
#include "reduce/failure_signature.h"
#include "reduce/number_sites.h"
#include "reduce/operand_sites.h"
#include "reduce/rays_to_list.h"
#include "reduce/reduce_report.h"
#include "reduce/used_vertices.h"
#include "reduce/yaml_sites.h"

namespace rayspec {
namespace {

// Fails while every element of `needed` is kept.
SubsetTest needs(std::set<size_t> needed, size_t* asked = nullptr) {
  return [needed, asked](const std::vector<size_t>& kept) {
    if (asked) ++*asked;
    for (size_t n : needed)
      if (std::find(kept.begin(), kept.end(), n) == kept.end()) return false;
    return true;
  };
}

TEST(DeltaDebug, FindsTheOneElement) {
  const DeltaResult r = deltaDebug(64, needs({37}));
  EXPECT_EQ(r.kept, std::vector<size_t>({37}));
  EXPECT_LT(r.tests, 20u);  // halves, not one by one
}

TEST(DeltaDebug, FindsElementsFarApart) {
  EXPECT_EQ(deltaDebug(100, needs({0, 50, 99})).kept, std::vector<size_t>({0, 50, 99}));
}

TEST(DeltaDebug, EmptyWhenNothingIsNeeded) {
  const DeltaResult r = deltaDebug(10, needs({}));
  EXPECT_TRUE(r.kept.empty());
  EXPECT_EQ(r.tests, 1u);
}

TEST(DeltaDebug, KeepsAllWhenAllAreNeeded) {
  EXPECT_EQ(deltaDebug(5, needs({0, 1, 2, 3, 4})).kept, std::vector<size_t>({0, 1, 2, 3, 4}));
}

TEST(DeltaDebug, OneMinimalForAPairThatMustStayTogether) {
  // Fails while 3 and 4 are both kept, or 8 alone is: either is 1-minimal.
  const SubsetTest test = [](const std::vector<size_t>& kept) {
    const auto has = [&](size_t n) {
      return std::find(kept.begin(), kept.end(), n) != kept.end();
    };
    return (has(3) && has(4)) || has(8);
  };
  const DeltaResult r = deltaDebug(12, test);
  ASSERT_FALSE(r.kept.empty());
  for (size_t i = 0; i < r.kept.size(); ++i) {
    std::vector<size_t> less = r.kept;
    less.erase(less.begin() + i);
    EXPECT_FALSE(test(less)) << "element " << r.kept[i] << " could still go";
  }
}

TEST(DeltaDebug, SameTestSameAttempts) {
  std::vector<std::vector<size_t>> first, second;
  const auto logged = [](std::vector<std::vector<size_t>>& log) {
    return [&log](const std::vector<size_t>& kept) {
      log.push_back(kept);
      return std::find(kept.begin(), kept.end(), 5) != kept.end();
    };
  };
  deltaDebug(33, logged(first));
  deltaDebug(33, logged(second));
  EXPECT_EQ(first, second);
}

TEST(DeltaDebug, ZeroElements) {
  size_t asked = 0;
  EXPECT_TRUE(deltaDebug(0, needs({}, &asked)).kept.empty());
  EXPECT_EQ(asked, 0u);
}

const char* const kSiteCase = R"(rules: [R-MISS-XOR-CHIT]
scene:
  blas:
    tri:
      - triangles: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [0, 1, 1]]}
  instances:
    - {blas: tri, mask: 0x0F}
    - {blas: tri, transform: {translate: [0, 0, 5]}}
rays:
  list:
    - {origin: [0.25, 0.25, 3], direction: [0, 0, -1]}
    - {origin: [0.25, 0.25, -3], direction: [0, 0, 1]}
pipeline:
  miss:
    - [count: miss, record: {hit: 0}]
  hit_groups:
    - closest_hit: [count: closesthit, record: [hit, primitive_id]]
outputs:
  counters: [miss, closesthit]
  per_ray: [hit, primitive_id]
)";

const Site* findSite(const std::vector<Site>& sites, const std::string& path) {
  for (const Site& s : sites)
    if (pathText(s.path) == path) return &s;
  return nullptr;
}

TEST(ReduceSites, ListsTheCaseParts) {
  const YAML::Node doc = YAML::Load(kSiteCase);
  const std::vector<Site> sites = reductionSites(doc);
  ASSERT_FALSE(sites.empty());
  EXPECT_EQ(pathText(sites[0].path), "rays.list");  // rays first
  const Site* vertices = findSite(sites, "scene.blas.tri[0].triangles.vertices");
  ASSERT_NE(vertices, nullptr);
  EXPECT_EQ(vertices->group, 3u);
  EXPECT_EQ(vertices->units, 2u);  // two triangles
  ASSERT_NE(findSite(sites, "scene.instances"), nullptr);
  EXPECT_NE(findSite(sites, "pipeline.hit_groups[0].closest_hit"), nullptr);
  // A vector is never a site: its length is its meaning.
  EXPECT_EQ(findSite(sites, "rays.list[0].origin"), nullptr);
}

TEST(ReduceSites, KeptUnitsParseAsACase) {
  const YAML::Node doc = YAML::Load(kSiteCase);
  const std::vector<Site> sites = reductionSites(doc);
  const Site* vertices = findSite(sites, "scene.blas.tri[0].triangles.vertices");
  ASSERT_NE(vertices, nullptr);
  const YAML::Node one = keepUnits(doc, *vertices, {1});
  const ParseResult parsed = parseCaseText(emitYaml(one), "one.yaml", "reduce/one");
  ASSERT_TRUE(parsed.value) << emitYaml(one);
  ASSERT_EQ(parsed.value->scene.blases[0].geometries[0].primitiveCount(), 1u);
  EXPECT_EQ(parsed.value->scene.blases[0].geometries[0].vertices[0][2], 1.0f);  // the second
  // The original is untouched.
  EXPECT_EQ(nodeAt(doc, vertices->path).size(), 6u);
}

TEST(ReduceSites, KeysGoToTheirDefaults) {
  const YAML::Node doc = YAML::Load(kSiteCase);
  const std::vector<Site> sites = reductionSites(doc);
  const Site* inst = findSite(sites, "scene.instances[0]");
  ASSERT_NE(inst, nullptr);
  EXPECT_EQ(inst->keys, std::vector<std::string>({"mask"}));  // blas stays
  const ParseResult parsed =
      parseCaseText(emitYaml(keepUnits(doc, *inst, {})), "k.yaml", "reduce/k");
  ASSERT_TRUE(parsed.value);
  EXPECT_EQ(parsed.value->scene.instances[0].mask, 0xFFu);
}

TEST(ReduceSites, FlagsAndBuildOptionsMayGo) {
  const YAML::Node doc = YAML::Load(R"(scene:
  blas:
    tri:
      - triangles: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}
        flags: [opaque, no_duplicate_any_hit]
  build: {flags: [allow_update, prefer_fast_build], copy: compact}
  instances:
    - {blas: tri, flags: [force_opaque]}
rays:
  flags: [opaque, cull_back_facing]
  list:
    - {origin: [0, 0, 1], direction: [0, 0, -1], flags: [skip_aabbs]}
)");
  const std::vector<Site> sites = reductionSites(doc);
  for (const char* path : {"rays.flags", "rays.list[0].flags", "scene.instances[0].flags",
                           "scene.blas.tri[0].flags", "scene.build.flags"}) {
    const Site* s = findSite(sites, path);
    ASSERT_NE(s, nullptr) << path;
    EXPECT_EQ(s->part, "flags");
  }
  const Site* build = findSite(sites, "scene.build");
  ASSERT_NE(build, nullptr);
  EXPECT_EQ(build->keys, std::vector<std::string>({"flags", "copy"}));
}

constexpr const char* kGridCase = R"(rules: [R-MISS-XOR-CHIT]
scene:
  blas:
    tri:
      - triangles: {vertices: [[-1, -1, 0], [2, -1, 0], [-1, 2, 0]]}
  instances: [{blas: tri}]
rays:
  grid: {size: [3, 2], origin: [0.1, -0.3, 5], du: [0.37, 0, 0], dv: [0, 0.29, 0], direction: [0, 0.01, -1]}
  tmax: 50
pipeline:
  miss: [[count: miss]]
  hit_groups: [{closest_hit: [count: closesthit]}]
outputs: {counters: [miss, closesthit]}
)";

// Issue 61: a reduced case printed `-0`. A zero is written 0 but in a ray
// direction, where its sign decides 1 / d and the case had it.
TEST(ReduceEmit, ANegativeZeroIsWrittenAsZeroButInADirection) {
  EXPECT_EQ(floatText(-0.0f), "0");
  EXPECT_EQ(floatText(0.0f), "0");
  EXPECT_EQ(floatText(-0.5f), "-0.5");
  EXPECT_EQ(exactFloatText(-0.0f), "-0");
  ParseResult grid = parseCaseText(kGridCase, "g.yaml", "reduce/g");
  ASSERT_TRUE(grid.value);
  grid.value->rays.rays[1].origin = {-0.0f, 0.25f, 5};
  grid.value->rays.rays[1].direction = {-0.0f, 0, -1};
  const YAML::Node doc = YAML::Load(kGridCase);
  const std::optional<YAML::Node> list = raysAsList(doc["rays"], *grid.value, {1});
  ASSERT_TRUE(list);
  const std::string text = emitYaml(*list);
  EXPECT_NE(text.find("origin: [0, 0.25, 5]"), std::string::npos) << text;
  EXPECT_NE(text.find("direction: [-0, 0, -1]"), std::string::npos) << text;
  const ParseResult listed =
      parseCaseText(emitYaml(replacedAt(doc, {{false, 0, "rays"}}, *list)), "l.yaml", "reduce/l");
  ASSERT_TRUE(listed.value);
  EXPECT_TRUE(std::signbit(listed.value->rays.rays[0].direction[0]));
  EXPECT_FALSE(std::signbit(listed.value->rays.rays[0].origin[0]));
}

// Issue 61: a reduction that kept none of a geometry's indices left
// `indices: []`, which is no index buffer (the vertices make the triangles
// three by three): the key goes, and the vertices past the last whole
// triangle; the same triangles.
TEST(ReduceEmit, EmptiedIndicesGoAndTheVerticesMakeTheSameTriangles) {
  const std::string tri = "{vertices: [[-1, -1, 0], [2, -1, 0], [-1, 2, 0]]}";
  const auto geometry_of = [&](const std::string& triangles) {
    std::string text = kGridCase;
    text.replace(text.find(tri), tri.size(), triangles);
    const ParseResult parsed = parseCaseText(text, "e.yaml", "reduce/e");
    EXPECT_TRUE(parsed.value) << (parsed.errors.empty() ? "" : parsed.errors[0].format());
    return parsed.value ? parsed.value->scene.blases[0].geometries[0] : Geometry{};
  };
  const std::string none = "{vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0], [5, 5, 5]], indices: []}";
  const std::optional<YAML::Node> listed = usedVerticesOnly(YAML::Load(none));
  ASSERT_TRUE(listed);
  const std::string text = emitYaml(*listed);
  EXPECT_EQ(text, "{vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}\n");
  EXPECT_FALSE(usedVerticesOnly(*listed)) << "nothing more to drop";
  const Geometry before = geometry_of(none), after = geometry_of(text.substr(0, text.size() - 1));
  EXPECT_EQ(before.primitiveCount(), 1u);
  EXPECT_EQ(after.primitiveCount(), 1u);
  for (uint32_t v = 0; v < 3; ++v) EXPECT_EQ(after.vertices[v], before.vertices[v]);
  const YAML::Node some =
      YAML::Load("{vertices: [[9, 9, 9], [0, 0, 0], [1, 0, 0], [0, 1, 0]], indices: [3, 1, 2]}");
  const std::optional<YAML::Node> used = usedVerticesOnly(some);
  ASSERT_TRUE(used);
  EXPECT_EQ(emitYaml(*used), "{vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]], indices: [2, 0, 1]}\n");
  EXPECT_FALSE(usedVerticesOnly(*used)) << "every vertex used";
}

// Issue 61: emptied lists (`flags: []`, a ray query's `aabb: []`) are found
// to be left out where the case still fails so.
TEST(ReduceEmit, EmptyListsAreFound) {
  const YAML::Node doc = YAML::Load(R"(scene:
  instances: [{blas: b, flags: []}]
pipeline:
  raygen:
    - ray_query: {triangle: [confirm], aabb: [], after: [record: {hit: 1}]}
  miss: [[]]
)");
  std::vector<std::string> paths;
  for (const YamlPath& p : emptyListKeys(doc)) paths.push_back(pathText(p));
  EXPECT_EQ(paths, (std::vector<std::string>{"scene.instances[0].flags",
                                             "pipeline.raygen[0].ray_query.aabb"}))
      << "an empty miss program is a list element, not a key";
}

// Issue 61: "does not fail to begin with: Pass: Pass" named the verdict twice.
TEST(ReduceReport, ACaseThatDoesNotFailNamesItsVerdictOnce) {
  CaseOutcome pass;
  pass.status = Status::Pass;
  pass.headline = "Pass";
  EXPECT_EQ(notFailingText("a/b", "", pass), "a/b does not fail to begin with: it passes");
  CaseOutcome warned;
  warned.status = Status::QualityWarning;
  warned.headline = "QualityWarning: R-WATERTIGHT: ray 3 passed between two triangles";
  EXPECT_EQ(notFailingText("a/b", "R-MASK", warned),
            "a/b does not fail by R-MASK to begin with: QualityWarning: R-WATERTIGHT: ray 3 "
            "passed between two triangles");
}

TEST(ReduceRays, GridBecomesAListOfTheSameRays) {
  const std::string text = R"(rules: [R-MISS-XOR-CHIT]
scene:
  blas:
    tri:
      - triangles: {vertices: [[-1, -1, 0], [2, -1, 0], [-1, 2, 0]]}
  instances: [{blas: tri}]
rays:
  grid: {size: [3, 2], origin: [0.1, -0.3, 5], du: [0.37, 0, 0], dv: [0, 0.29, 0], direction: [0, 0.01, -1]}
  tmax: 50
pipeline:
  miss: [[count: miss]]
  hit_groups: [{closest_hit: [count: closesthit]}]
outputs: {counters: [miss, closesthit]}
)";
  const ParseResult grid = parseCaseText(text, "g.yaml", "reduce/g");
  ASSERT_TRUE(grid.value);
  const YAML::Node doc = YAML::Load(text);
  const std::optional<YAML::Node> list = raysAsList(doc["rays"], *grid.value, {1, 4});
  ASSERT_TRUE(list);
  const ParseResult listed =
      parseCaseText(emitYaml(replacedAt(doc, {{false, 0, "rays"}}, *list)), "l.yaml", "reduce/l");
  ASSERT_TRUE(listed.value);
  ASSERT_EQ(listed.value->rays.rays.size(), 2u);
  for (int k = 0; k < 3; ++k) {  // bit-exact
    EXPECT_EQ(listed.value->rays.rays[0].origin[k], grid.value->rays.rays[1].origin[k]);
    EXPECT_EQ(listed.value->rays.rays[1].origin[k], grid.value->rays.rays[4].origin[k]);
    EXPECT_EQ(listed.value->rays.rays[1].direction[k], grid.value->rays.rays[4].direction[k]);
  }
  EXPECT_EQ(listed.value->rays.rays[1].tmax, 50.0f);
}

TEST(ReduceSignature, SameRuleAndKind) {
  CaseOutcome o;
  o.verdict.add({Status::Fail, "R-MASK", "per-ray field 'hit' differs (rays 3, 4)", {3, 4}, 2});
  o.deriveFromVerdict();
  const std::optional<FailureSignature> s = failureToKeep(o, "");
  ASSERT_TRUE(s);
  EXPECT_EQ(s->rule, "R-MASK");
  CaseOutcome fewer;
  fewer.verdict.add({Status::Fail, "R-MASK", "per-ray field 'hit' differs (rays 0)", {0}, 1});
  fewer.deriveFromVerdict();
  EXPECT_TRUE(failsTheSameWay(fewer, *s));
  CaseOutcome other;
  other.verdict.add({Status::Fail, "R-MASK", "per-ray field 'primitive_id' differs", {0}, 1});
  other.deriveFromVerdict();
  EXPECT_FALSE(failsTheSameWay(other, *s));
  EXPECT_TRUE(failsTheSameWay(other, *failureToKeep(o, "R-MASK")));  // a rule: any kind
  EXPECT_FALSE(failureToKeep(CaseOutcome{}, ""));                    // a pass: nothing to keep
}

// --keep R-X finds the rule among a finding's labels, and keeps it whatever
// else a variant's label names (a reduced case claims fewer rules).
TEST(FailureSignature, AKeptRuleIsFoundAmongTheLabels) {
  CaseOutcome o;
  o.verdict.add({Status::Fail, "R-FACE-DET/R-INST-XFORM", "counter 'miss' (exact)", {}, 0});
  o.deriveFromVerdict();
  const std::optional<FailureSignature> s = failureToKeep(o, "R-FACE-DET");
  ASSERT_TRUE(s);
  EXPECT_EQ(s->rule, "R-FACE-DET");
  EXPECT_FALSE(failureToKeep(o, "R-FACE"));  // a part names a whole rule, not a prefix
  CaseOutcome reduced;
  reduced.verdict.add({Status::Fail, "R-FACE-DET", "per-ray field 'hit' differs", {0}, 1});
  reduced.deriveFromVerdict();
  EXPECT_TRUE(failsTheSameWay(reduced, *s));
  CaseOutcome other;
  other.verdict.add({Status::Fail, "R-INST-XFORM", "per-ray field 'hit' differs", {0}, 1});
  other.deriveFromVerdict();
  EXPECT_FALSE(failsTheSameWay(other, *s));
}

const char* const kNumberCase = R"(rules: [R-MISS-XOR-CHIT]
scene:
  blas:
    grid:
      - triangles: {grid: {cells: [8, 4], size: [2, 2], center: [0, 0, 0]}}
    boxes:
      - aabbs: {grid: {cells: [16, 1], size: [2, 2], center: [0, 0, 0], height: 1}}
  instances:
    - {blas: grid, mask: 0x0F, custom_index: 7}
rays:
  grid: {size: [3, 2], origin: [-1, -1, 5], du: [0.5, 0, 0], dv: [0, 0.5, 0], direction: [0, 0, -1]}
  tmin: 0.5
pipeline:
  miss:
    - [count: miss]
  hit_groups:
    - closest_hit:
        - repeat: 5
          var: i
          do: [count: closesthit]
        - if: {lt: [hit_t, -3]}
          then: [count: closesthit]
outputs:
  counters: [miss, closesthit]
)";

std::vector<std::string> numberPaths(const YAML::Node& doc) {
  std::vector<std::string> out;
  for (const NumberSite& s : numberSites(doc))
    out.push_back(pathText(s.path) + "=" + std::to_string(s.value) + " " + s.part);
  return out;
}

TEST(ReduceNumbers, ListsGeneratorsLaunchFieldsAndStatementNumbers) {
  const YAML::Node doc = YAML::Load(kNumberCase);
  EXPECT_EQ(numberPaths(doc), std::vector<std::string>({
                                  "scene.blas.grid[0].triangles.grid.cells[0]=8 generator",
                                  "scene.blas.grid[0].triangles.grid.cells[1]=4 generator",
                                  "scene.blas.boxes[0].aabbs.grid.cells[0]=16 generator",
                                  "scene.blas.boxes[0].aabbs.grid.cells[1]=1 generator",
                                  "scene.instances[0].custom_index=7 instance field",
                                  "scene.instances[0].mask=15 instance field",
                                  "rays.grid.size[0]=3 launch",
                                  "rays.grid.size[1]=2 launch",
                                  "pipeline.hit_groups[0].closest_hit[0].repeat=5 statement",
                              }));
  // Not numbers to lower: coordinates and fractions (size, tmin 0.5), a
  // negative constant (-3), zero, a name.
}

TEST(ReduceNumbers, WholeNumbersAreWrittenPlainly) {
  EXPECT_EQ(wholeNumber(YAML::Node("12")), 12u);
  EXPECT_EQ(wholeNumber(YAML::Node("0xFF")), 255u);
  EXPECT_EQ(wholeNumber(YAML::Node("0")), 0u);
  for (const char* no :
       {"-1", "1.5", "1e3", "012", "0x", "12a", "miss", "", "99999999999999999999"})
    EXPECT_FALSE(wholeNumber(YAML::Node(no))) << no;
  EXPECT_FALSE(wholeNumber(YAML::Load("[1, 2]")));
}

TEST(ReduceNumbers, ALoweredGeneratorStillParses) {
  const YAML::Node doc = YAML::Load(kNumberCase);
  const std::vector<NumberSite> sites = numberSites(doc);
  ASSERT_FALSE(sites.empty());
  const YAML::Node lower = replacedAt(doc, sites[0].path, YAML::Node(uint64_t{1}));
  const ParseResult parsed = parseCaseText(emitYaml(lower), "n.yaml", "reduce/n");
  ASSERT_TRUE(parsed.value) << emitYaml(lower);
  EXPECT_EQ(parsed.value->scene.blases[0].geometries[0].primitiveCount(), 2u * 4u);  // 1 x 4 cells
}

TEST(ReduceOperands, OperatorsOuterFirstWithTheirOperands) {
  const YAML::Node doc = YAML::Load(R"(pipeline:
  raygen:
    - let: {a: {add: [{mod: [launch_id_x, 3]}, 1]}, b: {x: launch_id}}
    - record: [a]
)");
  const std::vector<OperandSite> sites = operandSites(doc);
  ASSERT_EQ(sites.size(), 3u);
  EXPECT_EQ(pathText(sites[0].path), "pipeline.raygen[0].let.a");
  EXPECT_EQ(sites[0].operands, 2u);
  EXPECT_EQ(pathText(sites[1].path), "pipeline.raygen[0].let.a.add[0]");
  EXPECT_EQ(emitYaml(operandOf(doc, sites[1], 0)), "launch_id_x\n");
  EXPECT_EQ(pathText(sites[2].path), "pipeline.raygen[0].let.b");  // one operand, no list
  EXPECT_EQ(sites[2].operands, 1u);
  EXPECT_EQ(emitYaml(operandOf(doc, sites[2], 0)), "launch_id\n");
  // `let` and `record` are statements, not operators.
}

}  // namespace
}  // namespace rayspec
