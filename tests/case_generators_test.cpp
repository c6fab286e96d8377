// The seeded mesh generators (fan, triangulation, subdivision), scene.split and the
// share frames, the aim rays and their case syntax.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "case/aim_rays.h"
#include "case/seeded_random.h"
#include "case/share_frame.h"
#include "case/subdivision.h"
#include "case/triangle_fan.h"
#include "case/triangle_grid.h"
#include "case/triangulation.h"
#include "parse/parse_case.h"

namespace rayspec {
namespace {

double signedArea(const Geometry& g, uint32_t p) {
  const Vec3 &a = g.vertices[g.indices[p * 3]], &b = g.vertices[g.indices[p * 3 + 1]],
             &c = g.vertices[g.indices[p * 3 + 2]];
  return (double(b[0]) - a[0]) * (double(c[1]) - a[1]) -
         (double(b[1]) - a[1]) * (double(c[0]) - a[0]);
}

// Each undirected edge used once (border) or twice in opposite directions.
void expectManifold(const Geometry& g) {
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  for (uint32_t p = 0; p < g.primitiveCount(); ++p)
    for (int e = 0; e < 3; ++e) ++directed[{g.indices[p * 3 + e], g.indices[p * 3 + (e + 1) % 3]}];
  for (const auto& [e, n] : directed) EXPECT_EQ(n, 1) << e.first << "->" << e.second;
}

TEST(SeededRandom, FixedSequence) {
  // splitmix64's published first outputs for seed 0 (the same on every platform).
  SeededRandom r(0);
  EXPECT_EQ(r.next(), 0xE220A8397B1DCDAFull);
  EXPECT_EQ(r.next(), 0x6E789E6AA1B965F4ull);
  SeededRandom u(7);
  for (int i = 0; i < 1000; ++i) {
    const double x = u.unit();
    EXPECT_GE(x, 0.0);
    EXPECT_LT(x, 1.0);
  }
}

TEST(TriangleFan, ClosedCounterClockwiseAndSeeded) {
  for (uint64_t seed : {0ull, 1ull, 99ull}) {
    Geometry g;
    makeTriangleFan({12, 2.0, {5, 6, 7}, seed}, g);
    ASSERT_EQ(g.primitiveCount(), 12u);
    EXPECT_EQ(g.vertices[0], (Vec3{5, 6, 7}));
    for (uint32_t p = 0; p < 12; ++p) EXPECT_GT(signedArea(g, p), 0) << seed << " " << p;
    expectManifold(g);
    for (size_t v = 1; v < g.vertices.size(); ++v) {
      const double r = std::hypot(g.vertices[v][0] - 5.0, g.vertices[v][1] - 6.0);
      EXPECT_LE(r, 2.0 + 1e-5);
      EXPECT_GE(r, seed ? 1.2 - 1e-5 : 2.0 - 1e-5);
      EXPECT_EQ(g.vertices[v][2], 7.0f);
    }
  }
  Geometry a, b, c;
  makeTriangleFan({9, 1, {0, 0, 0}, 5}, a);
  makeTriangleFan({9, 1, {0, 0, 0}, 5}, b);
  makeTriangleFan({9, 1, {0, 0, 0}, 6}, c);
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_NE(a.vertices, c.vertices);
}

TEST(Triangulation, CoversTheRectangleCounterClockwise) {
  for (uint64_t seed : {1ull, 2ull, 3ull, 12345ull}) {
    Geometry g;
    makeTriangulation({6, 4, {3, 2}, {10, 20, 0}, seed, 0.25}, g);
    ASSERT_EQ(g.primitiveCount(), 48u);
    double area = 0;
    for (uint32_t p = 0; p < 48; ++p) {
      EXPECT_GT(signedArea(g, p), 0) << seed << " " << p;
      area += signedArea(g, p) / 2;
    }
    EXPECT_NEAR(area, 6.0, 1e-4);  // the triangles tile the 3 x 2 rectangle
    expectManifold(g);
    EXPECT_EQ(g.vertices[0], (Vec3{8.5f, 19, 0}));  // corners stay
  }
  Geometry a, b, flat;
  makeTriangulation({4, 4, {1, 1}, {0, 0, 0}, 8, 0.25}, a);
  makeTriangulation({4, 4, {1, 1}, {0, 0, 0}, 9, 0.25}, b);
  EXPECT_NE(a.vertices, b.vertices);
  makeTriangulation({4, 4, {4, 4}, {0, 0, 0}, 8, 0.0}, flat);
  Geometry grid;
  makeTriangleGrid(4, 4, {4, 4}, {0, 0, 0}, grid);
  EXPECT_EQ(flat.vertices, grid.vertices);  // no jitter: the grid's vertices
}

TEST(Subdivision, TilesTheRectangleNonPlanarAndClosed) {
  for (uint32_t n : {2u, 4u, 64u, 4096u}) {
    Geometry g;
    ASSERT_TRUE(makeSubdivision({n, {3, 2}, {10, 20, 5}, 0.5, 7}, g));
    ASSERT_EQ(g.primitiveCount(), n);
    EXPECT_EQ(g.vertices.size(), 4u + (n - 2) / 2);
    double area = 0;
    for (uint32_t p = 0; p < n; ++p) {
      EXPECT_GT(signedArea(g, p), 0) << n << " " << p;
      area += signedArea(g, p) / 2;
    }
    EXPECT_NEAR(area, 6.0, 1e-3);  // the projections tile the 3 x 2 rectangle
    expectManifold(g);
    bool raised = false;
    for (size_t v = 4; v < g.vertices.size(); ++v) {
      EXPECT_GE(g.vertices[v][2], 5.0f);
      EXPECT_LE(g.vertices[v][2], 5.5f);
      raised = raised || g.vertices[v][2] != 5.0f;
    }
    EXPECT_EQ(raised, n > 2);
  }
}

TEST(Subdivision, SeededTheSameEverywhere) {
  Geometry a, b, c;
  ASSERT_TRUE(makeSubdivision({16, {1, 1}, {0, 0, 0}, 1, 11}, a));
  ASSERT_TRUE(makeSubdivision({16, {1, 1}, {0, 0, 0}, 1, 11}, b));
  ASSERT_TRUE(makeSubdivision({16, {1, 1}, {0, 0, 0}, 1, 12}, c));
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.indices, b.indices);
  EXPECT_NE(a.vertices, c.vertices);
  // The first split of seed 11, as every machine makes it (splitmix64 and
  // IEEE double only): a change of the generator shows here.
  ASSERT_EQ(a.vertices.size(), 11u);
  EXPECT_EQ(a.vertices[4], (Vec3{-0x1.dbd80ep-5f, 0x1.319e64p-2f, 0x1.525078p-3f}))
      << a.vertices[4][0] << " " << a.vertices[4][1] << " " << a.vertices[4][2];
}

TEST(Subdivision, AtLargeCoordinatesOrRefused) {
  // 65,536 triangles over 1024 x 1024 at x, y = 1e6 (a float step of 1/16):
  // every split point rounded to float still lies well inside its triangle.
  Geometry g;
  ASSERT_TRUE(makeSubdivision({65536, {1024, 1024}, {1e6, 1e6, 0}, 64, 3}, g));
  for (uint32_t p = 0; p < g.primitiveCount(); ++p) ASSERT_GT(signedArea(g, p), 0) << p;
  expectManifold(g);
  // Too many triangles for a rectangle of 4 float steps at that magnitude.
  Geometry small;
  const Result<void> refused = makeSubdivision({4096, {0.25, 0.25}, {1e6, 1e6, 0}, 0, 3}, small);
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().message.find("too small"), std::string::npos);
  EXPECT_FALSE(makeSubdivision({5, {1, 1}, {0, 0, 0}, 0, 1}, small));
}

