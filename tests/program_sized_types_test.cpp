// The sized scalars and vectors (program/sized_types.h): their rows, the
// conversion ops and constructors generated from them, the typing of
// literals and ops on them, and the values each type holds exactly
// (program/sized_values.h).
#include <gtest/gtest.h>

#include <cmath>

#include "program/locals.h"
#include "program/ops.h"
#include "program/sized_values.h"

namespace rayspec {
namespace {

Expr sizedLit(double v, ValueType t = ValueType::Uint) {
  Expr e;
  e.kind = Expr::Kind::Literal;
  e.type = t;
  e.literal = {v};
  return e;
}
Expr sizedOp(const std::string& name, std::vector<Expr> args) {
  Expr e;
  e.kind = Expr::Kind::Op;
  e.name = name;
  e.op = opNamed(name);
  e.args = std::move(args);
  return e;
}
std::string sizedTypeMessage(Expr& e) {
  const Result<void> r = typeCheck(e, Stage::Raygen);
  return r ? std::string() : r.error().message;
}

TEST(SizedTypes, EachRowIsAValueTypeAndAConversionOp) {
  int rows = 0;
  for (ValueType t : enumValues<ValueType>()) {
    const SizedType* s = sizedType(t);
    if (!s || isSizedVector(t)) continue;
    ++rows;
    EXPECT_EQ(s->type, t);
    EXPECT_EQ(valueTypeNamed(valueTypeSpelling(t)), t);
    const Op convert = opNamed(valueTypeSpelling(t));  // {int8: x} .. {float64: x}
    ASSERT_TRUE(isConversion(convert)) << valueTypeSpelling(t);
    EXPECT_EQ(conversionTarget(convert), t);
    EXPECT_EQ(std::string(opInfo(convert).glsl), std::string(valueTypeGlsl(t)) + "($0)");
    EXPECT_EQ(componentCount(t), 1);
  }
  EXPECT_EQ(rows, 9);
  EXPECT_EQ(sizedType(ValueType::Uint), nullptr);
  EXPECT_STREQ(valueTypeGlsl(ValueType::Float64), "float64_t");
  EXPECT_EQ(sizedType(ValueType::Int16)->bits, 16);
  EXPECT_EQ(sizedType(ValueType::Uint64)->kind, SizedKind::Unsigned);
  EXPECT_TRUE(isSizedFloat(ValueType::Float16));
  EXPECT_FALSE(isSizedInteger(ValueType::Float64));
  EXPECT_NE(arrayTypeSpellings().find("vec4, int8"), std::string::npos);
}

TEST(SizedTypes, LiteralsTakeTheirPartnersTypeWithinItsValues) {
  Expr a = sizedOp("add", {sizedOp("int8", {sizedLit(3)}), sizedLit(100)});
  EXPECT_EQ(sizedTypeMessage(a), "");
  EXPECT_EQ(a.type, ValueType::Int8);
  EXPECT_EQ(a.args[1].type, ValueType::Int8);
  Expr wide =
      sizedOp("add", {sizedOp("int8", {sizedLit(3)}), sizedLit(128)});  // 127 is int8's largest
  EXPECT_NE(sizedTypeMessage(wide).find("out of range 0..127"), std::string::npos);
  Expr half = sizedOp("mul", {sizedOp("float16", {sizedLit(3)}), sizedLit(1.5, ValueType::Float)});
  EXPECT_EQ(sizedTypeMessage(half), "");
  EXPECT_EQ(half.type, ValueType::Float16);
  Expr fine = sizedOp("mul", {sizedOp("float16", {sizedLit(3)}), sizedLit(0.1, ValueType::Float)});
  EXPECT_NE(sizedTypeMessage(fine).find("not a Float16 value"), std::string::npos);
  Expr big = sizedOp("mul", {sizedOp("uint64", {sizedLit(7)}), sizedLit(4294967295)});
  EXPECT_EQ(sizedTypeMessage(big), "");
  EXPECT_EQ(big.type, ValueType::Uint64);
}

TEST(SizedTypes, OnlyExactOpsAndDefinedConversionsType) {
  Expr div = sizedOp("div", {sizedOp("int16", {sizedLit(9)}), sizedLit(3)});
  EXPECT_NE(sizedTypeMessage(div).find("div is not offered"), std::string::npos);
  Expr mixed = sizedOp("add", {sizedOp("int16", {sizedLit(9)}), sizedOp("uint16", {sizedLit(3)})});
  EXPECT_NE(sizedTypeMessage(mixed), "");
  Expr from_float = sizedOp("int64", {sizedLit(2.5, ValueType::Float)});  // no float -> integer
  EXPECT_NE(sizedTypeMessage(from_float).find("need Uint or a sized integer"), std::string::npos);
  Expr narrow = sizedOp("int8", {sizedOp("uint64", {sizedLit(5)})});
  EXPECT_EQ(sizedTypeMessage(narrow), "");
  Expr to_float = sizedOp("float", {sizedOp("float64", {sizedLit(5)})});
  EXPECT_EQ(sizedTypeMessage(to_float), "");
  EXPECT_EQ(to_float.type, ValueType::Float);
  Expr high = sizedOp("high", {sizedOp("int64", {sizedLit(5)})});
  EXPECT_EQ(sizedTypeMessage(high), "");
  Expr high32 = sizedOp("high", {sizedOp("int16", {sizedLit(5)})});
  EXPECT_NE(sizedTypeMessage(high32).find("need Int64 or Uint64"), std::string::npos);
  Expr lt = sizedOp("lt", {sizedOp("float16", {sizedLit(5)}), sizedLit(2)});
  EXPECT_EQ(sizedTypeMessage(lt), "");
  EXPECT_EQ(lt.args[1].type, ValueType::Float16);
  Expr to_uint = sizedOp("uint", {sizedOp("int8", {sizedLit(5)})});
  EXPECT_EQ(sizedTypeMessage(to_uint), "");
}

TEST(SizedTypes, EachScalarHasVectorsOfTwoThreeAndFourWithConstructors) {
  int vectors = 0;
  for (ValueType t : enumValues<ValueType>()) {
    if (!isSizedVector(t)) continue;
    ++vectors;
    const ValueType component = sizedComponent(t);
    EXPECT_TRUE(isSizedScalar(component) || component == ValueType::Uint);  // uvec2 .. uvec4
    if (component != ValueType::Uint) {
      EXPECT_EQ(sizedType(t), sizedType(component));  // the component's row
    }
    EXPECT_EQ(sizedVectorOf(component, componentCount(t)), t);
    EXPECT_EQ(valueTypeNamed(valueTypeSpelling(t)), t);
    const Op make = opNamed(valueTypeSpelling(t));  // {i8vec2: ..} .. {f64vec4: ..}
    ASSERT_TRUE(isSizedConstructor(make)) << valueTypeSpelling(t);
    EXPECT_EQ(constructorTarget(make), t);
  }
  EXPECT_EQ(vectors, 30);  // 9 sized scalars' and uint's
  EXPECT_STREQ(valueTypeSpelling(ValueType::Uint8Vec3), "u8vec3");
  EXPECT_STREQ(valueTypeGlsl(ValueType::Float64Vec4), "f64vec4");
  EXPECT_EQ(componentCount(ValueType::Int16Vec2), 2);
  EXPECT_EQ(sizedComponent(ValueType::Float16Vec4), ValueType::Float16);
  EXPECT_EQ(sizedComponent(ValueType::Vec3), ValueType::Vec3);
  EXPECT_FALSE(isSizedVector(ValueType::Vec2));
  EXPECT_TRUE(isSizedFloat(ValueType::Float64Vec2));
}

// int32 is core GLSL's int (its vectors ivec2 .. ivec4): no #extension, no
// device feature; the 32-bit unsigned scalar stays `uint`, spelled once.
TEST(SizedTypes, Int32IsCoreIntAndUintHasNoSecondSpelling) {
  const SizedType* s = sizedType(ValueType::Int32Vec3);
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->type, ValueType::Int32);
  EXPECT_EQ(s->bits, 32);
  EXPECT_EQ(s->kind, SizedKind::Signed);
  EXPECT_STREQ(s->extension, "");
  EXPECT_STREQ(s->feature, "");
  EXPECT_STREQ(valueTypeGlsl(ValueType::Int32), "int");
  EXPECT_STREQ(valueTypeSpelling(ValueType::Int32Vec4), "ivec4");
  EXPECT_EQ(valueTypeNamed("ivec2"), ValueType::Int32Vec2);
  EXPECT_FALSE(valueTypeNamed("uint32").has_value());
  EXPECT_EQ(wrapToType(ValueType::Int32, 0x80000000u), static_cast<uint64_t>(INT32_MIN));
  Expr big = sizedOp("add", {sizedOp("int32", {sizedLit(3)}), sizedLit(2147483648.0)});
  EXPECT_NE(sizedTypeMessage(big).find("out of range 0..2147483647"), std::string::npos)
      << sizedTypeMessage(big);
}

// uvec2 .. uvec4 are uint's vectors: the sized vectors' machinery with the
// core Uint as component (its row makes no scalar: uint is not sized).
TEST(SizedTypes, UintVectorsTakeUintAsTheirComponent) {
  EXPECT_EQ(valueTypeNamed("uvec3"), ValueType::UintVec3);
  EXPECT_STREQ(valueTypeGlsl(ValueType::UintVec4), "uvec4");
  EXPECT_EQ(componentCount(ValueType::UintVec2), 2);
  EXPECT_TRUE(isSizedVector(ValueType::UintVec3));
  EXPECT_TRUE(isSizedInteger(ValueType::UintVec3));
  EXPECT_FALSE(isSized(ValueType::Uint));
  EXPECT_EQ(sizedComponent(ValueType::UintVec4), ValueType::Uint);
  EXPECT_EQ(sizedVectorOf(ValueType::Uint, 3), ValueType::UintVec3);
  const SizedType* s = sizedType(ValueType::UintVec2);
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->bits, 32);
  EXPECT_EQ(s->kind, SizedKind::Unsigned);
  EXPECT_STREQ(s->feature, "");
  EXPECT_EQ(wrapToType(ValueType::UintVec2, 0x1FFFFFFFFull), 0xFFFFFFFFu);
  Expr make = sizedOp("uvec3", {sizedLit(1), sizedLit(4000000000.0), sizedLit(3)});
  EXPECT_EQ(sizedTypeMessage(make), "");
  EXPECT_EQ(make.type, ValueType::UintVec3);
  Expr scaled = sizedOp("mul", {sizedOp("uvec2", {sizedLit(7)}), sizedLit(3)});
  EXPECT_EQ(sizedTypeMessage(scaled), "");
  EXPECT_EQ(scaled.type, ValueType::UintVec2);
  Expr z = sizedOp("z", {sizedOp("uvec4", {sizedLit(2)})});
  EXPECT_EQ(sizedTypeMessage(z), "");
  EXPECT_EQ(z.type, ValueType::Uint);
  Expr wrong = sizedOp("uvec2", {sizedLit(1.5, ValueType::Float), sizedLit(2)});
  EXPECT_NE(sizedTypeMessage(wrong).find("need Uint scalars"), std::string::npos);
}

