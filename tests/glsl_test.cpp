// The GLSL generator: every statement kind and stage of hand-built cases
// compiles to valid SPIR-V; layouts come from the C++ tables; only what the
// plan needs is declared; ray and scene packing.
#include <gtest/gtest.h>
#include <bit>
#include <cstring>

#include <cmath>
#include <map>
#include <regex>
#include <set>

#include "glsl/bindings.h"
#include "glsl/embedded_shaders.h"
#include "glsl/generate_glsl.h"
#include "glsl/glsl_literal.h"
#include "program/ops.h"
#include "results/record_layout.h"
#include "spirv/compile_glsl.h"

namespace rayspec {
namespace {

// ---- building programs by hand ----
Expr u(uint32_t v) {
  Expr e;
  e.kind = Expr::Kind::Literal;
  e.type = ValueType::Uint;
  e.literal = {double(v)};
  return e;
}
Expr f(double v) {
  Expr e;
  e.kind = Expr::Kind::Literal;
  e.type = ValueType::Float;
  e.literal = {v};
  return e;
}
Expr v2(double a, double b) {
  Expr e = f(a);
  e.type = ValueType::Vec2;
  e.literal = {a, b};
  return e;
}
Expr v3(double a, double b, double c) {
  Expr e = f(a);
  e.type = ValueType::Vec3;
  e.literal = {a, b, c};
  return e;
}
Expr b(const std::string& name) {
  return builtinExpr(name);
}
Expr op(const std::string& name, std::vector<Expr> args = {}) {
  Expr e;
  e.kind = Expr::Kind::Op;
  e.name = name;
  e.op = opNamed(name);
  e.args = std::move(args);
  return e;
}
Stmt count(const std::string& n) {
  Stmt s;
  s.kind = Stmt::Kind::Count;
  s.counter = n;
  return s;
}
Stmt record(std::vector<std::pair<std::string, Expr>> a) {
  Stmt s;
  s.kind = Stmt::Kind::Record;
  s.assigns = std::move(a);
  return s;
}
Stmt recordBuiltins(const std::vector<std::string>& names) {
  std::vector<std::pair<std::string, Expr>> a;
  for (const auto& n : names) a.push_back({n, b(n)});
  return record(a);
}
Stmt kind(Stmt::Kind k) {
  Stmt s;
  s.kind = k;
  return s;
}
Stmt assign(Stmt::Kind k, std::vector<std::pair<std::string, Expr>> a) {
  Stmt s = kind(k);
  s.assigns = std::move(a);
  return s;
}
Stmt ifs(Expr cond, Program then_, Program else_ = {}) {
  Stmt s = kind(Stmt::Kind::If);
  s.cond = std::move(cond);
  s.then_ = std::move(then_);
  s.else_ = std::move(else_);
  return s;
}
Stmt light(const std::string& l) {
  Stmt s = kind(Stmt::Kind::Light);
  s.light = l;
  return s;
}
Stmt call(Expr index, std::vector<std::pair<std::string, Expr>> a) {
  Stmt s = assign(Stmt::Kind::Call, std::move(a));
  s.call_index = std::move(index);
  return s;
}
Stmt trace(Expr origin, Expr direction) {
  Stmt s = kind(Stmt::Kind::Trace);
  s.trace.origin = {origin};
  s.trace.direction = {direction};
  return s;
}

// The scene of fullCase: a triangle and two boxes, one instance each.
void fullScene(Case& c) {
  Blas tri{"tri", {}, {}};
  Geometry g;
  g.vertices = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
  tri.geometries.push_back(g);
  Blas box{"box", {}, {}};
  Geometry a;
  a.kind = Geometry::Kind::Aabbs;
  a.aabbs = {{-1, -1, -1, 1, 1, 1}, {2, 2, 2, 3, 3, 3}};
  box.geometries.push_back(a);
  c.scene.blases = {tri, box};
  Instance i0, i1;
  i0.blas = 0;
  i1.blas = 1;
  c.scene.instances = {i0, i1};
}

// Two rays down the z axis, every counter, record field and image.
void fullRaysAndOutputs(Case& c) {
  c.rays.width = 2;
  c.rays.height = 1;
  Ray r;
  r.origin = {0, 0, 5};
  r.direction = {0, 0, -1};
  c.rays.rays = {r, r};
  c.rays.defaults.tmin = 0.001f;
  c.rays.defaults.tmax = 100.0f;
  c.outputs.counters = {"miss", "anyhit", "ignored", "closesthit", "isect", "calls"};
  c.outputs.per_ray = {"hit",
                       "primitive_id",
                       "hit_t",
                       "barycentrics",
                       "hit_kind",
                       "instance_id",
                       "geometry_index",
                       "instance_custom_index",
                       "world_ray_origin",
                       "hit_position",
                       "depth",
                       "value",
                       "color",
                       "ray_tmin",
                       "ray_tmax",
                       "incoming_ray_flags",
                       "object_ray_origin",
                       "object_ray_direction",
                       "world_ray_direction"};
  c.outputs.images = {
      {"primitive", "primitive_id", {}}, {"color", "color", {}}, {"t", "hit_t", {}}};
}

// raygen traces, records and calls; the two miss shaders trace again and call.
void fullRaygenAndMiss(Pipeline& p) {
  p.max_recursion = 3;
  Stmt rg = kind(Stmt::Kind::Trace);
  rg.trace.tmax = {f(50.0)};
  p.raygen = {rg, record({{"color", b("payload.color")}, {"value", b("payload.value")}}),
              call(u(0), {{"position", v3(0, 0, 0)}, {"normal", v3(0, 0, 1)}}),
              ifs(op("gt", {op("x", {b("callee.color")}), f(0.5)}), {count("calls")})};
  p.miss = {{count("miss"), recordBuiltins({"hit", "depth", "world_ray_origin", "ray_tmax"}),
             assign(Stmt::Kind::SetPayload, {{"value", u(7)}, {"color", op("vec4", {f(0.25)})}}),
             ifs(op("lt", {b("depth"), u(2)}),
                 {trace(b("world_ray_origin"), v3(0, 0, 1)),
                  record({{"value", op("add", {b("child.value"), u(1)})}})})},
            {call(u(1), {{"value", u(3)}}), record({{"value", b("callee.value")}})}};
}

// The triangles' closest-hit (traces, calls) and any-hit (ignores, terminates).
HitGroup fullTriangleGroup() {
  HitGroup tris;
  tris.closest_hit =
      Program{count("closesthit"),
              recordBuiltins({"hit", "primitive_id", "hit_t", "barycentrics", "hit_kind",
                              "instance_id", "geometry_index", "instance_custom_index",
                              "hit_position", "incoming_ray_flags", "object_ray_origin",
                              "object_ray_direction", "world_ray_direction", "ray_tmin"}),
              assign(Stmt::Kind::SetPayload, {{"color", op("vec4", {f(1), f(0), f(0), f(1)})},
                                              {"value", op("mod", {b("primitive_id"), u(3)})}}),
              ifs(op("and", {op("lt", {b("depth"), u(3)}), op("eq", {b("hit_kind"), u(254)})}),
                  {trace(b("hit_position"), op("normalize", {v3(1, 1, 1)}))}),
              call(op("shader_record_uint", {u(0)}), {{"position", b("hit_position")},
                                                      {"normal", v3(0, 0, 1)},
                                                      {"color", op("vec4", {f(0)})}}),
              assign(Stmt::Kind::SetPayload, {{"color", b("callee.color")}})};
  tris.any_hit =
      Program{count("anyhit"),
              ifs(op("odd", {b("primitive_id")}), {count("ignored"), kind(Stmt::Kind::Ignore)},
                  {ifs(op("ge", {b("hit_t"), op("mul", {f(2), b("ray_tmin")})}),
                       {kind(Stmt::Kind::Terminate)})}),
              assign(Stmt::Kind::SetPayload, {{"value", op("add", {b("payload.value"), u(1)})}}),
              record({{"barycentrics", op("sub", {b("barycentrics"), v2(0.5, 0.5)})}})};
  return tris;
}

// The boxes' intersection shader (reports spheres), closest-hit and any-hit.
HitGroup fullSphereGroup() {
  HitGroup spheres;
  Stmt rep = kind(Stmt::Kind::Report);
  rep.t = op("sphere_near");
  rep.hit_kind = u(5);
  rep.attribute = {op("vec2", {op("sphere_far"), op("x", {b("aabb_min")})})};
  rep.then_ = {count("isect")};
  rep.else_ = {record({{"value", u(99)}})};
  Stmt rep2 = kind(Stmt::Kind::Report);
  rep2.t = op("float", {b("primitive_id")});
  rep2.hit_kind = u(0);
  spheres.intersection =
      Program{recordBuiltins({"object_ray_origin"}), ifs(op("sphere_hit"), {rep}, {rep2}),
              record({{"color", op("vec4", {op("length", {b("aabb_max")})})}})};
  spheres.closest_hit = Program{recordBuiltins({"hit", "barycentrics", "hit_kind"}),
                                record({{"ray_tmax", op("round", {b("hit_t")})}})};
  spheres.any_hit = Program{ifs(op("eq", {b("hit_kind"), u(5)}), {kind(Stmt::Kind::Ignore)})};
  return spheres;
}

// A case using every statement kind in every stage that allows it.
Case fullCase() {
  Case c;
  c.name = "test/every-statement";
  fullScene(c);
  fullRaysAndOutputs(c);
  Pipeline& p = c.pipeline;
  fullRaygenAndMiss(p);
  p.hit_groups = {fullTriangleGroup(), fullSphereGroup()};
  p.callables = {
      {light("point"), record({{"color", b("call.color")}})},
      {light("spot"), assign(Stmt::Kind::SetCall, {{"value", op("add", {b("call.value"), u(1)})}})},
      {light("directional"),
       call(u(1), {{"value", b("call.value")}, {"position", b("call.position")}}),
       assign(Stmt::Kind::SetCall,
              {{"value", b("callee.value")},
               {"color", op("mul", {b("callee.color"), op("shader_record_float", {u(7)})})}})}};
  return c;
}

Plan fullPlan(const Case& c) {
  Plan plan;
  plan.triangles = plan.aabbs = plan.any_hit = plan.intersection = true;
  plan.closest_hit = plan.miss = plan.callables = plan.nested_trace = true;
  plan.trace_depth = 3;
  plan.scene_data = true;
  plan.counters = c.outputs.counters;
  plan.record_fields = c.outputs.per_ray;
  plan.records = true;
  plan.images = c.outputs.images;
  return plan;
}

// Type-checks every program with the vocabulary of harness/program (fills
// Expr::type), so the hand-built programs are ones a case file could hold.
void typeCheckAll(Case& c) {
  auto check = [&](Program& p, Stage s) {
    auto e = checkProgram(p, s, c.outputs.counters, c.outputs.per_ray);
    ASSERT_FALSE(e.has_value()) << stageName(s) << ": " << e->message << " at " << e->loc.field;
  };
  check(c.pipeline.raygen, Stage::Raygen);
  for (auto& m : c.pipeline.miss) check(m, Stage::Miss);
  for (auto& h : c.pipeline.hit_groups) {
    if (h.closest_hit) check(*h.closest_hit, Stage::ClosestHit);
    if (h.any_hit) check(*h.any_hit, Stage::AnyHit);
    if (h.intersection) check(*h.intersection, Stage::Intersection);
  }
  for (auto& k : c.pipeline.callables) check(k, Stage::Callable);
}

std::vector<GeneratedShader> allShaders(const GeneratedPipeline& g) {
  std::vector<GeneratedShader> v{g.raygen};
  v.insert(v.end(), g.miss.begin(), g.miss.end());
  for (const auto& h : g.hit_groups)
    for (const auto* s : {&h.closest_hit, &h.any_hit, &h.intersection})
      if (*s) v.push_back(**s);
  v.insert(v.end(), g.callables.begin(), g.callables.end());
  return v;
}

// Descriptor bindings (set 0) a SPIR-V module declares: OpDecorate id Binding n.
std::set<uint32_t> spirvBindings(const std::vector<uint32_t>& words) {
  std::set<uint32_t> out;
  for (size_t w = 5; w < words.size();) {
    const uint32_t n = words[w] >> 16, opcode = words[w] & 0xFFFF;
    if (n == 0) break;
    if (opcode == 71 && n >= 4 && words[w + 2] == 33) out.insert(words[w + 3]);
    w += n;
  }
  return out;
}

std::string allText(const std::vector<GeneratedShader>& shaders) {
  std::string s;
  for (const auto& sh : shaders) s += sh.glsl;
  return s;
}

class GenerateGlsl : public ::testing::Test {
 protected:
  void SetUp() override {
    c = fullCase();
    typeCheckAll(c);
    plan = fullPlan(c);
    g = generateGlsl(c, plan);
    shaders = allShaders(g);
  }
  Case c;
  Plan plan;
  GeneratedPipeline g;
  std::vector<GeneratedShader> shaders;
};

TEST_F(GenerateGlsl, SharedPiecesAreEmbedded) {
  for (const char* name :
       {"common.glsl", "payload.glsl", "scene.glsl", "sphere.glsl", "lights.glsl"})
    EXPECT_EQ(embeddedShaders().count(name), 1u) << name;
}

TEST_F(GenerateGlsl, EveryStageCompilesToValidSpirv) {
  ASSERT_EQ(shaders.size(), 1u + 2u + 5u + 3u);
  EXPECT_EQ(g.hit_groups.size(), 2u);
  EXPECT_EQ(g.hit_groups[1].intersection->name, "hit1.intersection");
  for (const auto& sh : shaders) {
    SpirvResult r = compileGlsl(sh.glsl, sh.stage, sh.compute);
    EXPECT_TRUE(r.error.empty()) << sh.name << ":\n" << r.error;
    EXPECT_FALSE(r.words.empty()) << sh.name;
  }
}

TEST_F(GenerateGlsl, EveryStatementKindIsEmitted) {
  const std::string all = allText(shaders);
  for (const char* needle :
       {"rs_count(0u);  // count \"miss\"", "ignoreIntersectionEXT;", "terminateRayEXT;",
        "reportIntersectionEXT(rs_sphere_current().t_near, 5u)", "} else {", "traceRayEXT(rs_tlas",
        "executeCallableEXT(rs_index, 0);", "executeCallableEXT(rs_index, 1);",
        "call.color = rs_light_point(call.position, call.normal);", "rs_light_spot(",
        "rs_light_directional(", "payload.value = 7u;", "call.value = (call.value + 1u);",
        "rs_record_vec2(RS_FIELD_BARYCENTRICS", "imageStore(rs_image_0",
        "rs_bump_runs(RS_FIELD_ANY_HIT_RUNS);"})
    EXPECT_NE(all.find(needle), std::string::npos) << needle;
  // Each stage says which case and stage it is.
  for (const auto& sh : shaders) {
    EXPECT_NE(sh.glsl.find("// rayspec case: test/every-statement"), std::string::npos);
    EXPECT_NE(sh.glsl.find("(" + sh.name + ")"), std::string::npos) << sh.name;
  }
}

TEST_F(GenerateGlsl, NestedTracesUseTheCaseDefaultsAndTheNextDepth) {
  const std::string& chit = g.hit_groups[0].closest_hit->glsl;
  EXPECT_NE(chit.find("child.depth = payload.depth + 1u;"), std::string::npos);
  EXPECT_NE(chit.find("float rs_tmin = " + glslFloat(0.001f) + ";"), std::string::npos) << chit;
  EXPECT_NE(chit.find("float rs_tmax = 100.0;"), std::string::npos);
  // The nested trace's payload (location 0 of the case, 1 in this stage: its
  // incoming payload is 0), copied into `child` after the trace.
  EXPECT_NE(chit.find("layout(location = 1) rayPayloadEXT RsPayload rs_payload_0;"),
            std::string::npos);
  EXPECT_NE(chit.find("rs_payload_0.depth = payload.depth + 1u;"), std::string::npos);
  EXPECT_NE(chit.find("child = rs_payload_0;"), std::string::npos);
  // Raygen: the launch's ray, with the given tmax overriding it.
  const std::string& rg = g.raygen.glsl;
  // (a global: a function's trace takes its fields too)
  EXPECT_NE(rg.find("\nRsRay rs_ray;"), std::string::npos);
  EXPECT_NE(rg.find("rs_ray = rs_load_ray(rs_launch_index());"), std::string::npos);
  EXPECT_NE(rg.find("vec3 rs_origin = rs_ray.origin;"), std::string::npos);
  EXPECT_NE(rg.find("float rs_tmax = 50.0;"), std::string::npos);
  EXPECT_NE(rg.find("payload.depth = 1u;"), std::string::npos);
}

TEST_F(GenerateGlsl, RecordOffsetsEqualRecordLayout) {
  const std::regex def(R"(#define (RS_FIELD|RS_BIT)_([A-Z_]+) (\d+)u)");
  std::set<std::string> seen;
  for (const auto& sh : shaders) {
    for (auto it = std::sregex_iterator(sh.glsl.begin(), sh.glsl.end(), def);
         it != std::sregex_iterator(); ++it) {
      std::string name = (*it)[2];
      for (char& ch : name) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
      const int index = recordFieldIndex(name);
      ASSERT_GE(index, 0) << name;
      const uint32_t value = static_cast<uint32_t>(std::stoul((*it)[3]));
      if ((*it)[1] == "RS_FIELD")
        EXPECT_EQ(value, recordFields()[index].offset) << name;
      else
        EXPECT_EQ(value, static_cast<uint32_t>(index)) << name;
      seen.insert(name);
    }
    EXPECT_NE(sh.glsl.find("#define RS_RECORD_WORDS " + std::to_string(recordWords()) + "\n"),
              std::string::npos);
    EXPECT_NE(sh.glsl.find("#define RS_RAY_WORDS " + std::to_string(kRayWords) + "\n"),
              std::string::npos);
  }
  // Every recordable field of the case and every automatic count was defined somewhere.
  for (const auto& f : c.outputs.per_ray) EXPECT_TRUE(seen.count(f)) << f;
  for (const auto& f : recordFields()) {
    if (f.automatic) {
      EXPECT_TRUE(seen.count(f.name)) << f.name;
    }
  }
}

TEST_F(GenerateGlsl, BindingsFollowThePlan) {
  // Full plan: raygen holds TLAS, rays, records, counters and the 3 images.
  SpirvResult rg = compileGlsl(g.raygen.glsl, Stage::Raygen);
  ASSERT_TRUE(rg.error.empty()) << rg.error;
  EXPECT_EQ(
      spirvBindings(rg.words),
      (std::set<uint32_t>{kBindingTlas, kBindingRays, kBindingRecords, kBindingCounters,
                          kBindingFirstImage, kBindingFirstImage + 1, kBindingFirstImage + 2}));
  SpirvResult isect = compileGlsl(g.hit_groups[1].intersection->glsl, Stage::Intersection);
  ASSERT_TRUE(isect.error.empty()) << isect.error;
  EXPECT_EQ(spirvBindings(isect.words),
            (std::set<uint32_t>{kBindingRecords, kBindingCounters, kBindingScene}));
  // Image formats follow the field types.
  EXPECT_NE(g.raygen.glsl.find("r32ui) uniform writeonly uimage2D rs_image_0"), std::string::npos);
  EXPECT_NE(g.raygen.glsl.find("rgba32f) uniform writeonly image2D rs_image_1"), std::string::npos);
  EXPECT_NE(
      g.raygen.glsl.find("uintBitsToFloat(rs_record_word(RS_FIELD_HIT_T, 0u)), 0.0, 0.0, 1.0)"),
      std::string::npos);
}

// The records are reached through a buffer reference (no maxStorageBufferRange
// limit): every stage that records enables GL_EXT_buffer_reference, and the
// binding at kBindingRecords holds the reference, not the words.
TEST_F(GenerateGlsl, RecordsAreReachedByDeviceAddress) {
  int recording = 0;
  for (const auto& sh : shaders) {
    if (sh.glsl.find("#define RS_USE_RECORDS") == std::string::npos) continue;
    ++recording;
    EXPECT_NE(sh.glsl.find("#extension GL_EXT_buffer_reference : require"), std::string::npos)
        << sh.name;
    EXPECT_NE(sh.glsl.find("layout(buffer_reference"), std::string::npos) << sh.name;
    EXPECT_NE(sh.glsl.find("RsRecordWords rs_records_ref;"), std::string::npos) << sh.name;
  }
  EXPECT_EQ(recording, static_cast<int>(shaders.size()));
}

TEST(GenerateGlslMinimal, NothingThePlanDoesNotName) {
  Case c;
  c.name = "test/minimal";
  Plan plan;               // no records, counters, images, scene data
  Stmt m = count("miss");  // a counter the plan does not keep
  c.pipeline.raygen = {kind(Stmt::Kind::Trace)};
  c.pipeline.miss = {{m}};
  HitGroup h;
  h.closest_hit = Program{};
  h.any_hit = Program{kind(Stmt::Kind::Ignore)};
  c.pipeline.hit_groups = {h};
  GeneratedPipeline g = generateGlsl(c, plan);
  EXPECT_FALSE(g.hit_groups[0].any_hit.has_value()) << "plan.any_hit is false";
  ASSERT_TRUE(g.hit_groups[0].closest_hit.has_value());
  for (const auto& sh : allShaders(g)) {
    SpirvResult r = compileGlsl(sh.glsl, sh.stage, sh.compute);
    ASSERT_TRUE(r.error.empty()) << sh.name << ":\n" << r.error;
    const std::set<uint32_t> bindings = spirvBindings(r.words);
    if (sh.stage == Stage::Raygen)
      EXPECT_EQ(bindings, (std::set<uint32_t>{kBindingTlas, kBindingRays})) << sh.name;
    else
      EXPECT_TRUE(bindings.empty()) << sh.name;
    EXPECT_EQ(sh.glsl.find("image2D"), std::string::npos);
    EXPECT_EQ(sh.glsl.find("#define RS_USE_RECORDS"), std::string::npos);
    EXPECT_EQ(sh.glsl.find("rs_bump_runs(RS_FIELD"), std::string::npos);
    EXPECT_EQ(sh.glsl.find("scene.glsl"), std::string::npos);
  }
  // A raygen trace that gives every field does not read the rays buffer.
  Stmt t = trace(v3(0, 0, 1), v3(0, 0, -1));
  for (auto* v : {&t.trace.tmin, &t.trace.tmax}) v->push_back(f(1));
  for (auto* v : {&t.trace.flags, &t.trace.cull_mask, &t.trace.sbt_offset, &t.trace.sbt_stride,
                  &t.trace.miss})
    v->push_back(u(0));
  c.pipeline.raygen = {t};
  GeneratedShader rg = generateGlsl(c, plan).raygen;
  SpirvResult r = compileGlsl(rg.glsl, Stage::Raygen);
  ASSERT_TRUE(r.error.empty()) << r.error;
  EXPECT_EQ(spirvBindings(r.words), (std::set<uint32_t>{kBindingTlas}));
}

// rays.same: the rays buffer holds one ray, and raygen loads it for every id.
TEST(GenerateGlslMinimal, TheSameRayIsLoadedForEveryLaunchId) {
  Case c;
  c.name = "test/same";
  Plan plan;
  c.pipeline.raygen = {kind(Stmt::Kind::Trace)};
  c.pipeline.miss = {{}};
  const std::string per_id = generateGlsl(c, plan).raygen.glsl;
  EXPECT_NE(per_id.find("rs_ray = rs_load_ray(rs_launch_index());"), std::string::npos) << per_id;
  c.rays.same = true;
  const std::string same = generateGlsl(c, plan).raygen.glsl;
  EXPECT_NE(same.find("rs_ray = rs_load_ray(0u);"), std::string::npos) << same;
  EXPECT_EQ(same.find("rs_load_ray(rs_launch_index())"), std::string::npos) << same;
  const SpirvResult r = compileGlsl(same, Stage::Raygen);
  EXPECT_TRUE(r.error.empty()) << r.error;
}

TEST_F(GenerateGlsl, OutputIsDeterministic) {
  GeneratedPipeline again = generateGlsl(c, plan);
  EXPECT_EQ(allText(allShaders(again)), allText(shaders));
}

// The shaderRecordEXT block declares the case's record data bytes
// (pipeline.sbt.record_data / 4 words), default 8; every stage still compiles
// (the lights' fixed word indices go through a function parameter).
TEST_F(GenerateGlsl, ShaderRecordBlockHoldsTheRecordDataWords) {
  size_t users = 0;
  for (const auto& sh : shaders)
    if (sh.glsl.find("#define RS_USE_SHADER_RECORD") != std::string::npos) {
      ++users;
      EXPECT_NE(sh.glsl.find("#define RS_SHADER_RECORD_WORDS 8\n"), std::string::npos) << sh.name;
    }
  ASSERT_GT(users, 0u);
  c.pipeline.sbt_record_data = 24;
  for (const auto& sh : allShaders(generateGlsl(c, plan))) {
    if (sh.glsl.find("#define RS_USE_SHADER_RECORD") == std::string::npos) continue;
    EXPECT_NE(sh.glsl.find("#define RS_SHADER_RECORD_WORDS 6\n"), std::string::npos) << sh.name;
    EXPECT_NE(sh.glsl.find("uint words[RS_SHADER_RECORD_WORDS];"), std::string::npos) << sh.name;
    SpirvResult r = compileGlsl(sh.glsl, sh.stage, sh.compute);
    EXPECT_TRUE(r.error.empty()) << sh.name << ":\n" << r.error;
  }
}

TEST(GenerateGlslErrors, AStageMisuseFailsWithTheLine) {
  Case c;
  c.pipeline.raygen = {kind(Stmt::Kind::Trace)};
  c.pipeline.miss = {{kind(Stmt::Kind::Ignore)}};  // any-hit only
  Plan plan;
  GeneratedPipeline g = generateGlsl(c, plan);
  SpirvResult r = compileGlsl(g.miss[0].glsl, Stage::Miss);
  EXPECT_TRUE(r.words.empty());
  EXPECT_NE(r.error.find("| #error rayspec: ignore is only allowed in any_hit"), std::string::npos)
      << r.error;
}

TEST(GlslLiteral, FloatsAreExact) {
  for (float v : {0.1f, 1.0f, -2.5f, 1e30f, 3.4028235e38f, 1.17549435e-38f, 1e-45f, 0.001f,
                  16777217.0f, 123456.789f, -0.0f}) {
    std::string s = glslFloat(v);
    ASSERT_FALSE(s.empty());
    if (s.front() == '(') s = s.substr(1, s.size() - 2);
    float back = std::strtof(s.c_str(), nullptr);
    EXPECT_EQ(std::memcmp(&back, &v, 4), 0) << s;
    EXPECT_NE(s.find_first_of(".e"), std::string::npos) << s;
  }
  EXPECT_EQ(glslFloat(1.0f), "1.0");
  EXPECT_EQ(glslFloat(0.1f), "0.1");
  EXPECT_EQ(glslFloat(100.0f), "100.0");
  EXPECT_EQ(glslFloat(-2.5f), "(-2.5)");
  EXPECT_EQ(glslFloat(1e30f), "1e+30");
  EXPECT_EQ(glslFloat(std::numeric_limits<float>::infinity()), "uintBitsToFloat(0x7F800000u)");
  EXPECT_EQ(glslUint(4294967295u), "4294967295u");
}

uint32_t bits(float v) {
  return std::bit_cast<uint32_t>(v);
}

TEST(Bindings, PackRaysRoundTripsFloatBits) {
  Rays rays;
  Ray a;
  a.origin = {std::nanf("0x123"), -0.0f, 1e-45f};
  a.direction = {1.0f / 3.0f, -1e30f, std::numeric_limits<float>::infinity()};
  a.tmin = 0.001f;
  a.tmax = 3.4028235e38f;
  a.flags = 0x204;
  a.cull_mask = 0x0F;
  a.sbt_offset = 3;
  a.sbt_stride = 17;
  a.miss = 0x10001;
  Ray z;
  rays.rays = {z, a};
  std::vector<uint32_t> w = packRays(rays);
  ASSERT_EQ(w.size(), 2 * kRayWords);
  const uint32_t* r = w.data() + kRayWords;
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(r[k], bits(a.origin[k])) << k;
    EXPECT_EQ(r[4 + k], bits(a.direction[k])) << k;
  }
  EXPECT_EQ(r[3], bits(a.tmin));
  EXPECT_EQ(r[7], bits(a.tmax));
  EXPECT_EQ(r[8], 0x204u);
  EXPECT_EQ(r[9], 0x0Fu);
  EXPECT_EQ(r[10], 3u);
  EXPECT_EQ(r[11], 17u);
  EXPECT_EQ(r[12], 0x10001u);
  EXPECT_EQ(r[13] | r[14] | r[15], 0u);
  EXPECT_EQ(w[11], 1u);  // default sbt_stride of the first ray
  EXPECT_EQ(w[9], 0xFFu);
}

// The reader of shaders/scene.glsl, in C++.
std::array<float, 6> sceneBox(const std::vector<uint32_t>& s, uint32_t inst, uint32_t geom,
                              uint32_t prim) {
  const uint32_t table = s[1 + inst];
  const uint32_t w = s[table + geom] + 6 * prim;
  std::array<float, 6> box;
  for (int k = 0; k < 6; ++k) box[k] = std::bit_cast<float>(s[w + k]);
  return box;
}

TEST(Bindings, SceneDataFindsEveryBox) {
  Scene scene;
  Blas tri{"tri", {Geometry{}}, {}};
  tri.geometries[0].vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  Blas boxes{"boxes", {}, {}};
  for (int g = 0; g < 3; ++g) {
    Geometry geo;
    geo.kind = Geometry::Kind::Aabbs;
    for (int p = 0; p <= g; ++p)
      geo.aabbs.push_back({float(g), float(p), 0, float(g) + 1, float(p) + 1, 0.5f});
    boxes.geometries.push_back(geo);
  }
  Blas other{"other", {Geometry{}}, {}};
  other.geometries[0].kind = Geometry::Kind::Aabbs;
  other.geometries[0].aabbs = {{-9, -9, -9, 9, 9, 9}};
  scene.blases = {tri, boxes, other};
  Instance i0, i1, i2, i3, i4;
  i0.blas = 1;  // boxes
  i1.blas = 0;  // triangles
  // i2: null
  i3.blas = 2;
  i4.blas = 1;
  scene.instances = {i0, i1, i2, i3, i4};
  std::vector<uint32_t> s = packSceneData(scene);
  ASSERT_EQ(s[0], 5u);
  EXPECT_EQ(s[2], kSceneNoTable);
  EXPECT_EQ(s[3], kSceneNoTable);
  EXPECT_EQ(s[1], s[5]);  // one table per BLAS
  for (uint32_t inst : {0u, 4u})
    for (uint32_t g = 0; g < 3; ++g)
      for (uint32_t p = 0; p <= g; ++p)
        EXPECT_EQ(sceneBox(s, inst, g, p), boxes.geometries[g].aabbs[p])
            << inst << " " << g << " " << p;
  EXPECT_EQ(sceneBox(s, 3, 0, 0), other.geometries[0].aabbs[0]);
  // Header, 1 table of 3 + 1 table of 1, 7 boxes.
  EXPECT_EQ(s.size(), 1u + 5u + 3u + 1u + 6u * 7u);
}

}  // namespace
}  // namespace rayspec
