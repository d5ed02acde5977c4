// The pure functions of Bruneton and Neyret 2008, "Precomputed Atmospheric Scattering"
// (EGSR 2008), as the 2016 study ran them (models/bruneton/README.md, "The
// parameterisation"): the ray-length limit, the parameterisations of the transmittance,
// irradiance and 4D scattering tables, and the texel <-> (r, mu, mu_s, nu) mappings.
//
// Notation (paper section 4): r distance to the planet centre (m), mu cosine of the view
// zenith angle, mu_s cosine of the sun zenith angle, nu cosine of the view-sun angle.
// Rg ground radius, Rt top of the atmosphere, RL = Rt + 1 km the ray-length limit of the
// integrals (rays are integrated to the sphere of radius RL, as the original code does).
//
// Tables follow GPU texture semantics, as the original code (and the study's CPU port) do:
// a table of n texels over u in [0, 1] holds texel i at u = (i + 0.5) / n, a lookup at u
// reads position u n - 0.5, interpolates linearly and clamps to the edge texels.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "models/core/numeric.h"

namespace clearsky::bruneton {

// The range of sun zenith cosines the tables cover (the 4D tables' mu_s axis and the
// irradiance table's), paper section 4 "parameterization" and the 2008 code's mu_s mapping:
//   mu_s(x) = tan((2 x - 1 + c) a) / tan((1 + c) a),  x = i / (RES_MU_S - 1) in [0, 1], a = 1.1,
// dense near the horizon. The 2008 code (and the study) use c = 0.26: x = 0 holds mu_s = -0.1979,
// lookups clamp mu_s to -0.1975 (the sun up to 101.39 degrees zenith), and the irradiance table
// spans mu_s in [-0.2, 1]. The extended range (max_sun_zenith_deg) solves c so that x = 0 holds
// mu_s_min = cos(max sun zenith) exactly; lookups clamp to mu_s_min and the irradiance table
// spans [mu_s_min, 1]. c falls from 0.26 as the range grows (0.185 for 110 degrees, 0.124 for
// 120), which spreads the texels over the wider range: their spacing at the horizon grows from
// 0.0133 (32 texels) to 0.0194 (110 degrees) and 0.0247 (120 degrees).
struct SunRange {
  double offset = 0.26;                     // c
  double tan_scale = std::tan(1.26 * 1.1);  // tan((1 + c) a), the 2008 literals for the default
  double lookup_min_mu_s = -0.1975;         // mu_s is clamped to this before a 4D lookup
  double irradiance_min_mu_s = -0.2;        // irradiance table: mu_s at texel 0
  double irradiance_span = 1.2;             // 1 - irradiance_min_mu_s
  bool extended = false;                    // false: the 2008 mapping (the default)

  // The 2008 mapping, bit for bit.
  static SunRange legacy() { return SunRange{}; }
  // The sun up to max_sun_zenith_rad (in (pi / 2, pi)), with the 4D tables' first texel there.
  static SunRange up_to(double max_sun_zenith_rad);
  double max_sun_zenith_rad() const { return std::acos(lookup_min_mu_s); }
};

// Table resolutions and integration sample counts (defaults: the 2008 code and the study).
struct Resolution {
  int transmittance_mu = 256;  // TRANSMITTANCE_W
  int transmittance_r = 64;    // TRANSMITTANCE_H
  int irradiance_mu_s = 64;    // SKY_W
  int irradiance_r = 16;       // SKY_H
  int r = 32;                  // RES_R
  int mu = 128;                // RES_MU (even: half ground-hitting rays, half sky rays)
  int mu_s = 32;               // RES_MU_S
  int nu = 8;                  // RES_NU
  int transmittance_steps = 500;
  int inscatter_steps = 50;
  int sphere_samples = 16;  // density J: sphere_samples zeniths x 2 sphere_samples azimuths
  int irradiance_samples =
      32;          // irradiance: irradiance_samples/2 zeniths x 2 irradiance_samples azimuths
  int orders = 4;  // scattering orders (1 = single scattering only)
  SunRange sun;    // the mu_s range of the 4D and irradiance tables

