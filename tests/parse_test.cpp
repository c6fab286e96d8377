// Tests of the case reader: the values of good cases (errors: parse_errors_test.cpp,
// files: parse_files_test.cpp).
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "parse/parse_case.h"
#include "parse_support.h"

namespace rayspec {
namespace {

// kGood, parsed without an error.
Case goodCase() {
  ParseResult r = parse(kGood);
  EXPECT_TRUE(r.errors.empty()) << allErrors(r);
  return r.value ? *r.value : Case{};
}

TEST(ParseCase, GoodCaseValues) {
  const Case c = goodCase();
  EXPECT_EQ(c.name, "family/t");
  EXPECT_EQ(c.family, "family");
  EXPECT_EQ(c.rules, (std::vector<std::string>{"R-IGNORE", "R-MISS-XOR-CHIT"}));
  EXPECT_EQ(c.description, "a quad and an inactive instance");

  ASSERT_EQ(c.scene.blases.size(), 2u);
  const Geometry& quad = c.scene.blases[0].geometries.at(0);
  EXPECT_EQ(quad.kind, Geometry::Kind::Triangles);
  EXPECT_EQ(quad.primitiveCount(), 2u);
  EXPECT_EQ(quad.flags, kGeometryOpaque | kGeometryNoDuplicateAnyHit);
  EXPECT_EQ(quad.loc.line, 6);
  const Geometry& balls = c.scene.blases[1].geometries.at(0);
  EXPECT_EQ(balls.kind, Geometry::Kind::Aabbs);
  ASSERT_EQ(balls.aabbs.size(), 2u);
  EXPECT_TRUE(std::isnan(balls.aabbs[1][0]));
}

TEST(ParseCase, GoodCaseInstancesAndRays) {
  const Case c = goodCase();
  ASSERT_EQ(c.scene.instances.size(), 3u);
  const Instance& i0 = c.scene.instances[0];
  EXPECT_EQ(i0.blas, 0u);
  EXPECT_EQ(i0.mask, 0x0Fu);
  EXPECT_EQ(i0.custom_index, 7u);
  EXPECT_EQ(i0.sbt_offset, 1u);
  EXPECT_EQ(i0.flags, kInstanceFlipFacing | kInstanceForceOpaque);
  const float expect[12] = {0, -2, 0, 1, 2, 0, 0, 2, 0, 0, 2, 3};  // T * R(z, 90) * S(2)
  for (int k = 0; k < 12; ++k) EXPECT_NEAR(i0.transform[k], expect[k], 1e-6) << k;
  EXPECT_FALSE(c.scene.instances[1].blas.has_value());
  EXPECT_EQ(c.scene.instances[1].mask, 0xFFu);
  EXPECT_EQ(c.scene.instances[2].blas, 1u);
  EXPECT_EQ(c.scene.instances[2].transform[3], 5.0f);

  EXPECT_EQ(c.rays.width, 2u);
  EXPECT_EQ(c.rays.height, 2u);
  ASSERT_EQ(c.rays.rays.size(), 4u);
  EXPECT_EQ(c.rays.defaults.flags, kRayCullBackFacing | kRaySkipAabbs);
  EXPECT_EQ(c.rays.rays[3].flags, kRayCullBackFacing | kRaySkipAabbs);
  EXPECT_EQ(c.rays.rays[0].cull_mask, 0x1FFu);
  EXPECT_FLOAT_EQ(c.rays.rays[0].tmin, 0.001f);
  EXPECT_FLOAT_EQ(c.rays.rays[0].tmax, 100.0f);
}

TEST(ParseCase, GoodCasePipeline) {
  const Case c = goodCase();
  // Default raygen and default SBT.
  ASSERT_EQ(c.pipeline.raygen.size(), 1u);
  EXPECT_EQ(c.pipeline.raygen[0].kind, Stmt::Kind::Trace);
  EXPECT_EQ(c.pipeline.max_recursion, 1u);
  ASSERT_EQ(c.pipeline.sbt_miss.size(), 1u);
  EXPECT_EQ(c.pipeline.sbt_miss[0].group, 0u);
  ASSERT_EQ(c.pipeline.sbt_hit.size(), 2u);
  EXPECT_EQ(c.pipeline.sbt_hit[1].group, 1u);
  EXPECT_TRUE(c.pipeline.sbt_callable.empty());

  // Programs.
  ASSERT_EQ(c.pipeline.miss.size(), 1u);
  const Stmt& rec = c.pipeline.miss[0][1];
  EXPECT_EQ(rec.kind, Stmt::Kind::Record);
  ASSERT_EQ(rec.assigns.size(), 1u);
  EXPECT_EQ(rec.assigns[0].first, "hit");
  EXPECT_EQ(rec.assigns[0].second.type, ValueType::Uint);
  const HitGroup& g0 = c.pipeline.hit_groups[0];
  ASSERT_TRUE(g0.closest_hit);
  EXPECT_FALSE(g0.any_hit);
  const Stmt& rec2 = (*g0.closest_hit)[1];
  ASSERT_EQ(rec2.assigns.size(), 2u);
  EXPECT_EQ(rec2.assigns[1].first, "hit_t");
  EXPECT_EQ(rec2.assigns[1].second.kind, Expr::Kind::Builtin);
  EXPECT_EQ(rec2.assigns[1].second.type, ValueType::Float);
  const HitGroup& g1 = c.pipeline.hit_groups[1];
  ASSERT_TRUE(g1.any_hit && g1.intersection);
  const Stmt& cond = (*g1.any_hit)[0];
  EXPECT_EQ(cond.kind, Stmt::Kind::If);
  EXPECT_EQ(cond.cond.kind, Expr::Kind::Op);
  EXPECT_EQ(cond.cond.name, "odd");
  EXPECT_EQ(cond.cond.type, ValueType::Bool);
  EXPECT_EQ(cond.then_.at(0).kind, Stmt::Kind::Ignore);
  const Stmt& report = (*g1.intersection)[0].then_.at(0);
  EXPECT_EQ(report.kind, Stmt::Kind::Report);
  EXPECT_EQ(report.t.kind, Expr::Kind::Op);
  EXPECT_EQ(report.t.name, "sphere_near");
  EXPECT_EQ(report.hit_kind.literal, std::vector<double>{3});
  EXPECT_EQ(report.then_.at(0).counter, "reported");

  EXPECT_EQ(c.outputs.counters, (std::vector<std::string>{"miss", "closesthit", "reported"}));
  ASSERT_EQ(c.outputs.images.size(), 1u);
  EXPECT_EQ(c.outputs.images[0].field, "primitive_id");
}

TEST(ParseCase, CameraRayDirections2x2) {
  ParseResult r = parse(kGood);
  ASSERT_TRUE(r.value) << allErrors(r);
  const auto& rays = r.value->rays.rays;
  // fov 90, aspect 1: pixel centres at +-0.5 on the image plane at distance 1;
  // row 0 is the top (+y).
  const float s = static_cast<float>(1 / std::sqrt(1.5));
  const float expect[4][3] = {{-0.5f * s, 0.5f * s, -s},
                              {0.5f * s, 0.5f * s, -s},
                              {-0.5f * s, -0.5f * s, -s},
                              {0.5f * s, -0.5f * s, -s}};
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(rays[i].origin, (Vec3{0, 0, 5}));
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(rays[i].direction[k], expect[i][k], 1e-7) << i << "," << k;
  }
}

TEST(ParseCase, GridAndListRays) {
  const std::string grid = R"(rules: [R-MASK]
rays:
  grid: {size: [2, 1], origin: [0, 0, 1], du: [1, 0, 0], dv: [0, 2, 0], direction: [0, 0, -1]}
  tmax: 10
  miss: 1
pipeline: {miss: [[], []]}
)";
  ParseResult r = parse(grid);
  ASSERT_TRUE(r.value) << allErrors(r);
  ASSERT_EQ(r.value->rays.rays.size(), 2u);
  EXPECT_EQ(r.value->rays.rays[1].origin, (Vec3{1.5f, 1.0f, 1.0f}));
  EXPECT_EQ(r.value->rays.rays[1].direction, (Vec3{0, 0, -1}));
  EXPECT_EQ(r.value->rays.rays[1].tmax, 10.0f);
  EXPECT_EQ(r.value->rays.rays[1].miss, 1u);