TEST(AimRays, EveryInnerVertexOfASubdivision) {
  // Only the four corners are open: (n - 2) / 2 inner vertices, 3 n / 2 - 2
  // shared edges, n faces.
  Geometry g;
  ASSERT_TRUE(makeSubdivision({1024, {8, 8}, {0, 0, 0}, 2, 5}, g));
  AimSpec spec;
  spec.edge_points = 1;
  EXPECT_EQ(meshAimTargets(g, spec).size(), 511u + 1534u + 1024u);
}

TEST(AimRays, InteriorFeaturesOfAGrid) {
  Geometry g;
  makeTriangleGrid(2, 2, {2, 2}, {0, 0, 0}, g);
  AimSpec spec;
  spec.edge_points = 1;
  // 1 inner vertex; 8 shared edges (4 inner axis edges, 4 diagonals); 8 faces.
  const auto points = meshAimPoints(g, spec);
  ASSERT_EQ(points.size(), 1u + 8u + 8u);
  EXPECT_EQ(points[0], (std::array<double, 3>{0, 0, 0}));
  spec.faces = spec.vertices = false;
  spec.edge_points = 3;
  EXPECT_EQ(meshAimPoints(g, spec).size(), 24u);
}

// Faces alone (the edges and vertices not sorted out then) are the faces of
// every feature, target for target, in the same order.
TEST(AimRays, FacesAloneAreTheFacesOfEveryFeature) {
  Geometry g;
  makeTriangleGrid(8, 4, {8, 4}, {0, 0, 0}, g);
  AimSpec all, faces;
  faces.vertices = faces.edges = false;
  const std::vector<AimTarget> every = meshAimTargets(g, all), alone = meshAimTargets(g, faces);
  ASSERT_EQ(alone.size(), 64u);
  ASSERT_GE(every.size(), alone.size());
  for (size_t k = 0; k < alone.size(); ++k) {
    const AimTarget& t = every[every.size() - alone.size() + k];
    EXPECT_EQ(alone[k].feature, AimFeature::Face);
    EXPECT_EQ(alone[k].feature, t.feature);
    EXPECT_EQ(alone[k].primitives, t.primitives);
    EXPECT_EQ(alone[k].object, t.object);
  }
}

