#include "glsl/glsl_literal.h"

#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace rayspec {
namespace {

std::string bitsLiteral(float f) {
  const uint32_t u = std::bit_cast<uint32_t>(f);
  char buf[40];
  std::snprintf(buf, sizeof buf, "uintBitsToFloat(0x%08Xu)", u);
  return buf;
}

}  // namespace

std::string glslFloat(float f) {
  if (!std::isfinite(f)) return bitsLiteral(f);
  if (f == 0.0f) return std::signbit(f) ? "(-0.0)" : "0.0";
  auto exact = [f](const char* text) {
    return std::strtof(text, nullptr) == f && static_cast<float>(std::strtod(text, nullptr)) == f;
  };
  auto finish = [f](std::string s) {
    if (s.find_first_of(".e") == std::string::npos) s += ".0";
    return f < 0 ? "(" + s + ")" : s;
  };
  char buf[64];
  const double a = std::fabs(static_cast<double>(f));
  if (a >= 1e-4 && a < 1e15) {  // plain decimals where they stay short
    for (int decimals = 1; decimals <= 12; ++decimals) {
      std::snprintf(buf, sizeof buf, "%.*f", decimals, static_cast<double>(f));
      if (exact(buf)) return finish(buf);
    }
  }
  for (int precision = 1; precision <= 9; ++precision) {
    std::snprintf(buf, sizeof buf, "%.*g", precision, static_cast<double>(f));
    if (exact(buf)) return finish(buf);
  }
  return bitsLiteral(f);
}

std::string glslDouble(double d) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", d);
  std::string s = buf;
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return "(" + s + "lf)";
}

std::string glslUint(uint32_t u) {
  return std::to_string(u) + "u";
}

std::string glslHexUint(uint32_t u) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%Xu", u);
  return buf;
}

}  // namespace rayspec
