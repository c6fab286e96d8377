// translate * rotate * scale, as the case format defines instance transforms.
#include "case/transform.h"

#include <cmath>

namespace rayspec {

Transform composeTransform(const TransformParts& p) {
  const double len =
      std::sqrt(p.axis[0] * p.axis[0] + p.axis[1] * p.axis[1] + p.axis[2] * p.axis[2]);
  const double x = p.axis[0] / len, y = p.axis[1] / len, z = p.axis[2] / len;
  const double a = p.degrees * M_PI / 180.0;
  const double c = std::cos(a), s = std::sin(a), k = 1 - c;
  // Rodrigues' rotation matrix.
  const double r[3][3] = {{c + x * x * k, x * y * k - z * s, x * z * k + y * s},
                          {y * x * k + z * s, c + y * y * k, y * z * k - x * s},
                          {z * x * k - y * s, z * y * k + x * s, c + z * z * k}};
  Transform t{};
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col)
      t[row * 4 + col] = static_cast<float>(r[row][col] * p.scale[col]);
    t[row * 4 + 3] = static_cast<float>(p.translate[row]);
  }
  return t;
}

double linearDeterminant(const Transform& t) {
  auto m = [&](int r, int c) {
    return static_cast<double>(t[r * 4 + c]);
  };
  return m(0, 0) * (m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1)) -
         m(0, 1) * (m(1, 0) * m(2, 2) - m(1, 2) * m(2, 0)) +
         m(0, 2) * (m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0));
}

std::array<double, 12> invertTransform(const Transform& m) {
  const double a = m[0], b = m[1], c = m[2], d = m[4], e = m[5], f = m[6], g = m[8], h = m[9],
               i = m[10];
  const double cof0 = e * i - f * h, cof1 = -(d * i - f * g), cof2 = d * h - e * g;
  const double det = a * cof0 + b * cof1 + c * cof2;
  std::array<double, 12> r{};
  if (det == 0.0 || std::isnan(det)) return r;
  const double inv = 1.0 / det;
  const double l[9] = {cof0 * inv, -(b * i - c * h) * inv, (b * f - c * e) * inv,
                       cof1 * inv, (a * i - c * g) * inv,  -(a * f - c * d) * inv,
                       cof2 * inv, -(a * h - b * g) * inv, (a * e - b * d) * inv};
  for (int row = 0; row < 3; ++row) {
    r[row * 4 + 0] = l[row * 3 + 0];
    r[row * 4 + 1] = l[row * 3 + 1];
    r[row * 4 + 2] = l[row * 3 + 2];
    r[row * 4 + 3] = -(l[row * 3 + 0] * m[3] + l[row * 3 + 1] * m[7] + l[row * 3 + 2] * m[11]);
  }
  return r;
}

}  // namespace rayspec