  long long texels_4d() const { return 1LL * r * mu * mu_s * nu; }
};

// The radii of the spherical shell, m.
struct ShellGeometry {
  double bottom_m = 6360e3;  // Rg
  double top_m = 6420e3;     // Rt
  double limit_m = 6421e3;   // RL = Rt + 1 km

  double horizon_length_m() const { return std::sqrt(top_m * top_m - bottom_m * bottom_m); }  // H
};

// Cosine of the zenith angle of the geometric horizon seen from radius r (>= Rg).
inline double horizon_mu(double r, const ShellGeometry& g) {
  const double ratio = g.bottom_m / r;
  return -safe_sqrt(1.0 - ratio * ratio);
}

// Distance along (r, mu) to the ground, or else to the limit sphere RL (the 2008 code's
// "limit"): the length over which every integral of the model runs.
inline double limit_distance(double r, double mu, const ShellGeometry& g) {
  double d_out = -r * mu + safe_sqrt(r * r * (mu * mu - 1.0) + g.limit_m * g.limit_m);
  const double delta_sq = r * r * (mu * mu - 1.0) + g.bottom_m * g.bottom_m;
  if (delta_sq >= 0.0) {
    const double d_in = -r * mu - std::sqrt(delta_sq);
    if (d_in >= 0.0) d_out = std::min(d_out, d_in);
  }
  return d_out;
}

// One axis of a texture lookup: the two texels around position u n - 0.5 and the weight of
// the second. Fractions within 1e-9 of a texel centre snap to it, so that lookups at texel
// centres (most lookups of the precomputation) touch one texel instead of two.
struct Axis {
  int i0 = 0, i1 = 0;
  double f = 0;  // weight of i1
};

// floor() for |x| < 2^62 without a libm call (baseline x86-64 has no rounding instruction,
// and this runs a billion times per precomputation).
inline double floor_small(double x) {
  const double t = static_cast<double>(static_cast<long long>(x));
  return t > x ? t - 1.0 : t;
}

inline Axis texture_axis(double u, int n) {
  // Positions beyond [-1, n] read the edge texels whatever their fraction; NaN reads texel 0.
  double p = u * n - 0.5;
  if (!(p >= -1.0)) p = -1.0;
  if (p > n) p = n;
  double fl = floor_small(p);
  double f = p - fl;
  if (f < 1e-9) {
    f = 0.0;
  } else if (f > 1.0 - 1e-9) {
    fl += 1.0;
    f = 0.0;
  }
  const double clamped = std::clamp(fl, -1.0, static_cast<double>(n));
  const int i = static_cast<int>(clamped);
  Axis a;
  a.i0 = std::clamp(i, 0, n - 1);
  a.i1 = std::clamp(i + 1, 0, n - 1);
  a.f = f;
  return a;
}

// --- Transmittance table (2008 code: "TRANSMITTANCE_NON_LINEAR") ---------------------------
// x over mu: mu = -0.15 + tan(1.5 x) / tan(1.5) * 1.15; y over r: r = Rg + y^2 (Rt - Rg).
inline double transmittance_texel_mu(int i, int width) {
  const double x = (i + 0.5) / width;
  return -0.15 + std::tan(1.5 * x) / std::tan(1.5) * 1.15;
}
inline double transmittance_texel_r(int j, int height, const ShellGeometry& g) {
  const double y = (j + 0.5) / height;
  return g.bottom_m + y * y * (g.top_m - g.bottom_m);
}
inline double transmittance_u_mu(double mu) {
  return std::atan((mu + 0.15) / 1.15 * std::tan(1.5)) / 1.5;
}
inline double transmittance_u_r(double r, const ShellGeometry& g) {
  return std::sqrt(std::max(r - g.bottom_m, 0.0) / (g.top_m - g.bottom_m));
}

// --- Irradiance table --------------------------------------------------------------------
// Texel (i, j) holds mu_s = m + (1 - m) i / (W - 1) (m = -0.2 in the 2008 code, SunRange),
// r = Rg + j / (H - 1) (Rt - Rg), but is read at u = (mu_s - m) / (1 - m) with texture
// semantics: the original code's half-texel mismatch, kept because the study's numbers
// include it.
inline double irradiance_texel_mu_s(int i, int width, const SunRange& s) {
  return s.irradiance_min_mu_s + s.irradiance_span * i / (width - 1.0);
}
inline double irradiance_texel_r(int j, int height, const ShellGeometry& g) {
  return g.bottom_m + j / (height - 1.0) * (g.top_m - g.bottom_m);
}
inline double irradiance_u_mu_s(double mu_s, const SunRange& s) {
  return (mu_s - s.irradiance_min_mu_s) / s.irradiance_span;
}
inline double irradiance_u_r(double r, const ShellGeometry& g) {
  return (r - g.bottom_m) / (g.top_m - g.bottom_m);
}

// --- 4D scattering tables (paper section 4, 2008 code) -------------------------------------
// Layer l holds r with rho = sqrt(r^2 - Rg^2) = H l / (RES_R - 1), nudged 10 m up at the ground
// and 1 m down at the top; dmin/dmax (sky rays) and dminp/dmaxp (ground rays) bound the
// distances that parameterise mu in that layer.
struct Layer {
  double r = 0, dmin = 0, dmax = 0, dminp = 0, dmaxp = 0;
};

inline Layer layer_geometry(int layer, int res_r, const ShellGeometry& g) {
  const double u = static_cast<double>(layer) * layer / ((res_r - 1.0) * (res_r - 1.0));
  Layer l;
  l.r = std::sqrt(g.bottom_m * g.bottom_m + u * (g.top_m * g.top_m - g.bottom_m * g.bottom_m)) +
        (layer == 0 ? 10.0 : (layer == res_r - 1 ? -1.0 : 0.0));
  l.dmin = g.top_m - l.r;
  l.dmax = safe_sqrt(l.r * l.r - g.bottom_m * g.bottom_m) + g.horizon_length_m();
  l.dminp = l.r - g.bottom_m;
  l.dmaxp = safe_sqrt(l.r * l.r - g.bottom_m * g.bottom_m);
  return l;
}

// mu of texel row j: the lower half parameterises the distance to the ground (horizon to
// nadir), the upper half the distance to the top (zenith to horizon).
inline double texel_mu(int j, int res_mu, const Layer& l, const ShellGeometry& g) {
  const double y = j;
  const double half = res_mu / 2.0;
  if (y < half) {
    double d = (1.0 - y / (half - 1.0)) * l.dmaxp;
    d = std::min(std::max(l.dminp, d), l.dmaxp * 0.999);
    const double mu = (g.bottom_m * g.bottom_m - l.r * l.r - d * d) / (2.0 * l.r * d);
    return std::max(std::min(mu, horizon_mu(l.r, g) - 0.001), -1.0);
  }
  double d = ((y - half) / (half - 1.0)) * l.dmax;
  d = std::min(std::max(l.dmin, d), l.dmax * 0.999);
  return std::min((g.top_m * g.top_m - l.r * l.r - d * d) / (2.0 * l.r * d), 1.0);
}

// The 2008 code's "better" mu_s mapping, generalised by SunRange:
// mu_s = tan((2 x - 1 + c) 1.1) / tan((1 + c) 1.1).
inline constexpr double kMuSAngle = 1.1;
inline constexpr double kMinLookupMuS = -0.1975;  // the 2008 code's clamp before lookup
inline double texel_mu_s(int i, int res_mu_s, const SunRange& s) {
  const double x = i / (res_mu_s - 1.0);
  return std::tan((2.0 * x - 1.0 + s.offset) * kMuSAngle) / s.tan_scale;
}
// nu linear over the slices.
inline double texel_nu(int k, int res_nu) { return -1.0 + 2.0 * k / (res_nu - 1.0); }

inline double u_mu_s(double mu_s, int res_mu_s, const SunRange& s) {
  return 0.5 / res_mu_s + (std::atan(std::max(mu_s, s.lookup_min_mu_s) * s.tan_scale) / kMuSAngle +
                           (1.0 - s.offset)) *
                              0.5 * (1.0 - 1.0 / res_mu_s);
}

inline SunRange SunRange::up_to(double max_sun_zenith_rad) {
  const double target = std::cos(max_sun_zenith_rad);
  // mu_s(0) = tan((c - 1) a) / tan((1 + c) a) rises monotonically from -1 at c = 0 to 0 at
  // c = pi / (2 a) - 1, where tan((1 + c) a) diverges: bisection for mu_s(0) = target.
  auto first_texel = [](double c) {
    return std::tan((c - 1.0) * kMuSAngle) / std::tan((1.0 + c) * kMuSAngle);
  };
  double lo = 0.0, hi = kPi / (2.0 * kMuSAngle) - 1.0;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (first_texel(mid) < target ? lo : hi) = mid;
  }
  SunRange s;
  s.offset = 0.5 * (lo + hi);
  s.tan_scale = std::tan((1.0 + s.offset) * kMuSAngle);
  s.lookup_min_mu_s = target;
  s.irradiance_min_mu_s = target;
  s.irradiance_span = 1.0 - target;
  s.extended = true;
  return s;
}

