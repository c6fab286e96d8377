// The shader record block's member offsets under std430 and scalar
// (program/shader_record_layout.h), against offsets worked out by hand from
// the two rules.
#include <gtest/gtest.h>

#include "program/shader_record_layout.h"

namespace rayspec {
namespace {

ShaderRecordLayout layout(bool scalar, std::vector<ValueType> types) {
  ShaderRecordLayout l;
  l.scalar = scalar;
  for (size_t i = 0; i < types.size(); ++i)
    l.members.push_back({"m" + std::to_string(i), types[i], 0, {}});
  layOutShaderRecord(l);
  return l;
}

std::vector<uint32_t> offsets(const ShaderRecordLayout& l) {
  std::vector<uint32_t> out;
  for (const RecordMember& m : l.members) out.push_back(m.offset);
  return out;
}

TEST(ShaderRecordLayout, Std430AlignsVectorsAndLetsAScalarFollowAVec3) {
  using enum ValueType;
  const ShaderRecordLayout a = layout(false, {Uint, Vec2, Vec3, Float});
  EXPECT_EQ(offsets(a), (std::vector<uint32_t>{0, 8, 16, 28}));
  EXPECT_EQ(a.bytes, 32u);
  const ShaderRecordLayout b = layout(false, {Float, Vec3, Float});
  EXPECT_EQ(offsets(b), (std::vector<uint32_t>{0, 16, 28}));
  const ShaderRecordLayout c = layout(false, {Float, Vec4});
  EXPECT_EQ(offsets(c), (std::vector<uint32_t>{0, 16}));
  EXPECT_EQ(c.bytes, 32u);
}

TEST(ShaderRecordLayout, ScalarPacksEveryMemberAtFourBytes) {
  using enum ValueType;
  const ShaderRecordLayout a = layout(true, {Uint, Vec2, Vec3, Float});
  EXPECT_EQ(offsets(a), (std::vector<uint32_t>{0, 4, 12, 24}));
  EXPECT_EQ(a.bytes, 28u);
  EXPECT_EQ(offsets(layout(true, {Float, Vec3, Float})), (std::vector<uint32_t>{0, 4, 16}));
  EXPECT_EQ(memberAlignment(Vec4, true), 4u);
  EXPECT_EQ(memberAlignment(Vec4, false), 16u);
}

}  // namespace
}  // namespace rayspec