TEST(AimRays, ThroughTheInstanceTransform) {
  Scene s;
  Blas b;
  b.name = "m";
  Geometry g;
  makeTriangleFan({4, 1, {0, 0, 0}, 0}, g);
  b.geometries.push_back(g);
  s.blases.push_back(b);
  Instance inst;
  inst.blas = 0;
  inst.transform = {1, 0, 0, 1000, 0, 1, 0, 2000, 0, 0, 1, 0};
  s.instances.push_back(inst);
  AimSpec spec;
  spec.edges = spec.faces = false;
  spec.offset = {0, 0.5, 4};
  spec.direction_scale = 0.25;
  const auto rays = aimRays(s, spec, Ray{});
  ASSERT_TRUE(rays) << rays.error().format();
  ASSERT_EQ(rays->size(), 1u);  // the fan's centre
  EXPECT_EQ((*rays)[0].origin, (Vec3{1000, 2000.5f, 4}));
  EXPECT_EQ((*rays)[0].direction, (Vec3{0, -0.125f, -1}));
  spec.instance = 3;
  const auto none = aimRays(s, spec, Ray{});
  ASSERT_FALSE(none);
  EXPECT_NE(none.error().message.find("instance 3"), std::string::npos);
}

TEST(AimRays, CaseSyntaxAndErrors) {
  const std::string text = R"(rules: [R-WATERTIGHT]
scene:
  blas:
    fan:
      - triangles: {fan: {triangles: 6, radius: 2, seed: 3}}
    tri:
      - triangles: {triangulation: {cells: [3, 3], size: [3, 3], seed: 4}}
  instances: [{blas: fan}, {blas: tri}]
rays:
  aim: {instance: ${instance}, at: [${at}], edge_points: 2, offset: [0, 0, 3]}
pipeline: {miss: [[]], hit_groups: [{}]}
)";
  auto parse = [&](const std::string& instance, const std::string& at) {
    std::string t = text;
    t.replace(t.find("${instance}"), 11, instance);
    t.replace(t.find("${at}"), 5, at);
    return parseCaseText(t, "t.yaml", "family/t");
  };
  ParseResult fan = parse("0", "vertices, edges, faces");
  ASSERT_TRUE(fan.value);
  EXPECT_EQ(fan.value->rays.rays.size(), 1u + 6u * 2 + 6u);
  EXPECT_EQ(fan.value->rays.width, 19u);
  ParseResult tri = parse("1", "vertices");
  ASSERT_TRUE(tri.value);
  EXPECT_EQ(tri.value->rays.rays.size(), 4u);  // the inner vertices of a 3 x 3 triangulation
  ParseResult bad = parse("1", "corners");
  ASSERT_FALSE(bad.value);
  EXPECT_EQ(bad.errors[0].loc.line, 10);
  EXPECT_NE(bad.errors[0].message.find("unknown feature 'corners'"), std::string::npos);
  ParseResult none = parse("5", "faces");
  ASSERT_FALSE(none.value);
  EXPECT_NE(none.errors[0].message.find("instance 5"), std::string::npos);
}

