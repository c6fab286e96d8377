// GLSL spellings of constants: exact float literals, uint literals.
#pragma once

#include <cstdint>
#include <string>

namespace rayspec {

// Shortest decimal that reads back as exactly f (whether the compiler parses
// it straight to float or through double), e.g. "0.1", "1.0", "1e+30";
// negatives in parentheses; NaN / infinity as uintBitsToFloat(0x...u).
std::string glslFloat(float f);
std::string glslDouble(double d);     // "(2.5lf)": every double exactly (%.17g)
std::string glslUint(uint32_t u);     // "42u"
std::string glslHexUint(uint32_t u);  // "0xFFFFFFu": a bit mask

}  // namespace rayspec
