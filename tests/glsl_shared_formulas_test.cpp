// What the GLSL and the model share: the any-hit slot in GLSL is the formula
// of results/record_layout.h written as text (glsl/glsl_uint_text.h), the
// masks of a trace's arguments those of case/bit_widths.h.
#include <gtest/gtest.h>

#include "case/bit_widths.h"
#include "glsl/glsl_literal.h"
#include "glsl/glsl_uint_text.h"

namespace rayspec {
namespace {

TEST(GlslUintText, TheAnyHitSlotIsTheModelsFormula) {
  EXPECT_EQ(anyHitSlotGlsl("uint(gl_InstanceID)", "gl_GeometryIndexEXT", "uint(gl_PrimitiveID)"),
            "(uint(gl_InstanceID) * 13u + gl_GeometryIndexEXT * 5u + uint(gl_PrimitiveID)) & 31u");
  // The factors are the model's: a change of them changes both.
  EXPECT_EQ(anyHitSlotGlsl("i", "g", "p"), "(i * " + std::to_string(kAnyHitSlotInstanceFactor) +
                                               "u + g * " +
                                               std::to_string(kAnyHitSlotGeometryFactor) +
                                               "u + p) & " + std::to_string(kAnyHitSlotMask) + "u");
}

// The widths spelled as the GLSL spelled them before they had names.
TEST(GlslLiteral, TheBitWidthsAsHexMasks) {
  EXPECT_EQ(glslHexUint(kInstanceFieldMask), "0xFFFFFFu");
  EXPECT_EQ(glslHexUint(kTraceSbtFieldMask), "0xFu");
  EXPECT_EQ(glslHexUint(kTraceMissIndexMask), "0xFFFFu");
  EXPECT_EQ(glslHexUint(kVisibilityMask), "0xFFu");
  EXPECT_EQ(glslHexUint(0), "0x0u");
}

}  // namespace
}  // namespace rayspec