TEST(GeneratedMesh, Errors) {
  auto parse_blas = [](const std::string& blas) {
    return parseCaseText(
        "rules: [R-WATERTIGHT]\nscene:\n  blas:\n    m:\n      - triangles: " + blas +
            "\n  instances: [{blas: m}]\nrays:\n  list: [{origin: [0, 0, 1], direction: [0, 0, "
            "-1]}]\npipeline: {miss: [[]], hit_groups: [{}]}\n",
        "t.yaml", "family/t");
  };
  auto expect = [](const ParseResult& r, const std::string& field, const std::string& text) {
    ASSERT_FALSE(r.value);
    ASSERT_FALSE(r.errors.empty());
    EXPECT_EQ(r.errors[0].loc.line, 5);
    EXPECT_NE(r.errors[0].loc.field.find(field), std::string::npos) << r.errors[0].format();
    EXPECT_NE(r.errors[0].message.find(text), std::string::npos) << r.errors[0].format();
  };
  expect(parse_blas("{fan: {triangles: 2}}"), "fan.triangles", "at least 3");
  expect(parse_blas("{fan: {triangles: 5, radius: -1}}"), "fan.radius", "positive");
  expect(parse_blas("{triangulation: {cells: [2, 2], size: [1, 1], seed: 1, jitter: 0.5}}"),
         "jitter", "0.25");
  expect(parse_blas("{triangulation: {cells: [2, 2], size: [1, 1]}}"), "triangulation", "seed");
  expect(parse_blas("{fan: {triangles: 5}, grid: {cells: [1, 1], size: [1, 1]}}"), "triangles",
         "one of them alone");
  expect(parse_blas("{subdivision: {triangles: 7, size: [1, 1], seed: 1}}"),
         "subdivision.triangles", "even number");
  expect(parse_blas("{subdivision: {triangles: 8, size: [1, 1], seed: 1, relief: -1}}"),
         "subdivision", "relief not negative");
  expect(parse_blas("{subdivision: {triangles: 8, size: [1, 1]}}"), "subdivision", "seed");
  EXPECT_TRUE(parse_blas("{fan: {triangles: 5, seed: 2}}").value);
  EXPECT_TRUE(parse_blas("{subdivision: {triangles: 8, size: [1, 1], seed: 2, relief: 1}}").value);
}

// scene.split: the fan's triangles in geometries or instances of their own,
// every world position bit identical to the fan's; the rays aimed at the
// whole fan first.
ParseResult parseSplit(const std::string& split, const std::string& center = "[0, 0, 0]") {
  return parseCaseText(
      "rules: [R-WATERTIGHT]\nscene:\n  blas:\n    m:\n      - triangles: {fan: {triangles: 6, "
      "radius: 2, center: " +
          center + "}}\n  instances: [{blas: m}]\n  split: " + split +
          "\nrays:\n  aim: {offset: [0, 0, 3]}\n  sbt_stride: 0\npipeline: {miss: [[]], "
          "hit_groups: "
          "[{}]}\n",
      "t.yaml", "family/t");
}

// The world corners of every triangle of the scene, in instance, geometry
// and primitive order.
std::vector<std::array<Vec3, 3>> worldTriangles(const Scene& s) {
  std::vector<std::array<Vec3, 3>> out;
  for (const Instance& inst : s.instances)
    for (const Geometry& g : s.blases[*inst.blas].geometries)
      for (uint32_t p = 0; p < g.primitiveCount(); ++p) {
        std::array<Vec3, 3> t;
        for (uint32_t v = 0; v < 3; ++v) {
          const Vec3& o = g.vertices[g.indices.empty() ? 3 * p + v : g.indices[3 * p + v]];
          for (int row = 0; row < 3; ++row) {
            double w = inst.transform[4 * row + 3];
            for (int col = 0; col < 3; ++col) w += double(inst.transform[4 * row + col]) * o[col];
            t[v][row] = static_cast<float>(w);
            EXPECT_EQ(double(t[v][row]), w);  // exact
          }
        }
        out.push_back(t);
      }
  return out;
}