TEST(SizedTypes, VectorsTypeLaneByLaneAndTheirLiteralsTakeTheComponentType) {
  Expr make = sizedOp("i8vec3", {sizedLit(1), sizedLit(2), sizedOp("int8", {sizedLit(3)})});
  EXPECT_EQ(sizedTypeMessage(make), "");
  EXPECT_EQ(make.type, ValueType::Int8Vec3);
  EXPECT_EQ(make.args[0].type, ValueType::Int8);
  Expr splat = sizedOp("f16vec4", {sizedLit(1.5, ValueType::Float)});
  EXPECT_EQ(sizedTypeMessage(splat), "");
  Expr two = sizedOp("u16vec3", {sizedLit(1), sizedLit(2)});
  EXPECT_NE(sizedTypeMessage(two).find("takes 1 (splat) or 3"), std::string::npos);
  Expr wrong = sizedOp("i64vec2", {sizedOp("uint64", {sizedLit(1)}), sizedLit(2)});
  EXPECT_NE(sizedTypeMessage(wrong).find("need Int64 scalars"), std::string::npos);
  Expr scaled = sizedOp("mul", {sizedOp("i16vec2", {sizedLit(7)}), sizedLit(3)});
  EXPECT_EQ(sizedTypeMessage(scaled), "");
  EXPECT_EQ(scaled.type, ValueType::Int16Vec2);
  EXPECT_EQ(scaled.args[1].type, ValueType::Int16);
  Expr y = sizedOp("y", {sizedOp("f64vec3", {sizedLit(2)})});
  EXPECT_EQ(sizedTypeMessage(y), "");
  EXPECT_EQ(y.type, ValueType::Float64);
  Expr w = sizedOp("w", {sizedOp("u8vec3", {sizedLit(2)})});
  EXPECT_NE(sizedTypeMessage(w).find("need a vector with a .w component"), std::string::npos);
  Expr compared =
      sizedOp("lt", {sizedOp("i8vec2", {sizedLit(2)}), sizedOp("i8vec2", {sizedLit(3)})});
  EXPECT_NE(sizedTypeMessage(compared), "");  // comparisons are of scalars
  Expr to_uint = sizedOp("uint", {sizedOp("u8vec2", {sizedLit(2)})});
  EXPECT_NE(sizedTypeMessage(to_uint), "");
}

