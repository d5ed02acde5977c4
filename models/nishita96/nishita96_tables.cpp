// Single-scattering tables of the sampling directions of Nishita96 (see nishita96_tables.h).
#include "models/nishita96/nishita96_tables.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "models/atmosphere/phase_functions.h"
#include "models/core/fast_exp.h"
#include "models/core/invalid_input.h"
#include "models/core/numeric.h"
#include "models/core/parallel.h"
#include "models/nishita93/nishita93_functions.h"

namespace clearsky::nishita96 {

SamplingTable::SamplingTable(double angle_rad, double earth_radius_m, double top_radius_m,
                             int nodes, std::size_t wavelengths)
    : angle_rad_(angle_rad),
      earth_radius_m_(earth_radius_m),
      top_radius_m_(top_radius_m),
      half_width_m_(std::sqrt(top_radius_m * top_radius_m - earth_radius_m * earth_radius_m)),
      // The study tests the exact angles of the horizontal directions (+-90 degrees).
      horizontal_(angle_rad == 0.5 * kPi || angle_rad == -0.5 * kPi),
      axis_against_height_(angle_rad > -0.5 * kPi && angle_rad <= 0.5 * kPi),
      tan_angle_(std::tan(angle_rad)),
      nodes_(nodes),
      stored_rows_(nodes / 2 + 1),
      wavelengths_(wavelengths),
      values_(static_cast<std::size_t>(nodes) * (nodes / 2 + 1) * nodes * wavelengths, 0.0f) {
  if (nodes < 3 || nodes % 2 == 0) throw InvalidInput("table_nodes", "must be odd and >= 3");
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
  const double last = nodes_ - 1;
  const auto split = [last](double coordinate, int& index0, double& fraction) {
    const double c = std::clamp(coordinate * last, 0.0, last);
    index0 = std::min(static_cast<int>(c), static_cast<int>(last) - 1);
    fraction = c - index0;
  };
  int i0, j0, k0;
  double fu, fv, fw;
  split(u, i0, fu);
  split(v, j0, fv);
  split(w, k0, fw);
  const int jj0 = j0 - nodes_ / 2;  // >= 0 since v >= 0.5
  const float* corners[8];
  float weights[8];
  int c = 0;
  for (int di = 0; di < 2; ++di) {
    for (int dj = 0; dj < 2; ++dj) {
      for (int dk = 0; dk < 2; ++dk, ++c) {
        weights[c] =
            static_cast<float>((di ? fu : 1.0 - fu) * (dj ? fv : 1.0 - fv) * (dk ? fw : 1.0 - fw));
        corners[c] = values_.data() + index(i0 + di, std::max(jj0 + dj, 0), k0 + dk);
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

// One column of a table: nodes k = 0 .. nodes - 1 along the axis, from p0 in direction d
// with spacing step; the radiance arriving at each node from -d.
void build_column(const ColumnContext& c, SamplingTable& table, int i, int j) {
  const auto& a = c.atmosphere;
  const std::size_t n = a.grid.size();
  const double earth = a.parameters.earth_radius_m;
  const double top = a.parameters.top_radius_m;
  const Vec3 p0 = table.node_position(i, j, 0);
  const Vec3 p1 = table.node_position(i, j, 1);
  const double step = length(p1 - p0);
  const Vec3 d = (1.0 / step) * (p1 - p0);
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

}  // namespace

std::shared_ptr<const SunTables> build_sun_tables(const Nishita93Tables& optical_lengths,
                                                  const AtmosphereSpectra& atmosphere,
                                                  double sun_zenith_rad, int nodes,
                                                  int phase_theta_cells,
                                                  const PrecomputeContext& context) {
  const auto angles = sampling_angles_rad(sun_zenith_rad);
  std::vector<SamplingTable> tables;
  for (double a : angles) {
    tables.emplace_back(a, atmosphere.parameters.earth_radius_m, atmosphere.parameters.top_radius_m,
                        nodes, atmosphere.grid.size());
  }
  const ColumnContext c{
      optical_lengths, atmosphere, direction_of_angle(sun_zenith_rad),
      0.5 * (atmosphere.parameters.top_radius_m - atmosphere.parameters.earth_radius_m)};
  const int rows = nodes / 2 + 1;
  const std::size_t columns_per_table = static_cast<std::size_t>(nodes) * rows;
  parallel_for(
      kSamplingDirections * columns_per_table,
      [&](std::size_t x) {
        context.check_cancelled();
        const int t = static_cast<int>(x / columns_per_table);
        const int i = static_cast<int>(x % columns_per_table) / rows;
        const int j = nodes / 2 + static_cast<int>(x % columns_per_table) % rows;
        build_column(c, tables[static_cast<std::size_t>(t)], i, j);
      },
      context.threads, 8);
  context.report(1.0, "sampling tables");
  return std::make_shared<const SunTables>(sun_zenith_rad, std::move(tables), phase_theta_cells);
}

}  // namespace clearsky::nishita96
