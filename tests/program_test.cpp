// Tests of the stage vocabulary: tables, expression typing, program checks.
#include <gtest/gtest.h>

#include <set>

#include "program/builtins.h"
#include "program/constant_value.h"
#include "program/ops.h"

namespace rayspec {
namespace {

Expr lit(double v, ValueType t = ValueType::Uint) {
  Expr e;
  e.kind = Expr::Kind::Literal;
  e.type = t;
  e.literal = {v};
  return e;
}
Expr vec(std::vector<double> v) {
  Expr e;
  e.kind = Expr::Kind::Literal;
  e.literal = v;
  e.type = v.size() == 2 ? ValueType::Vec2 : v.size() == 3 ? ValueType::Vec3 : ValueType::Vec4;
  return e;
}
Expr builtin(const std::string& name, int line = 0) {
  SourceLoc loc;
  loc.line = line;
  return builtinExpr(name, loc);
}
Expr op(const std::string& name, std::vector<Expr> args, int line = 0) {
  Expr e;
  e.kind = Expr::Kind::Op;
  e.name = name;
  e.op = opNamed(name);
  e.args = std::move(args);
  e.loc.line = line;
  return e;
}
Stmt stmt(Stmt::Kind k, int line) {
  Stmt s;
  s.kind = k;
  s.loc.line = line;
  s.loc.field = "f" + std::to_string(line);
  return s;
}

TEST(Names, StageAndTypeNames) {
  EXPECT_STREQ(stageName(Stage::ClosestHit), "closest_hit");
  EXPECT_STREQ(stageName(Stage::AnyHit), "any_hit");
  EXPECT_STREQ(stageName(Stage::Callable), "callable");
  EXPECT_STREQ(valueTypeName(ValueType::Vec3), "Vec3");
  EXPECT_EQ(componentCount(ValueType::Float), 1);
  EXPECT_EQ(componentCount(ValueType::Vec2), 2);
  EXPECT_EQ(componentCount(ValueType::Vec4), 4);
}

TEST(Builtins, TableMatchesDocumentation) {
  std::set<std::string> names;
  for (const BuiltinInfo& b : builtins()) EXPECT_TRUE(names.insert(b.name).second) << b.name;
  // One row per Builtin, each name finding its own row and id; every row but
  // the word<i> and <type> families and hit (spelled by the emitter) has its GLSL.
  ASSERT_EQ(builtins().size(), size_t{kBiCount});
  const uint32_t int8 = static_cast<uint32_t>(ValueType::Int8);
  for (size_t i = 0; i < builtins().size(); ++i) {
    const BuiltinInfo& b = builtins()[i];
    const Builtin id = static_cast<Builtin>(i);
    EXPECT_EQ(findBuiltin(builtinSpelling(id, isSizedFamily(id) ? int8 : 3)), &b) << b.name;
    EXPECT_EQ(builtinId(&b), id) << b.name;
    const bool spelled_by_emitter = std::string(b.name).find("<i>") != std::string::npos ||
                                    isSizedFamily(id) || std::string(b.name) == "hit";
    EXPECT_EQ(b.glsl == nullptr, spelled_by_emitter) << b.name;
  }
  EXPECT_EQ(builtinId(findBuiltin("payload.word3")), kBiPayloadWord);
  EXPECT_EQ(builtinId(findBuiltin("no_such_builtin")), kBiUnknown);
  EXPECT_EQ(findBuiltin("launch_id_z")->stages, kAllStages);
  const BuiltinInfo* t = findBuiltin("hit_t");
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->type, ValueType::Float);
  EXPECT_EQ(t->stages, stageBit(Stage::AnyHit) | stageBit(Stage::ClosestHit));
  EXPECT_EQ(findBuiltin("launch_id_x")->stages, kAllStages);
  EXPECT_EQ(findBuiltin("aabb_min")->stages, stageBit(Stage::Intersection));
  EXPECT_EQ(findBuiltin("payload.color")->type, ValueType::Vec4);
  EXPECT_TRUE(findBuiltin("payload.value")->stages & stageBit(Stage::Raygen));
  EXPECT_FALSE(findBuiltin("payload.value")->stages & stageBit(Stage::Intersection));
  EXPECT_EQ(findBuiltin("hit")->stages, stageBit(Stage::ClosestHit) | stageBit(Stage::Miss));
  EXPECT_EQ(findBuiltin("barycentrics")->type, ValueType::Vec2);
  EXPECT_EQ(findBuiltin("nope"), nullptr);
}

TEST(Ops, TableMatchesDocumentation) {
  std::set<std::string> names;
  for (const OpInfo& o : ops()) EXPECT_TRUE(names.insert(o.name).second) << o.name;
  EXPECT_EQ(findOp("sphere_near")->stages, stageBit(Stage::Intersection));
  EXPECT_EQ(findOp("sphere_near")->max_args, 0);
  EXPECT_EQ(findOp("and")->min_args, 2);
  EXPECT_EQ(findOp("vec3")->max_args, 3);
  EXPECT_EQ(findOp("frobnicate"), nullptr);
}

// typeCheck's error message, "" when the expression checks.
std::string typeCheckMessage(Expr& e, Stage stage) {
  const Result<void> r = typeCheck(e, stage);
  return r ? std::string() : r.error().message;
}

TEST(TypeCheck, InfersTypes) {
  Expr e = op("add", {builtin("hit_t"), lit(1, ValueType::Float)});
  EXPECT_EQ(typeCheckMessage(e, Stage::ClosestHit), "");
  EXPECT_EQ(e.type, ValueType::Float);

  Expr v = op("mul", {builtin("world_ray_direction"), lit(2)});  // Uint literal promoted
  EXPECT_EQ(typeCheckMessage(v, Stage::Miss), "");
  EXPECT_EQ(v.type, ValueType::Vec3);
  EXPECT_EQ(v.args[1].type, ValueType::Float);

  Expr c = op("eq", {builtin("hit_kind"), lit(254)});
  EXPECT_EQ(typeCheckMessage(c, Stage::AnyHit), "");
  EXPECT_EQ(c.type, ValueType::Bool);

  Expr s = op("vec4", {lit(1, ValueType::Float)});
  EXPECT_EQ(typeCheckMessage(s, Stage::Raygen), "");
  EXPECT_EQ(s.type, ValueType::Vec4);

  Expr x = op("y", {builtin("barycentrics")});
  EXPECT_EQ(typeCheckMessage(x, Stage::ClosestHit), "");
  EXPECT_EQ(x.type, ValueType::Float);

  Expr n = op("sphere_near", {});
  EXPECT_EQ(typeCheckMessage(n, Stage::Intersection), "");
  EXPECT_EQ(n.type, ValueType::Float);
}

TEST(TypeCheck, RejectsBadTypes) {
  Expr e = op("odd", {builtin("hit_t")});
  EXPECT_NE(typeCheckMessage(e, Stage::ClosestHit).find("need Uint"), std::string::npos);
  Expr a = op("add", {builtin("primitive_id"), builtin("hit_t")});
  EXPECT_NE(typeCheckMessage(a, Stage::ClosestHit), "");
  Expr z = op("z", {builtin("barycentrics")});  // Vec2 has no z
  EXPECT_NE(typeCheckMessage(z, Stage::ClosestHit), "");
  Expr d = op("dot", {vec({1, 2}), vec({1, 2, 3})});
  EXPECT_NE(typeCheckMessage(d, Stage::Raygen), "");
  Expr div0 = op("div", {lit(4), lit(0)});
  EXPECT_NE(typeCheckMessage(div0, Stage::Raygen).find("zero"), std::string::npos);
  Expr rec = op("shader_record_uint", {lit(8)});
  EXPECT_NE(typeCheckMessage(rec, Stage::Miss), "");
  Expr arity = op("not", {lit(1, ValueType::Bool), lit(0, ValueType::Bool)});
  EXPECT_NE(typeCheckMessage(arity, Stage::Miss).find("argument"), std::string::npos);
}

TEST(ConstantValue, FoldsUintOperatorsAndLeavesRunTimeValuesOpen) {
  Expr e = op("add", {op("mul", {lit(3), lit(4)}), op("sub", {lit(1), lit(2)})});
  ASSERT_EQ(typeCheckMessage(e, Stage::Raygen), "");
  EXPECT_EQ(constantUint(e), 11u) << "3*4 + (1-2) modulo 2^32";
  Expr m = op("min", {op("mod", {lit(17), lit(5)}), op("div", {lit(9), lit(2)})});
  ASSERT_EQ(typeCheckMessage(m, Stage::Raygen), "");
  EXPECT_EQ(constantUint(m), 2u);
  Expr dynamic = op("add", {builtin("launch_id_x"), lit(1)});
  ASSERT_EQ(typeCheckMessage(dynamic, Stage::Raygen), "");
  EXPECT_FALSE(constantUint(dynamic));
  Expr f = lit(2.5, ValueType::Float);
  EXPECT_FALSE(constantUint(f));
  EXPECT_EQ(constantFloat(f), 2.5);
}

TEST(TypeCheck, UintDivisionOrModuloByAConstantZeroIsAnError) {
  Expr d = op("div", {builtin("launch_id_x"), op("sub", {lit(3), lit(3)})});
  EXPECT_NE(typeCheckMessage(d, Stage::Raygen).find("Uint division by a constant zero"),
            std::string::npos);
  Expr m = op("mod", {builtin("launch_id_y"), op("mul", {lit(0), builtin("launch_id_x")})});
  EXPECT_EQ(typeCheckMessage(m, Stage::Raygen), "") << "0 * a run-time value is not folded";
  Expr m0 = op("mod", {builtin("launch_id_y"), op("min", {lit(0), lit(4)})});
  EXPECT_NE(typeCheckMessage(m0, Stage::Raygen).find("Uint modulo by a constant zero"),
            std::string::npos);
  Expr fine = op("div", {lit(4), builtin("launch_id_x")});
  EXPECT_EQ(typeCheckMessage(fine, Stage::Raygen), "");
}

TEST(TypeCheck, StagePermissions) {
  Expr t = builtin("hit_t");
  EXPECT_NE(typeCheckMessage(t, Stage::Miss).find("cannot be read in miss"), std::string::npos);
  Expr s = op("sphere_hit", {});
  EXPECT_NE(typeCheckMessage(s, Stage::AnyHit), "");
  Expr a = builtin("aabb_max");
  EXPECT_EQ(typeCheckMessage(a, Stage::Intersection), "");
  Expr u = builtin("unknown_thing");
  EXPECT_NE(typeCheckMessage(u, Stage::Raygen).find("unknown built-in"), std::string::npos);
}

TEST(CheckProgram, StatementKindsPerStage) {
  Program p = {stmt(Stmt::Kind::Ignore, 7)};
  auto e = checkProgram(p, Stage::ClosestHit, {}, {});
  ASSERT_TRUE(e);
  EXPECT_EQ(e->loc.line, 7);
  EXPECT_NE(e->message.find("'ignore' is not allowed in closest_hit"), std::string::npos);
  EXPECT_FALSE(checkProgram(p, Stage::AnyHit, {}, {}));

  Program t = {stmt(Stmt::Kind::Terminate, 3)};
  EXPECT_TRUE(checkProgram(t, Stage::Intersection, {}, {}));
  Program light = {stmt(Stmt::Kind::Light, 2)};
  light[0].light = "point";
  EXPECT_TRUE(checkProgram(light, Stage::Miss, {}, {}));
  EXPECT_FALSE(checkProgram(light, Stage::Callable, {}, {}));
}

TEST(CheckProgram, NestedBlocksAreChecked) {
  Stmt s = stmt(Stmt::Kind::If, 4);
  s.cond = op("odd", {builtin("primitive_id")});
  s.then_ = {stmt(Stmt::Kind::Terminate, 5)};
  s.else_ = {stmt(Stmt::Kind::Ignore, 6)};
  Program p = {s};
  EXPECT_FALSE(checkProgram(p, Stage::AnyHit, {}, {}));
  auto e = checkProgram(p, Stage::ClosestHit, {}, {});
  ASSERT_TRUE(e);
  EXPECT_EQ(e->loc.line, 5);  // the first bad statement inside `then`
}

TEST(CheckProgram, ConditionMustBeBool) {
  Stmt s = stmt(Stmt::Kind::If, 4);
  s.cond = builtin("primitive_id", 9);
  Program p = {s};
  auto e = checkProgram(p, Stage::ClosestHit, {}, {});
  ASSERT_TRUE(e);
  EXPECT_EQ(e->loc.line, 9);
  EXPECT_NE(e->message.find("expected Bool"), std::string::npos);
}

TEST(CheckProgram, TypeErrorPointsAtInnermostNode) {
  Stmt s = stmt(Stmt::Kind::If, 4);
  s.cond =
      op("and", {op("odd", {builtin("primitive_id")}, 10), op("odd", {builtin("hit_t")}, 11)}, 12);
  Program p = {s};
  auto e = checkProgram(p, Stage::AnyHit, {}, {});
  ASSERT_TRUE(e);
  EXPECT_EQ(e->loc.line, 11);
}

TEST(CheckProgram, CountersMustBeDeclared) {
  Stmt s = stmt(Stmt::Kind::Count, 2);
  s.counter = "anyhit";
  Program p = {s};
  EXPECT_FALSE(checkProgram(p, Stage::AnyHit, {"anyhit"}, {}));
  auto e = checkProgram(p, Stage::AnyHit, {"miss"}, {});
  ASSERT_TRUE(e);
  EXPECT_NE(e->message.find("outputs.counters"), std::string::npos);
}

TEST(CheckProgram, RecordFields) {
  Stmt s = stmt(Stmt::Kind::Record, 2);
  s.assigns = {{"ray_tmin", lit(1)}};  // Uint literal where Float is wanted: promoted
  Program p = {s};
  EXPECT_FALSE(checkProgram(p, Stage::Miss, {}, {"ray_tmin"}));
  EXPECT_EQ(p[0].assigns[0].second.type, ValueType::Float);
  // not declared
  auto e = checkProgram(p, Stage::Miss, {}, {"hit"});
  ASSERT_TRUE(e);
  EXPECT_NE(e->message.find("outputs.per_ray"), std::string::npos);
  // automatic field
  Stmt a = stmt(Stmt::Kind::Record, 3);
  a.assigns = {{"miss_runs", lit(1)}};
  Program pa = {a};
  e = checkProgram(pa, Stage::Miss, {}, {"miss_runs"});
  ASSERT_TRUE(e);
  EXPECT_NE(e->message.find("automatic"), std::string::npos);
  // component count mismatch: barycentrics is Vec2, world_ray_origin Vec3
  Stmt b = stmt(Stmt::Kind::Record, 4);
  b.assigns = {{"barycentrics", builtin("world_ray_origin", 44)}};
  Program pb = {b};
  e = checkProgram(pb, Stage::ClosestHit, {}, {"barycentrics"});
  ASSERT_TRUE(e);
  EXPECT_EQ(e->loc.line, 44);
  // unknown field
  Stmt u = stmt(Stmt::Kind::Record, 5);
  u.assigns = {{"colour", vec({1, 2, 3, 4})}};
  Program pu = {u};
  EXPECT_TRUE(checkProgram(pu, Stage::ClosestHit, {}, {"colour"}));
}

TEST(CheckProgram, PayloadAndCallData) {
  Stmt s = stmt(Stmt::Kind::SetPayload, 2);
  s.assigns = {{"color", vec({1, 0, 0, 1})}, {"value", builtin("primitive_id")}};
  Program p = {s};
  EXPECT_FALSE(checkProgram(p, Stage::ClosestHit, {}, {}));
  EXPECT_TRUE(checkProgram(p, Stage::Callable, {}, {}));  // payload not in callable
  Stmt bad = stmt(Stmt::Kind::SetPayload, 3);
  bad.assigns = {{"color", vec({1, 0, 0})}};
  Program pb = {bad};
  EXPECT_TRUE(checkProgram(pb, Stage::Miss, {}, {}));
  Stmt c = stmt(Stmt::Kind::SetCall, 4);
  c.assigns = {{"value", lit(3)}};
  Program pc = {c};
  EXPECT_FALSE(checkProgram(pc, Stage::Callable, {}, {}));
  EXPECT_TRUE(checkProgram(pc, Stage::Miss, {}, {}));
}

TEST(CheckProgram, ReportTraceCall) {
  Stmt r = stmt(Stmt::Kind::Report, 2);
  r.t = op("sphere_near", {});
  r.hit_kind = lit(1);
  r.attribute = {vec({0.5, 0.5})};
  Program pr = {r};
  EXPECT_FALSE(checkProgram(pr, Stage::Intersection, {}, {}));
  pr[0].hit_kind = lit(200);
  EXPECT_TRUE(checkProgram(pr, Stage::Intersection, {}, {}));  // kind > 127
  pr[0].hit_kind = lit(1, ValueType::Float);
  EXPECT_TRUE(checkProgram(pr, Stage::Intersection, {}, {}));  // kind must be Uint

  Stmt t = stmt(Stmt::Kind::Trace, 3);
  Program pt = {t};
  EXPECT_FALSE(checkProgram(pt, Stage::Raygen, {}, {}));
  EXPECT_TRUE(checkProgram(pt, Stage::ClosestHit, {}, {}));  // origin/direction required
  pt[0].trace.origin = {builtin("hit_position")};
  pt[0].trace.direction = {builtin("world_ray_direction")};
  pt[0].trace.tmin = {lit(0)};
  EXPECT_FALSE(checkProgram(pt, Stage::ClosestHit, {}, {}));
  EXPECT_TRUE(checkProgram(pt, Stage::AnyHit, {}, {}));  // no trace in any-hit
  pt[0].trace.flags = {lit(1, ValueType::Float)};
  EXPECT_TRUE(checkProgram(pt, Stage::ClosestHit, {}, {}));

  Stmt c = stmt(Stmt::Kind::Call, 4);
  c.call_index = lit(0);
  c.assigns = {{"position", builtin("hit_position")}, {"normal", vec({0, 0, 1})}};
  Program pc = {c};
  EXPECT_FALSE(checkProgram(pc, Stage::ClosestHit, {}, {}));
  EXPECT_TRUE(checkProgram(pc, Stage::AnyHit, {}, {}));
  pc[0].call_index = lit(0, ValueType::Float);
  EXPECT_TRUE(checkProgram(pc, Stage::ClosestHit, {}, {}));
}

}  // namespace
}  // namespace rayspec