TEST(SizedValues, Float16HoldsElevenSignificantBitsOfNormalNumbers) {
  EXPECT_TRUE(exactInFloat16(0));
  EXPECT_TRUE(exactInFloat16(-20.5));
  EXPECT_TRUE(exactInFloat16(2047));
  EXPECT_FALSE(exactInFloat16(2049));  // 12 significant bits
  EXPECT_TRUE(exactInFloat16(65504));
  EXPECT_FALSE(exactInFloat16(65536));
  EXPECT_TRUE(exactInFloat16(std::ldexp(1.0, -14)));
  EXPECT_FALSE(exactInFloat16(std::ldexp(1.0, -15)));  // a denormal: a device may flush it
  EXPECT_TRUE(exactInFloat32(16777216.0));
  EXPECT_FALSE(exactInFloat32(16777217.0));
}

TEST(SizedValues, IntegersWrapToTheirBitsAndSignedness) {
  EXPECT_EQ(wrapToType(ValueType::Int8, 300), 44u);
  EXPECT_EQ(wrapToType(ValueType::Int8, 200), static_cast<uint64_t>(-56));
  EXPECT_EQ(wrapToType(ValueType::Uint8, static_cast<uint64_t>(-1)), 255u);
  EXPECT_EQ(wrapToType(ValueType::Int16, 0x18000), static_cast<uint64_t>(-32768));
  EXPECT_EQ(wrapToType(ValueType::Uint64, 0xFFFFFFFFFFFFFFFFull), 0xFFFFFFFFFFFFFFFFull);
}

}  // namespace
}  // namespace rayspec