  // A NaN tmin is undefined behaviour (R-UB): only a robustness probe may hold one.
  const std::string list = R"(rules: [R-MASK, R-UB]
rays:
  list:
    - {origin: [0, 0, 1], direction: [0, 0, -1]}
    - {origin: [0, 0, 1], direction: [0, 0, -1], flags: [opaque, terminate_on_first_hit], cull_mask: 0x80, tmin: .nan}
  tmin: 0.5
pipeline: {miss: [[]]}
)";
  r = parse(list);
  ASSERT_TRUE(r.value) << allErrors(r);
  ASSERT_EQ(r.value->rays.width, 2u);
  EXPECT_EQ(r.value->rays.height, 1u);
  EXPECT_EQ(r.value->rays.rays[0].tmin, 0.5f);
  EXPECT_EQ(r.value->rays.rays[1].flags, kRayOpaque | kRayTerminateOnFirstHit);
  EXPECT_EQ(r.value->rays.rays[1].cull_mask, 0x80u);
  EXPECT_TRUE(std::isnan(r.value->rays.rays[1].tmin));
}

TEST(ParseCase, TriangleGridGenerator) {
  ParseResult r = parse(R"(rules: [R-WATERTIGHT]
scene:
  blas:
    grid:
      - triangles: {grid: {cells: [2, 3], size: [2, 3], center: [0, 0, -1]}}
  instances: [{blas: grid}]
rays:
  list: [{origin: [0, 0, 1], direction: [0, 0, -1]}]
pipeline: {miss: [[]], hit_groups: [{}]}
)");
  ASSERT_TRUE(r.value) << allErrors(r);
  const Geometry& g = r.value->scene.blases[0].geometries[0];
  EXPECT_EQ(g.vertices.size(), 12u);
  EXPECT_EQ(g.primitiveCount(), 12u);
  EXPECT_EQ(g.vertices[0], (Vec3{-1, -1.5f, -1}));
  EXPECT_EQ(g.vertices[11], (Vec3{1, 1.5f, -1}));
  // primitive 0 is counter-clockwise seen from +z
  const Vec3 &a = g.vertices[g.indices[0]], &b = g.vertices[g.indices[1]],
             &c = g.vertices[g.indices[2]];
  const float nz = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  EXPECT_GT(nz, 0);
}