// Where (r, mu, mu_s, nu) falls in a 4D table (the 2008 code's texture4D).
struct Coord4 {
  Axis r, mu, mu_s, nu;
};

inline Axis r_axis_4d(double r, const Resolution& res, const ShellGeometry& g) {
  const double h = g.horizon_length_m();
  const double rho = safe_sqrt(r * r - g.bottom_m * g.bottom_m);
  return texture_axis(0.5 / res.r + rho / h * (1.0 - 1.0 / res.r), res.r);
}

inline Axis mu_axis_4d(double r, double mu, const Resolution& res, const ShellGeometry& g) {
  const double h = g.horizon_length_m();
  const double rho = safe_sqrt(r * r - g.bottom_m * g.bottom_m);
  const double rmu = r * mu;
  const double delta = rmu * rmu - r * r + g.bottom_m * g.bottom_m;
  double u;
  if (rmu < 0.0 && delta > 0.0) {
    // Ray to the ground: minus the distance to the ground over its horizon value rho.
    const double ratio = rho > 0.0 ? (rmu + std::sqrt(delta)) / rho : 0.0;
    u = 0.5 - 0.5 / res.mu + ratio * (0.5 - 1.0 / res.mu);
  } else {
    // Ray to the sky: the distance to the top over its maximum rho + H.
    // delta + H^2 = Rt^2 - r^2 (1 - mu^2) is summed from terms of order r^2 (4e13 m^2), so it
    // carries a rounding error of order r^2 x 1e-16: a ray grazing the top of the atmosphere
    // (r = Rt, mu = 0) may come out a few 1e-4 m^2 below zero, which is zero (found by
    // fuzz/table_cache_fuzz.cpp; safe_sqrt's check is for values clearly below zero).
    const double to_top = delta + h * h;
    const double rounding = 8.0 * std::numeric_limits<double>::epsilon() * r * r;
    u = 0.5 + 0.5 / res.mu +
        (-rmu + safe_sqrt(to_top > -rounding ? std::max(to_top, 0.0) : to_top)) / (rho + h) *
            (0.5 - 1.0 / res.mu);
  }
  return texture_axis(u, res.mu);
}

inline Axis nu_axis_4d(double nu, const Resolution& res) {
  const double lerp = (std::clamp(nu, -1.0, 1.0) + 1.0) / 2.0 * (res.nu - 1);
  double k = floor_small(lerp);
  double f = lerp - k;
  if (f < 1e-9) {
    f = 0.0;
  } else if (f > 1.0 - 1e-9) {
    k += 1.0;
    f = 0.0;
  }
  Axis a;
  a.i0 = std::clamp(static_cast<int>(k), 0, res.nu - 1);
  a.i1 = std::clamp(static_cast<int>(k) + 1, 0, res.nu - 1);
  a.f = f;
  return a;
}

inline Coord4 coordinates_4d(double r, double mu, double mu_s, double nu, const Resolution& res,
                             const ShellGeometry& g) {
  return {r_axis_4d(r, res, g), mu_axis_4d(r, mu, res, g),
          texture_axis(u_mu_s(mu_s, res.mu_s, res.sun), res.mu_s), nu_axis_4d(nu, res)};
}

}  // namespace clearsky::bruneton
