// The GLSL text of a uint expression, whose * + & write the expression: a
// formula of results/ written once as a template (anyHitSlotOf) reads as
// numbers in the model and the judge and as GLSL here. The operands of * and
// + are primary expressions (a name, a call, a literal); & parenthesizes its
// left side.
#pragma once

#include <cstdint>
#include <string>

#include "results/record_layout.h"

namespace rayspec {

struct GlslUint {
  std::string text;
};
inline GlslUint operator*(const GlslUint& a, uint32_t k) {
  return {a.text + " * " + std::to_string(k) + "u"};
}
inline GlslUint operator+(const GlslUint& a, const GlslUint& b) {
  return {a.text + " + " + b.text};
}
inline GlslUint operator&(const GlslUint& a, uint32_t k) {
  return {"(" + a.text + ") & " + std::to_string(k) + "u"};
}

// The any-hit slot of a primitive (results/record_layout.h anyHitSlotOf), in GLSL.
inline std::string anyHitSlotGlsl(const std::string& instance, const std::string& geometry,
                                  const std::string& primitive) {
  return anyHitSlotOf(GlslUint{instance}, GlslUint{geometry}, GlslUint{primitive}).text;
}

}  // namespace rayspec