TEST(ParseCase, ExplicitSbtRaygenAndTrace) {
  const std::string text = R"(rules: [R-SBT-ZERO]
rays:
  list: [{origin: [0, 0, 1], direction: [0, 0, -1]}]
pipeline:
  max_recursion: 2
  raygen:
    - trace: {flags: [opaque, skip_closest_hit], cull_mask: 0xF0, miss: 1}
    - record: {value: payload.value, color: {vec4: [1, {float: launch_id_x}, 0, 1]}}
  raygen_data: {uints: [1, 0xFFFFFFFF]}
  miss:
    - [payload: {value: 1}]
    - []
  hit_groups:
    - closest_hit:
        - trace: {origin: hit_position, direction: world_ray_direction, tmin: 0.01}
        - payload: {value: child.value}
  callables:
    - [light: point]
  sbt:
    miss: [1, zero]
    hit: [{group: 0, data: {floats: [1, 2]}}, zero]
outputs:
  per_ray: [value, color]
)";
  ParseResult r = parse(text);
  ASSERT_TRUE(r.value) << allErrors(r);
  const Pipeline& p = r.value->pipeline;
  EXPECT_EQ(p.max_recursion, 2u);
  ASSERT_EQ(p.raygen.size(), 2u);
  const TraceArgs& t = p.raygen[0].trace;
  ASSERT_EQ(t.flags.size(), 1u);
  EXPECT_EQ(t.flags[0].kind, Expr::Kind::Literal);
  EXPECT_EQ(t.flags[0].type, ValueType::Uint);
  EXPECT_EQ(t.flags[0].literal[0], double(kRayOpaque | kRaySkipClosestHit));
  EXPECT_EQ(t.cull_mask.at(0).literal[0], 0xF0);
  EXPECT_TRUE(t.origin.empty());
  EXPECT_EQ(p.raygen[1].assigns[1].second.type, ValueType::Vec4);
  EXPECT_EQ(p.raygen_data, (std::vector<uint32_t>{1, 0xFFFFFFFFu}));
  ASSERT_EQ(p.sbt_miss.size(), 2u);
  EXPECT_EQ(p.sbt_miss[0].group, 1u);
  EXPECT_FALSE(p.sbt_miss[1].group.has_value());
  ASSERT_EQ(p.sbt_hit.size(), 2u);
  EXPECT_EQ(p.sbt_hit[0].group, 0u);
  const uint32_t one = std::bit_cast<uint32_t>(1.0f);
  ASSERT_EQ(p.sbt_hit[0].data.size(), 2u);
  EXPECT_EQ(p.sbt_hit[0].data[0], one);
  EXPECT_FALSE(p.sbt_hit[1].group.has_value());
  ASSERT_EQ(p.sbt_callable.size(), 1u);  // default region
  EXPECT_EQ(p.callables[0][0].light, "point");
}

