// Radiance's RGB from XYZ (radiance_rgb.h).
#include "api/colour/radiance_rgb.h"

#include <algorithm>
#include <array>

namespace clearsky::api {

namespace {

using Matrix = std::array<std::array<double, 3>, 3>;

Matrix inverse(const Matrix& m) {
  const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                     m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                     m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  Matrix r{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      // Cofactor of m[j][i] (the adjugate is the transposed cofactor matrix).
      const int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
      r[i][j] = (m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0]) / det;
    }
  }
  return r;
}

// RGB -> XYZ for the primaries, each column scaled so that R = G = B = 1 is the white with
// Y = 1 (the usual construction, e.g. CIE 15:2004 annex on RGB colour spaces).
Matrix rgb_to_xyz() {
  const double xy[3][2] = {{0.640, 0.330}, {0.290, 0.600}, {0.150, 0.060}};
  Matrix p{};
  for (int c = 0; c < 3; ++c) {
    p[0][c] = xy[c][0] / xy[c][1];
    p[1][c] = 1.0;
    p[2][c] = (1.0 - xy[c][0] - xy[c][1]) / xy[c][1];
  }
  const Matrix p_inverse = inverse(p);
  const double white[3] = {1.0, 1.0, 1.0};  // equal-energy white, Y = 1
  Matrix m{};
  for (int c = 0; c < 3; ++c) {
    double s = 0.0;
    for (int k = 0; k < 3; ++k) s += p_inverse[c][k] * white[k];
    for (int row = 0; row < 3; ++row) m[row][c] = p[row][c] * s;
  }
  return m;
}

const Matrix& forward() {
  static const Matrix m = rgb_to_xyz();
  return m;
}

const Matrix& backward() {
  static const Matrix m = inverse(forward());
  return m;
}

}  // namespace

RadianceRgb xyz_to_radiance_rgb(const Xyz& xyz) {
  const Matrix& m = backward();
  const double k = kMaxLuminousEfficacy / kRadianceWhiteEfficacy;
  const double v[3] = {xyz.x, xyz.y, xyz.z};
  double out[3];
  for (int i = 0; i < 3; ++i) out[i] = k * (m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2]);
  return {out[0], out[1], out[2]};
}

double radiance_rgb_luminance(const RadianceRgb& rgb) {
  const Matrix& m = forward();
  return kRadianceWhiteEfficacy * (m[1][0] * rgb.r + m[1][1] * rgb.g + m[1][2] * rgb.b);
}

ClippedRadianceRgb clip_radiance_rgb(const RadianceRgb& rgb) {
  ClippedRadianceRgb out{rgb, rgb.r < 0.0 || rgb.g < 0.0 || rgb.b < 0.0};
  out.rgb.r = std::max(0.0, rgb.r);
  out.rgb.g = std::max(0.0, rgb.g);
  out.rgb.b = std::max(0.0, rgb.b);
  return out;
}

}  // namespace clearsky::api
