// CIELAB and CIEDE2000 (delta_e_2000.h); the equation numbers are Sharma, Wu and Dalal 2005's.
#include "models/colour/delta_e_2000.h"

#include <cmath>

#include "models/core/numeric.h"

namespace clearsky {

namespace {

// CIE 15:2004 equation (8.3): the cube root above (6/29)^3, the linear segment below.
double lab_f(double t) {
  constexpr double kDelta = 6.0 / 29.0;
  if (t > kDelta * kDelta * kDelta) return std::cbrt(t);
  return t / (3.0 * kDelta * kDelta) + 4.0 / 29.0;
}

double degrees(double rad) { return rad * 180.0 / kPi; }
double radians(double deg) { return deg * kPi / 180.0; }

// Hue angle in degrees in [0, 360); 0 for a = b = 0 (equation 4).
double hue_deg(double b, double a_prime) {
  if (b == 0.0 && a_prime == 0.0) return 0.0;
  const double h = degrees(std::atan2(b, a_prime));
  return h < 0.0 ? h + 360.0 : h;
}

}  // namespace

Lab xyz_to_lab(const Xyz& xyz, const Xyz& white) {
  const double fx = lab_f(xyz.x / white.x);
  const double fy = lab_f(xyz.y / white.y);
  const double fz = lab_f(xyz.z / white.z);
  return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

double delta_e_2000(const Lab& c1, const Lab& c2) {
  // (2) to (5): a' stretched by G, which depends on the mean chroma.
  const double c_ab_mean = 0.5 * (std::hypot(c1.a, c1.b) + std::hypot(c2.a, c2.b));
  const double c7 = std::pow(c_ab_mean, 7.0);
  const double g = 0.5 * (1.0 - std::sqrt(c7 / (c7 + std::pow(25.0, 7.0))));
  const double a1 = (1.0 + g) * c1.a, a2 = (1.0 + g) * c2.a;
  const double chroma1 = std::hypot(a1, c1.b), chroma2 = std::hypot(a2, c2.b);
  const double h1 = hue_deg(c1.b, a1), h2 = hue_deg(c2.b, a2);

  // (8) to (10): the differences; the hue difference is 0 when either chroma is 0.
  const double dl = c2.l - c1.l;
  const double dc = chroma2 - chroma1;
  double dh = 0.0;
  if (chroma1 * chroma2 != 0.0) {
    dh = h2 - h1;
    if (dh > 180.0) dh -= 360.0;
    if (dh < -180.0) dh += 360.0;
  }
  const double d_hue = 2.0 * std::sqrt(chroma1 * chroma2) * std::sin(radians(0.5 * dh));

  // (12) to (14): the means; the mean hue is the sum when either chroma is 0.
  const double l_mean = 0.5 * (c1.l + c2.l);
  const double c_mean = 0.5 * (chroma1 + chroma2);
  double h_mean = h1 + h2;
  if (chroma1 * chroma2 != 0.0) {
    if (std::abs(h1 - h2) <= 180.0)
      h_mean = 0.5 * (h1 + h2);
    else if (h1 + h2 < 360.0)
      h_mean = 0.5 * (h1 + h2 + 360.0);
    else
      h_mean = 0.5 * (h1 + h2 - 360.0);
  }

  // (15) to (21): the weighting functions and the rotation term.
  const double t =
      1.0 - 0.17 * std::cos(radians(h_mean - 30.0)) + 0.24 * std::cos(radians(2.0 * h_mean)) +
      0.32 * std::cos(radians(3.0 * h_mean + 6.0)) - 0.20 * std::cos(radians(4.0 * h_mean - 63.0));
  const double d_theta = 30.0 * std::exp(-std::pow((h_mean - 275.0) / 25.0, 2.0));
  const double c_mean7 = std::pow(c_mean, 7.0);
  const double r_c = 2.0 * std::sqrt(c_mean7 / (c_mean7 + std::pow(25.0, 7.0)));
  const double l50 = (l_mean - 50.0) * (l_mean - 50.0);
  const double s_l = 1.0 + 0.015 * l50 / std::sqrt(20.0 + l50);
  const double s_c = 1.0 + 0.045 * c_mean;
  const double s_h = 1.0 + 0.015 * c_mean * t;
  const double r_t = -std::sin(radians(2.0 * d_theta)) * r_c;

  // (22)
  const double tl = dl / s_l, tc = dc / s_c, th = d_hue / s_h;
  return std::sqrt(tl * tl + tc * tc + th * th + r_t * tc * th);
}

}  // namespace clearsky
