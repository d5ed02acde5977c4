// Single-scattering tables of the sampling directions of Nishita96 (see nishita96_tables.h).
#include "models/nishita96/nishita96_tables.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "models/atmosphere/phase_functions.h"
#include "models/core/fast_exp.h"
#include "models/core/invalid_input.h"
#include "models/core/numeric.h"
#include "models/core/parallel.h"
#include "models/nishita93/nishita93_functions.h"

namespace clearsky::nishita96 {

namespace {

// Weight of the grazing layout for a direction at angle a from the zenith: 0 beyond
// kGrazingBlendEndDeg from the horizontal, 1 below kGrazingBlendStartDeg, a smoothstep of the
// elevation in between (continuous, with a continuous derivative, so that the blend adds no
// kink to the radiance as a function of the sun zenith). The fixed horizontals keep the
// study's horizontal layout (weight 0).
double grazing_weight_of(double angle_rad, bool horizontal) {
  if (horizontal) return 0.0;
  const double elevation_deg =
      radians_to_degrees(std::asin(std::min(1.0, std::abs(std::cos(angle_rad)))));
  if (elevation_deg >= kGrazingBlendEndDeg) return 0.0;
  if (elevation_deg <= kGrazingBlendStartDeg) return 1.0;
  const double s =
      (kGrazingBlendEndDeg - elevation_deg) / (kGrazingBlendEndDeg - kGrazingBlendStartDeg);
  return s * s * (3.0 - 2.0 * s);
}

}  // namespace

SamplingTable::SamplingTable(double angle_rad, double earth_radius_m, double top_radius_m,
                             int nodes, std::size_t wavelengths, bool fixed_horizontal)
    : angle_rad_(angle_rad),
      earth_radius_m_(earth_radius_m),
      top_radius_m_(top_radius_m),
      half_width_m_(std::sqrt(top_radius_m * top_radius_m - earth_radius_m * earth_radius_m)),
      // The study tests the exact angles of the horizontal directions (+-90 degrees).
      horizontal_(fixed_horizontal && (angle_rad == 0.5 * kPi || angle_rad == -0.5 * kPi)),
      axis_against_height_(angle_rad > -0.5 * kPi && angle_rad <= 0.5 * kPi),
      tan_angle_(std::tan(angle_rad)),
      nodes_(nodes),
      stored_rows_(nodes / 2 + 1),
      wavelengths_(wavelengths),
      grazing_weight_(grazing_weight_of(angle_rad, horizontal_)) {
  if (nodes < 3 || nodes % 2 == 0) throw InvalidInput("table_nodes", "must be odd and >= 3");
  const std::size_t size = static_cast<std::size_t>(nodes) * stored_rows_ * nodes * wavelengths;
  if (has_sheared()) values_.assign(size, 0.0f);
  if (has_grazing()) {
    grazing_values_.assign(size / nodes * grazing_across_nodes(), 0.0f);
    // d = -s: the light arriving from s travels along -s, and the columns are integrated in
    // the direction the light travels. n: d turned by 90 degrees in the sun's vertical plane,
    // upwards (s is near the horizontal, so sin(a) is far from 0).
    const double sign = std::sin(angle_rad) > 0.0 ? 1.0 : -1.0;
    grazing_axis_ = {-std::sin(angle_rad), 0.0, -std::cos(angle_rad)};
    grazing_normal_ = {-sign * std::cos(angle_rad), 0.0, sign * std::sin(angle_rad)};
    // The box covers the rectangle x in [-D, D], z in [R, R_top] of the sun's vertical plane,
    // which holds every point the views sample (|p| <= R_top, z >= R).
    o_min_ = t_min_ = std::numeric_limits<double>::infinity();
    o_max_ = t_max_ = -std::numeric_limits<double>::infinity();
    for (const double x : {-half_width_m_, half_width_m_}) {
      for (const double z : {earth_radius_m, top_radius_m}) {
        const Vec3 corner{x, 0.0, z};
        o_min_ = std::min(o_min_, dot(corner, grazing_normal_));
        o_max_ = std::max(o_max_, dot(corner, grazing_normal_));
        t_min_ = std::min(t_min_, dot(corner, grazing_axis_));
        t_max_ = std::max(t_max_, dot(corner, grazing_axis_));
      }
    }
  }
}

Vec3 SamplingTable::node_position(int i, int j, int k) const {
  const double scale = 1.0 / (nodes_ - 1);
  const double u = i * scale, v = j * scale, w = k * scale;
  const double along = axis_against_height_ ? 1.0 - w : w;
  const double thickness = top_radius_m_ - earth_radius_m_;
  if (horizontal_) {
    return {(2.0 * along - 1.0) * half_width_m_, (2.0 * v - 1.0) * half_width_m_,
            earth_radius_m_ + u * thickness};
  }
  const double height = along * thickness;
  return {(2.0 * u - 1.0) * half_width_m_ + tan_angle_ * height, (2.0 * v - 1.0) * half_width_m_,
          earth_radius_m_ + height};
}

Vec3 SamplingTable::grazing_node_position(int i, int j, int k) const {
  const double scale = 1.0 / (nodes_ - 1);
  const double o = o_min_ + (i / (grazing_across_nodes() - 1.0)) * (o_max_ - o_min_);
  const double t = t_min_ + (k * scale) * (t_max_ - t_min_);
  return o * grazing_normal_ + t * grazing_axis_ +
         Vec3{0.0, (2.0 * (j * scale) - 1.0) * half_width_m_, 0.0};
}

std::span<float> SamplingTable::grazing_node(int i, int j, int k) {
  return {grazing_values_.data() + index(i, j - nodes_ / 2, k), wavelengths_};
}

std::span<float> SamplingTable::node(int i, int j, int k) {
  return {values_.data() + index(i, j - nodes_ / 2, k), wavelengths_};
}
std::span<const float> SamplingTable::node(int i, int j, int k) const {
  return {values_.data() + index(i, j - nodes_ / 2, k), wavelengths_};
}

namespace {

// The weighted sum of the 8 corner spectra of a voxel, in single precision (the tables').
__attribute__((target_clones("avx2", "default"))) void trilinear(const float* const* corners,
                                                                 const float* weights, float* out,
                                                                 std::size_t n) {
  for (std::size_t l = 0; l < n; ++l) {
    out[l] = weights[0] * corners[0][l] + weights[1] * corners[1][l] + weights[2] * corners[2][l] +
             weights[3] * corners[3][l] + weights[4] * corners[4][l] + weights[5] * corners[5][l] +
             weights[6] * corners[6][l] + weights[7] * corners[7][l];
  }
}

}  // namespace

void SamplingTable::lookup(Vec3 p, std::span<float> out) const {
  if (grazing_weight_ == 0.0) {
    lookup_sheared(p, out);
    return;
  }
  if (grazing_weight_ == 1.0) {
    lookup_grazing(p, out);
    return;
  }
  // The blend band: both layouts, weighted (see grazing_weight_of).
  thread_local std::vector<float> sheared;
  sheared.resize(out.size());
  lookup_sheared(p, sheared);
  lookup_grazing(p, out);
  const auto g = static_cast<float>(grazing_weight_);
  for (std::size_t l = 0; l < out.size(); ++l) out[l] = g * out[l] + (1.0f - g) * sheared[l];
}

void SamplingTable::lookup_sheared(Vec3 p, std::span<float> out) const {
  const double thickness = top_radius_m_ - earth_radius_m_;
  double u, w;
  // |y|: the stored half, by symmetry about the sun's vertical plane.
  const double v = 0.5 * (std::abs(p.y) / half_width_m_ + 1.0);
  if (horizontal_) {
    u = (p.z - earth_radius_m_) / thickness;
    const double along = 0.5 * (p.x / half_width_m_ + 1.0);
    w = axis_against_height_ ? 1.0 - along : along;
  } else {
    const double height = p.z - earth_radius_m_;
    u = 0.5 * ((p.x - tan_angle_ * height) / half_width_m_ + 1.0);
    const double along = height / thickness;
    w = axis_against_height_ ? 1.0 - along : along;
  }
  interpolate(values_, nodes_, u, v, w, out);
}

void SamplingTable::lookup_grazing(Vec3 p, std::span<float> out) const {
  const double v = 0.5 * (std::abs(p.y) / half_width_m_ + 1.0);
  const double u = (dot(p, grazing_normal_) - o_min_) / (o_max_ - o_min_);
  const double w = (dot(p, grazing_axis_) - t_min_) / (t_max_ - t_min_);
  interpolate(grazing_values_, grazing_across_nodes(), u, v, w, out);
}

void SamplingTable::interpolate(const std::vector<float>& values, int u_nodes, double u, double v,
                                double w, std::span<float> out) const {
  const auto split = [](double coordinate, double last, int& index0, double& fraction) {
    const double c = std::clamp(coordinate * last, 0.0, last);
    index0 = std::min(static_cast<int>(c), static_cast<int>(last) - 1);
    fraction = c - index0;
  };
  const double last = nodes_ - 1;
  int i0, j0, k0;
  double fu, fv, fw;
  split(u, u_nodes - 1.0, i0, fu);
  split(v, last, j0, fv);
  split(w, last, k0, fw);
  const int jj0 = j0 - nodes_ / 2;  // >= 0 since v >= 0.5
  const float* corners[8];
  float weights[8];
  int c = 0;
  for (int di = 0; di < 2; ++di) {
    for (int dj = 0; dj < 2; ++dj) {
      for (int dk = 0; dk < 2; ++dk, ++c) {
        weights[c] =
            static_cast<float>((di ? fu : 1.0 - fu) * (dj ? fv : 1.0 - fv) * (dk ? fw : 1.0 - fw));
        corners[c] = values.data() + index(i0 + di, std::max(jj0 + dj, 0), k0 + dk);
      }
    }
  }
  trilinear(corners, weights, out.data(), out.size());
}

namespace {

std::array<Vec3, kSamplingDirections> directions_of(const std::vector<SamplingTable>& tables) {
  std::array<Vec3, kSamplingDirections> d;
  for (int k = 0; k < kSamplingDirections; ++k)
    d[k] = direction_of_angle(tables[static_cast<std::size_t>(k)].angle_rad());
  return d;
}

}  // namespace

SunTables::SunTables(double sun_zenith_rad, std::vector<SamplingTable> tables,
                     int phase_theta_cells)
    : sun_zenith_rad_(sun_zenith_rad),
      tables_(std::move(tables)),
      directions_(directions_of(tables_)),
      phase_bins_(directions_, phase_theta_cells) {}

std::size_t SunTables::memory_bytes() const {
  std::size_t bytes = sizeof(*this);
  for (const auto& t : tables_) bytes += t.memory_bytes();
  return bytes;
}

namespace {

// Distance from p (inside the atmosphere) along d to the top or, if it comes first, the ground.
double distance_to_ground_or_top(Vec3 p, Vec3 d, double earth_radius_m, double top_radius_m) {
  const double b = dot(p, d);
  const double c = dot(p, p);
  double distance = -b + safe_sqrt(b * b - c + top_radius_m * top_radius_m);
  const double ground = b * b - c + earth_radius_m * earth_radius_m;
  if (ground >= 0.0) {
    // A point on the ground looking down meets it at distance 0, which rounding can make a
    // tiny negative number: without the tolerance such a ray would run through the Earth.
    const double to_ground = -b - std::sqrt(ground);
    if (to_ground >= -1e-3) distance = std::min(distance, std::max(to_ground, 0.0));
  }
  return distance;
}

struct ColumnContext {
  const Nishita93Tables& optical_lengths;
  const AtmosphereSpectra& atmosphere;
  Vec3 sun;
  double ground_albedo_height_m;  // below it a ray's start is on the ground
};

void sun_transmittance_at(const ColumnContext& c, Vec3 p, std::span<double> out) {
  const double r = length(p);
  nishita93::sun_transmittance(c.optical_lengths, c.atmosphere, r, clamp_cosine(dot(p, c.sun) / r),
                               out);
}

// The line of a column through its first two nodes: node k is at p0 + (k step) d. Both layouts
// space a column's nodes evenly along a straight axis (nishita96_tables.h), so the two nodes
// give the whole column.
struct ColumnLine {
  Vec3 p0;
  Vec3 d;         // unit direction of the axis
  double step_m;  // node spacing along d
};

ColumnLine column_line(Vec3 p0, Vec3 p1) {
  const double step_m = length(p1 - p0);
  return {p0, (1.0 / step_m) * (p1 - p0), step_m};
}

// One column of a table: nodes k = 0 .. nodes - 1 along the axis, from p0 in direction d
// with spacing step; the radiance arriving at each node from -d.
void build_column(const ColumnContext& c, SamplingTable& table, int i, int j) {
  const auto& a = c.atmosphere;
  const std::size_t n = a.grid.size();
  const double earth = a.parameters.earth_radius_m;
  const double top = a.parameters.top_radius_m;
  // Named copies, not a structured binding: a lambda below uses the step, and capturing a
  // structured binding is not C++20 (GCC allows it, clang refuses it).
  const ColumnLine line = column_line(table.node_position(i, j, 0), table.node_position(i, j, 1));
  const Vec3 p0 = line.p0;
  const Vec3 d = line.d;
  const double step = line.step_m;
  double start_t;
  double end_t;
  if (dot(p0, p0) >= top * top) {
    // Outside the atmosphere: the ray starts where it enters it (if it does).
    const double b = dot(p0, d);
    const double disc = b * b - dot(p0, p0) + top * top;
    start_t = disc >= 0.0 ? -b - std::sqrt(disc) : -1.0;
    if (start_t < 0.0) return;
    end_t = start_t + distance_to_ground_or_top(p0 + start_t * d, d, earth, top);
  } else {
    start_t = -distance_to_ground_or_top(p0, -1.0 * d, earth, top);
    end_t = distance_to_ground_or_top(p0, d, earth, top);
  }
  const double hr = a.parameters.rayleigh_scale_height_m;
  const double hm = a.parameters.mie_scale_height_m;
  const Vec3 start = p0 + start_t * d;
  const double start_height = length(start) - earth;
  double previous_rayleigh = std::exp(-start_height / hr);
  double previous_mie = std::exp(-start_height / hm);
  std::vector<double> previous_sun(n), sun_t(n), segment(n), rayleigh_integral(n, 0.0),
      mie_integral(n, 0.0), background(n, 0.0);
  sun_transmittance_at(c, start, previous_sun);
  // A ray that starts on the ground sees it: sunlit Lambertian ground, albedo / pi.
  if (start_height < c.ground_albedo_height_m) {
    const double cos_sun = std::max(0.0, dot(normalize(start), c.sun));
    for (std::size_t w = 0; w < n; ++w)
      background[w] = previous_sun[w] * a.ground_albedo[w] / kPi * cos_sun;
  }
  const double nu = dot(-1.0 * d, c.sun);
  const double rayleigh_phase_value = rayleigh_phase(nu);
  const double mie_phase_value = cornette_shanks_phase(nu, a.parameters.mie_phase_g);
  const int start_k = static_cast<int>(std::ceil(start_t / step));
  const int end_k = std::min(static_cast<int>(std::ceil(end_t / step)), table.nodes() - 1);
  for (int k = start_k; k <= end_k; ++k) {
    const Vec3 pk = p0 + (k * step) * d;
    const double height = length(pk) - earth;
    const double rayleigh = std::exp(-height / hr);
    const double mie = std::exp(-height / hm);
    const double half = 0.5 * (k == start_k ? k * step - start_t : step);
    transmittance_from_lengths(n, a.rayleigh_scattering_per_m.data(), a.mie_extinction_per_m.data(),
                               (rayleigh + previous_rayleigh) * half, (mie + previous_mie) * half,
                               segment.data());
    sun_transmittance_at(c, pk, sun_t);
    for (std::size_t w = 0; w < n; ++w) {
      rayleigh_integral[w] =
          (sun_t[w] * rayleigh + previous_sun[w] * segment[w] * previous_rayleigh) * half +
          segment[w] * rayleigh_integral[w];
      mie_integral[w] = (sun_t[w] * mie + previous_sun[w] * segment[w] * previous_mie) * half +
                        segment[w] * mie_integral[w];
      background[w] *= segment[w];
    }
    if (k >= 0) {
      auto out = table.node(i, j, k);
      for (std::size_t w = 0; w < n; ++w) {
        out[w] = static_cast<float>(
            rayleigh_integral[w] * a.rayleigh_scattering_per_m[w] * rayleigh_phase_value +
            mie_integral[w] * a.mie_scattering_per_m[w] * mie_phase_value + background[w]);
      }
    }
    previous_rayleigh = rayleigh;
    previous_mie = mie;
    std::swap(previous_sun, sun_t);
  }
}

// Integrates the light travelling along d over [t0, t1] of the line p0 + t d, starting with
// `value` (the radiance arriving at t0: 0 from space, the sunlit ground's otherwise), writes
// the nodes k with k step in (t0, t1] (k = 0 .. nodes - 1), and leaves the radiance at t1 in
// `value`. The trapezoid rule between consecutive samples, as build_column.
void integrate_segment(const ColumnContext& c, SamplingTable& table, int i, int j, Vec3 p0, Vec3 d,
                       double step, double t0, double t1, std::vector<double>& value) {
  const auto& a = c.atmosphere;
  const std::size_t n = a.grid.size();
  const double earth = a.parameters.earth_radius_m;
  const double hr = a.parameters.rayleigh_scale_height_m;
  const double hm = a.parameters.mie_scale_height_m;
  const double nu = dot(-1.0 * d, c.sun);
  const double rayleigh_phase_value = rayleigh_phase(nu);
  const double mie_phase_value = cornette_shanks_phase(nu, a.parameters.mie_phase_g);
  // The radiance is kept as background (attenuated start value) plus the two scattering
  // integrals, as in build_column.
  std::vector<double> previous_sun(n), sun_t(n), segment(n), rayleigh_integral(n, 0.0),
      mie_integral(n, 0.0), background(value);
  const auto height_at = [&](double t) { return std::max(length(p0 + t * d) - earth, 0.0); };
  double previous_t = t0;
  double previous_rayleigh = std::exp(-height_at(t0) / hr);
  double previous_mie = std::exp(-height_at(t0) / hm);
  sun_transmittance_at(c, p0 + t0 * d, previous_sun);
  const auto radiance = [&](std::size_t w) {
    return rayleigh_integral[w] * a.rayleigh_scattering_per_m[w] * rayleigh_phase_value +
           mie_integral[w] * a.mie_scattering_per_m[w] * mie_phase_value + background[w];
  };
  const int last = table.nodes() - 1;
  int k = std::max(static_cast<int>(std::floor(t0 / step)) + 1, 0);
  while (previous_t < t1) {
    const bool at_node = k <= last && k * step < t1;
    const double t = at_node ? k * step : t1;
    const double height = height_at(t);
    const double rayleigh = std::exp(-height / hr);
    const double mie = std::exp(-height / hm);
    const double half = 0.5 * (t - previous_t);
    transmittance_from_lengths(n, a.rayleigh_scattering_per_m.data(), a.mie_extinction_per_m.data(),
                               (rayleigh + previous_rayleigh) * half, (mie + previous_mie) * half,
                               segment.data());
    sun_transmittance_at(c, p0 + t * d, sun_t);
    for (std::size_t w = 0; w < n; ++w) {
      rayleigh_integral[w] =
          (sun_t[w] * rayleigh + previous_sun[w] * segment[w] * previous_rayleigh) * half +
          segment[w] * rayleigh_integral[w];
      mie_integral[w] = (sun_t[w] * mie + previous_sun[w] * segment[w] * previous_mie) * half +
                        segment[w] * mie_integral[w];
      background[w] *= segment[w];
    }
    if (at_node && k >= 0) {
      auto out = table.grazing_node(i, j, k);
      for (std::size_t w = 0; w < n; ++w) out[w] = static_cast<float>(radiance(w));
    }
    previous_rayleigh = rayleigh;
    previous_mie = mie;
    previous_t = t;
    std::swap(previous_sun, sun_t);
    if (at_node) ++k;
    if (!at_node && t >= t1) break;
  }
  for (std::size_t w = 0; w < n; ++w) value[w] = radiance(w);
}

// One column of the grazing layout (nishita96_tables.h): the whole line p0 + t d, whose nodes
// may lie in space, in the atmosphere on either side of the Earth, or inside the Earth. The
// radiance arriving from -d: 0 before the line enters the atmosphere; integrated from there to
// the top's exit or to the ground; inside the Earth (nodes only the lookups next to the ground
// weigh) blended linearly along the chord from the light reaching the ground to the sunlit
// ground's at the exit, so that the nodes' values stay continuous as the layout turns with the
// sun; integrated again from the exit; beyond the atmosphere, the value at its exit (the light
// travels on unchanged).
void build_grazing_column(const ColumnContext& c, SamplingTable& table, int i, int j) {
  const auto& a = c.atmosphere;
  const std::size_t n = a.grid.size();
  const double earth = a.parameters.earth_radius_m;
  const double top = a.parameters.top_radius_m;
  // Named copies, not a structured binding: a lambda below uses the step, and capturing a
  // structured binding is not C++20 (GCC allows it, clang refuses it).
  const ColumnLine line =
      column_line(table.grazing_node_position(i, j, 0), table.grazing_node_position(i, j, 1));
  const Vec3 p0 = line.p0;
  const Vec3 d = line.d;
  const double step = line.step_m;
  const int last = table.nodes() - 1;
  const double b = dot(p0, d);
  const double cc = dot(p0, p0);
  const double top_disc = b * b - cc + top * top;
  if (top_disc <= 0.0) return;  // the line misses the atmosphere: zeros
  const double top_in = -b - std::sqrt(top_disc);
  const double top_out = -b + std::sqrt(top_disc);
  const auto fill = [&](double from_t, double to_t, const auto& value_at) {
    for (int k = std::max(static_cast<int>(std::floor(from_t / step)) + 1, 0);
         k <= last && k * step <= to_t; ++k) {
      auto out = table.grazing_node(i, j, k);
      for (std::size_t w = 0; w < n; ++w) out[w] = static_cast<float>(value_at(k * step, w));
    }
  };
  std::vector<double> value(n, 0.0);
  const double earth_disc = b * b - cc + earth * earth;
  double end = top_out;
  if (earth_disc > 0.0) {
    const double earth_in = -b - std::sqrt(earth_disc);
    const double earth_out = -b + std::sqrt(earth_disc);
    integrate_segment(c, table, i, j, p0, d, step, top_in, earth_in, value);
    const std::vector<double> reaching = value;
    // The sunlit Lambertian ground at the exit, albedo / pi (as build_column).
    const Vec3 exit = p0 + earth_out * d;
    std::vector<double> sun_t(n);
    sun_transmittance_at(c, exit, sun_t);
    const double cos_sun = std::max(0.0, dot(normalize(exit), c.sun));
    for (std::size_t w = 0; w < n; ++w) value[w] = sun_t[w] * a.ground_albedo[w] / kPi * cos_sun;
    const double chord = earth_out - earth_in;
    fill(earth_in, earth_out, [&](double t, std::size_t w) {
      const double f = chord > 0.0 ? (t - earth_in) / chord : 1.0;
      return (1.0 - f) * reaching[w] + f * value[w];
    });
    integrate_segment(c, table, i, j, p0, d, step, earth_out, top_out, value);
  } else {
    integrate_segment(c, table, i, j, p0, d, step, top_in, top_out, value);
  }
  fill(end, std::numeric_limits<double>::infinity(),
       [&](double, std::size_t w) { return value[w]; });
}

}  // namespace

std::vector<SamplingTable> empty_sampling_tables(const AtmosphereSpectra& atmosphere,
                                                 double sun_zenith_rad, int nodes) {
  const auto angles = sampling_angles_rad(sun_zenith_rad);
  std::vector<SamplingTable> tables;
  for (std::size_t k = 0; k < angles.size(); ++k) {
    // Tables 2 and 3 are the fixed horizontals (sampling_angles_rad).
    tables.emplace_back(angles[k], atmosphere.parameters.earth_radius_m,
                        atmosphere.parameters.top_radius_m, nodes, atmosphere.grid.size(),
                        k == 2 || k == 3);
  }
  return tables;
}

std::shared_ptr<const SunTables> build_sun_tables(const Nishita93Tables& optical_lengths,
                                                  const AtmosphereSpectra& atmosphere,
                                                  double sun_zenith_rad, int nodes,
                                                  int phase_theta_cells,
                                                  const PrecomputeContext& context) {
  std::vector<SamplingTable> tables = empty_sampling_tables(atmosphere, sun_zenith_rad, nodes);
  const ColumnContext c{
      optical_lengths, atmosphere, direction_of_angle(sun_zenith_rad),
      0.5 * (atmosphere.parameters.top_radius_m - atmosphere.parameters.earth_radius_m)};
  const int rows = nodes / 2 + 1;
  // The grazing layout has more columns across (kGrazingAcrossRefinement); the sheared one
  // skips the indices beyond its nodes.
  const int across = tables.front().grazing_across_nodes();
  const std::size_t columns_per_table = static_cast<std::size_t>(across) * rows;
  // The layouts to build: (table, grazing); both for a direction in the blend band.
  std::vector<std::pair<int, bool>> layouts;
  for (int t = 0; t < kSamplingDirections; ++t) {
    if (tables[static_cast<std::size_t>(t)].has_sheared()) layouts.emplace_back(t, false);
    if (tables[static_cast<std::size_t>(t)].has_grazing()) layouts.emplace_back(t, true);
  }
  parallel_for(
      layouts.size() * columns_per_table,
      [&](std::size_t x) {
        context.check_cancelled();
        const auto [t, grazing] = layouts[x / columns_per_table];
        const int i = static_cast<int>(x % columns_per_table) / rows;
        const int j = nodes / 2 + static_cast<int>(x % columns_per_table) % rows;
        if (grazing) {
          build_grazing_column(c, tables[static_cast<std::size_t>(t)], i, j);
        } else if (i < nodes) {
          build_column(c, tables[static_cast<std::size_t>(t)], i, j);
        }
      },
      context.threads, 8);
  context.report(1.0, "sampling tables");
  return std::make_shared<const SunTables>(sun_zenith_rad, std::move(tables), phase_theta_cells);
}

}  // namespace clearsky::nishita96