TEST(ParseCase, ExpressionLiterals) {
  const std::string text = R"(rules: [R-PAYLOAD]
rays:
  list: [{origin: [0, 0, 1], direction: [0, 0, -1]}]
pipeline:
  miss:
    - - record: {value: 0xFF}
      - record: {value: {uint: -1}}
      - record: {value: {uint: {length: [3, 4]}}}
      - record: {color: [1, 2, 3.5, 1e2]}
      - if: {and: [{lt: [ray_tmax, 2]}, {not: false}]}
outputs:
  per_ray: [value, color]
)";
  ParseResult r = parse(text);
  ASSERT_TRUE(r.value) << allErrors(r);
  const Program& m = r.value->pipeline.miss.at(0);
  const Expr& hex = m[0].assigns[0].second;
  EXPECT_EQ(hex.type, ValueType::Uint);
  EXPECT_EQ(hex.literal[0], 255);
  const Expr& neg = m[1].assigns[0].second.args.at(0);
  EXPECT_EQ(neg.type, ValueType::Float);  // a sign makes it a Float
  EXPECT_EQ(neg.literal[0], -1);
  const Expr& len = m[2].assigns[0].second.args.at(0);
  EXPECT_EQ(len.name, "length");
  ASSERT_EQ(len.args.size(), 1u);  // [3, 4] is one Vec2 argument
  EXPECT_EQ(len.args[0].type, ValueType::Vec2);
  const Expr& color = m[3].assigns[0].second;
  EXPECT_EQ(color.type, ValueType::Vec4);
  EXPECT_EQ(color.literal, (std::vector<double>{1, 2, 3.5, 100}));
  const Expr& lt = m[4].cond.args.at(0);
  EXPECT_EQ(lt.args.at(1).type, ValueType::Float);  // 2 promoted next to a Float
  EXPECT_EQ(m[4].cond.args.at(1).args.at(0).type, ValueType::Bool);

  std::string big = text;
  big.replace(big.find("0xFF"), 4, "4294967296");
  expectError(parse(big), 6, "pipeline.miss[0][0].record.value", "32 bits");
  std::string unknown = text;
  unknown.replace(unknown.find("ray_tmax"), 8, "ray_tmux");
  expectError(parse(unknown), 10, "pipeline.miss[0][4].if.and[0].lt[0]", "unknown name 'ray_tmux'");
}

}  // namespace
}  // namespace rayspec

namespace rayspec {
namespace {

std::string withCounters(const std::string& counters) {
  std::string text = kGood;
  const std::string from = "counters: [miss, closesthit, reported]";
  text.replace(text.find(from), from.size(), "counters: " + counters);
  return text;
}

TEST(ParseCase, CounterModesAreDeclaredAsNameModePairs) {
  const ParseResult r = parse(withCounters("[miss, {closesthit: exact}, {reported: at_least}]"));
  ASSERT_TRUE(r.value) << allErrors(r);
  EXPECT_EQ(r.value->outputs.counters,
            (std::vector<std::string>{"miss", "closesthit", "reported"}));
  EXPECT_EQ(r.value->outputs.counter_modes.at("reported"), "at_least");
  EXPECT_EQ(r.value->outputs.counter_modes.at("closesthit"), "exact");
  EXPECT_EQ(r.value->outputs.counter_modes.count("miss"), 0u);
}

TEST(ParseCase, UnknownCounterModeIsAnError) {
  const ParseResult r = parse(withCounters("[miss, closesthit, {reported: sometimes}]"));
  expectError(r, 41, "outputs.counters[2].reported", "unknown counter mode 'sometimes'");
}

}  // namespace
}  // namespace rayspec

namespace rayspec {
namespace {

std::string withImage(const std::string& image) {
  std::string text = kGood;
  const size_t at = text.find("outputs:");
  EXPECT_NE(at, std::string::npos);
  const size_t images = text.find("images:", at);
  if (images == std::string::npos) return text;
  const size_t end = text.find('\n', images);
  text.insert(end + 1, "    - " + image + "\n");
  return text;
}

TEST(ParseCase, ImageThresholds) {
  const ParseResult r =
      parse(withImage("{name: tol, from: hit_t, tolerance: 4, max_failing_pixels: 2}"));
  ASSERT_TRUE(r.value) << allErrors(r);
  const ImageOutput& im = r.value->outputs.images.front();
  EXPECT_EQ(im.name, "tol");
  EXPECT_EQ(im.tolerance, 4.0);
  EXPECT_EQ(im.max_failing_pixels, 2u);
  const ParseResult bad = parse(withImage("{name: tol, from: hit_t, tolerance: 0}"));
  EXPECT_FALSE(bad.value);
  EXPECT_NE(allErrors(bad).find("tolerance scale must be above 0"), std::string::npos)
      << allErrors(bad);
}

}  // namespace
}  // namespace rayspec