TEST(SplitMesh, GeometriesAndInstancesKeepTheWorldFan) {
  Geometry fan;
  makeTriangleFan({6, 2, {0, 0, 0}, 0}, fan);
  Scene whole;
  whole.blases.push_back({"m", {fan}, {}});
  whole.instances.push_back(Instance{});
  whole.instances[0].blas = 0;
  const auto expected = worldTriangles(whole);
  const ParseResult geoms = parseSplit("{blas: m, into: geometries}");
  ASSERT_TRUE(geoms.value) << geoms.errors[0].format();
  EXPECT_EQ(geoms.value->rays.rays.size(), 1u + 6u + 6u);  // aimed at the whole fan
  ASSERT_EQ(geoms.value->scene.blases[0].geometries.size(), 6u);
  EXPECT_EQ(worldTriangles(geoms.value->scene), expected);
  const ParseResult insts = parseSplit("{blas: m, into: instances}");
  ASSERT_TRUE(insts.value) << insts.errors[0].format();
  ASSERT_EQ(insts.value->scene.instances.size(), 6u);
  ASSERT_EQ(insts.value->scene.blases.size(), 6u);
  EXPECT_EQ(worldTriangles(insts.value->scene), expected);
  const ParseResult moved =
      parseSplit("{blas: m, into: instances, translate: [0, 0, 4], cycle_axes: true}");
  ASSERT_TRUE(moved.value) << moved.errors[0].format();
  EXPECT_EQ(worldTriangles(moved.value->scene), expected);
  const Scene& ms = moved.value->scene;
  EXPECT_EQ(ms.instances[1].transform, (Transform{0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0, 4}));
  EXPECT_EQ(ms.instances[2].transform, (Transform{0, 1, 0, 0, 0, 0, 1, 0, 1, 0, 0, 0}));
}

TEST(SplitMesh, ErrorsNameTheField) {
  auto expect = [](const ParseResult& r, const std::string& text) {
    ASSERT_FALSE(r.value);
    ASSERT_FALSE(r.errors.empty());
    EXPECT_EQ(r.errors[0].loc.line, 7) << r.errors[0].format();
    EXPECT_NE(r.errors[0].loc.field.find("scene.split"), std::string::npos);
    EXPECT_NE(r.errors[0].message.find(text), std::string::npos) << r.errors[0].format();
  };
  expect(parseSplit("{blas: n, into: geometries}"), "unknown BLAS 'n'");
  expect(parseSplit("{blas: m, into: boxes}"), "unknown split 'boxes'");
  expect(parseSplit("{blas: m, into: geometries, translate: [1, 0, 0]}"), "only with into");
  // A fan about the origin moved by 0.1: its rim's coordinates leave the float grid.
  expect(parseSplit("{blas: m, into: instances, translate: [0.1, 0, 0]}"), "off the float grid");
}

// R-WATERTIGHT's frames (case/share_frame.h): the instances of the identity
// transform share one; any other transform, or another geometry transform,
// frames its triangles apart.
TEST(ShareFrame, IdentityInstancesShareGeometryTransformsApart) {
  Instance a, b, moved;
  moved.transform = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 4};
  EXPECT_EQ(shareFrame(a, 0, std::nullopt), shareFrame(b, 7, std::nullopt));
  EXPECT_EQ(shareFrame(a, 0, std::nullopt), shareFrame(a, 0, kIdentity));
  EXPECT_NE(shareFrame(moved, 1, std::nullopt), shareFrame(a, 0, std::nullopt));
  EXPECT_NE(shareFrame(moved, 1, std::nullopt), shareFrame(moved, 2, std::nullopt));
  EXPECT_EQ(shareFrame(moved, 1, std::nullopt), shareFrame(moved, 1, std::nullopt));
  const Transform scaled = {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0};
  EXPECT_NE(shareFrame(a, 0, scaled), shareFrame(a, 0, std::nullopt));
  EXPECT_EQ(shareFrame(a, 0, scaled), shareFrame(b, 3, scaled));
}

// aim.every: each k-th point of each feature, from the first.
TEST(AimRays, EveryKthPointOfEachFeature) {
  Geometry g;
  makeTriangleFan({8, 2, {0, 0, 0}, 0}, g);
  AimSpec spec;
  const std::vector<AimTarget> all = meshAimTargets(g, spec);
  ASSERT_EQ(all.size(), 1u + 8u + 8u);
  spec.every = 3;
  const std::vector<AimTarget> some = meshAimTargets(g, spec);
  ASSERT_EQ(some.size(), 1u + 3u + 3u);  // the centre; spokes 0, 3, 6; faces 0, 3, 6
  EXPECT_EQ(some[0].feature, AimFeature::Vertex);
  EXPECT_EQ(some[1].object, all[1].object);
  EXPECT_EQ(some[2].object, all[4].object);
  EXPECT_EQ(some[6].primitives, std::vector<uint32_t>{6});
}

}  // namespace
}  // namespace rayspec
