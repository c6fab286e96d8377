#include "metamorphic/motion_spec.h"

#include <charconv>
#include <cmath>
#include <vector>

namespace rayspec {
namespace {

std::vector<std::string> splitCommas(const std::string& s) {
  std::vector<std::string> parts(1);
  for (char ch : s) {
    if (ch == ',')
      parts.emplace_back();
    else if (ch != ' ')
      parts.back() += ch;
  }
  return parts;
}

// "x", "+y", "-z": the axis index and its sign.
bool parseSignedAxis(const std::string& t, int* axis, int* sign) {
  if (t.empty() || t.size() > 2) return false;
  *sign = 1;
  size_t i = 0;
  if (t.size() == 2) {
    if (t[0] != '+' && t[0] != '-') return false;
    *sign = t[0] == '-' ? -1 : 1;
    i = 1;
  }
  if (t[i] < 'x' || t[i] > 'z') return false;
  *axis = t[i] - 'x';
  return true;
}

bool parseNumber(const std::string& t, double* out) {
  const char* end = t.data() + t.size();
  const auto [p, ec] = std::from_chars(t.data(), end, *out);
  return ec == std::errc() && p == end && std::isfinite(*out);
}

std::string numberText(double v) {
  char buf[64];
  const auto [p, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return ec == std::errc() ? std::string(buf, p) : std::string("?");
}

}  // namespace

Result<RigidMotion> parseMotionSpec(const std::string& spec) {
  const std::vector<std::string> parts = splitCommas(spec);
  if (parts.size() != 3 && parts.size() != 6) {
    return errorMessage("'" + spec +
                        "': expected three signed axes (e.g. -y,x,z), optionally followed by three "
                        "translation terms");
  }
  RigidMotion m;
  std::array<int, 3> seen{0, 0, 0};
  for (int k = 0; k < 3; ++k) {
    if (!parseSignedAxis(parts[k], &m.axis[k], &m.sign[k])) {
      return errorMessage("'" + parts[k] + "' (term " + std::to_string(k + 1) +
                          "): not a signed axis (x, -y, +z, ...)");
    }
    ++seen[m.axis[k]];
  }
  if (seen != std::array<int, 3>{1, 1, 1}) {
    return errorMessage("'" + spec + "': each of x, y and z must appear once");
  }
  for (int k = 0; k < 3 && parts.size() == 6; ++k)
    if (!parseNumber(parts[3 + k], &m.translate[k]) ||
        double(float(m.translate[k])) != m.translate[k]) {
      return errorMessage("'" + parts[3 + k] + "' (term " + std::to_string(4 + k) +
                          "): not a finite number exact in float");
    }
  return m;
}

std::string motionSpecText(const RigidMotion& m) {
  std::string s;
  for (int k = 0; k < 3; ++k)
    s += std::string(k ? "," : "") + (m.sign[k] < 0 ? "-" : "") + char('x' + m.axis[k]);
  if (m.translate != std::array<double, 3>{0, 0, 0})
    for (double t : m.translate) s += "," + numberText(t);
  return s;
}

}  // namespace rayspec
