// translate * rotate * scale, as the case format defines instance transforms.
#include "case/transform.h"

#include <cmath>

namespace rayspec {

Transform composeTransform(const TransformParts& p) {
  const double len = std::sqrt(p.axis[0] * p.axis[0] + p.axis[1] * p.axis[1] + p.axis[2] * p.axis[2]);
  const double x = p.axis[0] / len, y = p.axis[1] / len, z = p.axis[2] / len;
  const double a = p.degrees * M_PI / 180.0;
  const double c = std::cos(a), s = std::sin(a), k = 1 - c;
  // Rodrigues' rotation matrix.
  const double r[3][3] = {{c + x * x * k, x * y * k - z * s, x * z * k + y * s},
                          {y * x * k + z * s, c + y * y * k, y * z * k - x * s},
                          {z * x * k - y * s, z * y * k + x * s, c + z * z * k}};
  Transform t{};
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) t[row * 4 + col] = static_cast<float>(r[row][col] * p.scale[col]);
    t[row * 4 + 3] = static_cast<float>(p.translate[row]);
  }
  return t;
}

double linearDeterminant(const Transform& t) {
  auto m = [&](int r, int c) { return static_cast<double>(t[r * 4 + c]); };
  return m(0, 0) * (m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1)) -
         m(0, 1) * (m(1, 0) * m(2, 2) - m(1, 2) * m(2, 0)) +
         m(0, 2) * (m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0));
}

}  // namespace rayspec
