// Grid, multiple-scattering gathering and sky dome of the Haber model (see haber_tables.h).
#include "models/haber/haber_tables.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "models/atmosphere/phase_functions.h"
#include "models/core/fast_exp_float.h"
#include "models/core/invalid_input.h"
#include "models/core/numeric.h"
#include "models/core/parallel.h"

namespace clearsky::haber {

HaberGrid::HaberGrid(const HaberSettings& settings, double earth_radius_m,
                     double rayleigh_scale_height_m, double mie_scale_height_m)
    : settings_(settings),
      layers_(earth_radius_m, settings.top_height_m, settings.layer_count, rayleigh_scale_height_m,
              mie_scale_height_m),
      angular_step_rad_(2.0 * kPi / settings.azimuth_sectors) {
  if (settings.azimuth_sectors < 8 || settings.azimuth_sectors % 2 != 0)
    throw InvalidInput("azimuth_sectors", "must be even and >= 8");
  if (settings.shell_stride < 1) throw InvalidInput("shell_stride", "must be >= 1");
  if (settings.layer_count < 1) throw InvalidInput("layers", "must be >= 1");
  if (settings.scattering_orders < 1) throw InvalidInput("scattering_orders", "must be >= 1");
  const double n_phi = settings.azimuth_sectors;
  // Shells as thick as the cells are wide (Haber et al. 2005): r_{k+1} / r_k = (1 + pi/n) / (1 - pi/n).
  const double ratio = (1.0 + kPi / n_phi) / (1.0 - kPi / n_phi);
  const double top = settings.top_height_m;
  // Distance from the viewer to the top of the layers seen at the horizon.
  const double max_shell = std::sqrt(top * top + 2.0 * earth_radius_m * top);
  shell_count_ = static_cast<int>(
      std::ceil(std::log(max_shell / settings.min_shell_radius_m) / std::log(ratio)));
  // Rings down to the zenith angle of that farthest point (just below the horizon).
  ring_count_ = static_cast<int>(std::ceil(
      (0.5 * kPi + 2.0 * std::asin(max_shell / (2.0 * earth_radius_m))) / angular_step_rad_));
  const double sector_solid_fraction = 2.0 * kPi / n_phi;
  const double top_radius = earth_radius_m + top;
  for (int i = 0; i < ring_count_; ++i) {
    ring_begin_.push_back(static_cast<int>(ring_cells_.size()));
    const double theta = (i + 0.5) * angular_step_rad_;
    const double cos_min = std::cos(i * angular_step_rad_);
    const double cos_max = std::cos((i + 1) * angular_step_rad_);
    for (int k = 0; k < shell_count_; ++k) {
      const double r_min = settings.min_shell_radius_m * std::pow(ratio, k);
      const double r_max = settings.min_shell_radius_m * std::pow(ratio, k + 1);
      const double r = 0.5 * (r_min + r_max);
      const double centre_radius =
          length(Vec3{r * std::sin(theta), 0.0, earth_radius_m + r * std::cos(theta)});
      if (centre_radius <= earth_radius_m) continue;
      if (centre_radius >= top_radius) break;
      RingCell cell;
      cell.ring = i;
      cell.shell = k;
      cell.radius_m = r;
      cell.volume_m3 = (r_max * r_max * r_max - r_min * r_min * r_min) / 3.0 *
                       sector_solid_fraction * (cos_min - cos_max);
      cell.radial_width_m = r_max - r_min;
      cell.layer = layers_.layer_index(centre_radius);
      ring_cells_.push_back(cell);
    }
  }
  ring_begin_.push_back(static_cast<int>(ring_cells_.size()));
  const int stride = settings.shell_stride;
  for (int i = 0; i < ring_count_; ++i) {
    for (int c = ring_begin_[i]; c < ring_begin_[i + 1]; ++c) {
      RingCell& cell = ring_cells_[c];
      if (cell.shell % stride == 0) {
        active_.push_back(c);
        continue;
      }
      const int shell0 = stride * (cell.shell / stride);
      const int shell1 = shell0 + stride;
      for (int o = ring_begin_[i]; o < ring_begin_[i + 1]; ++o) {
        if (ring_cells_[o].shell == shell0) cell.lower_active = o;
        if (ring_cells_[o].shell == shell1) cell.upper_active = o;
      }
      cell.upper_weight = static_cast<double>(cell.shell % stride) / stride;
    }
  }
}

Vec3 HaberGrid::centre(const RingCell& cell, double phi_rad) const {
  const double theta = (cell.ring + 0.5) * angular_step_rad_;
  const double s = cell.radius_m * std::sin(theta);
  return {s * std::cos(phi_rad), s * std::sin(phi_rad),
          layers_.earth_radius_m() + cell.radius_m * std::cos(theta)};
}

void HaberDome::radiance(double view_zenith_rad, double view_sun_azimuth_rad,
                         std::span<double> out) const {
  // Texel centres at (i + 0.5) step: clamped bilinear interpolation.
  const double u = view_zenith_rad / step_ - 0.5;
  const double v = view_sun_azimuth_rad / step_ - 0.5;
  const double fi = std::floor(u);
  const double fj = std::floor(v);
  const double a = u - fi;
  const double b = v - fj;
  const auto clamp_index = [](double x, int n) {
    return static_cast<int>(std::clamp(x, 0.0, n - 1.0));
  };
  const int i0 = clamp_index(fi, rings_), i1 = clamp_index(fi + 1.0, rings_);
  const int j0 = clamp_index(fj, sectors_), j1 = clamp_index(fj + 1.0, sectors_);
  const auto l00 = node(i0, j0), l10 = node(i1, j0), l01 = node(i0, j1), l11 = node(i1, j1);
  for (std::size_t w = 0; w < out.size(); ++w) {
    out[w] =
        (1 - a) * (1 - b) * l00[w] + a * (1 - b) * l10[w] + (1 - a) * b * l01[w] + a * b * l11[w];
  }
}

namespace {

// Per-cell spectra of the precomputation, cell (ring cell c, sector j) at c * sectors + j.
struct CellSpectra {
  std::size_t wavelengths;
  std::vector<double> values;
  CellSpectra(std::size_t cells, std::size_t n) : wavelengths(n), values(cells * n, 0.0) {}
  double* at(std::size_t cell) { return values.data() + cell * wavelengths; }
  const double* at(std::size_t cell) const { return values.data() + cell * wavelengths; }
};

// Transmittances exp(-(sigma_R l_R + sigma_M,ext l_M)) for the float arrays of the gathering.
__attribute__((target_clones("avx2", "default"))) void transmittance(const float* sigma_rayleigh,
                                                                     const float* sigma_mie,
                                                                     float rayleigh_m, float mie_m,
                                                                     float weight, float* out,
                                                                     std::size_t n) {
  for (std::size_t w = 0; w < n; ++w) {
    out[w] =
        weight * exp_nonpositive_float(-(sigma_rayleigh[w] * rayleigh_m + sigma_mie[w] * mie_m));
  }
}

// The hot loops of the gathering: for each stored target sector jt, the sum over the n_phi
// source sectors js of kernel[(js - jt) mod n_phi] * source[js]. Sources are given for 2 n_phi
// sectors (mirrors included, duplicated) so that js = jt + delta reads contiguously. Spectra
// are padded to a multiple of kChunk floats; each chunk's sum stays in registers over delta.
constexpr std::size_t kChunk = 8;
// A chunk as a GCC vector (one AVX register, two SSE registers in the default clone).
using Chunk = float __attribute__((vector_size(kChunk * sizeof(float))));

// Unaligned loads and stores; chunks pass by reference (a vector argument or return value
// would change the ABI between the AVX and default clones).
#define CLEARSKY_LOAD_CHUNK(name, pointer) \
  Chunk name;                              \
  std::memcpy(&name, (pointer), sizeof(Chunk))
inline void add_to(float* p, const Chunk& c) {
  Chunk old;
  std::memcpy(&old, p, sizeof(old));
  old += c;
  std::memcpy(p, &old, sizeof(old));
}

__attribute__((target_clones("avx2", "default"))) void gather_isotropic(
    const float* kernel, const float* source, int n_phi, std::size_t n_padded, float* accumulator) {
  const int stored = n_phi / 2;
  for (int jt = 0; jt < stored; ++jt) {
    for (std::size_t w0 = 0; w0 < n_padded; w0 += kChunk) {
      // Four partial sums (delta mod 4) so that the additions do not wait on each other.
      Chunk sum[4] = {};
      int delta = 0;
      for (; delta + 4 <= n_phi; delta += 4) {
        for (int u = 0; u < 4; ++u) {
          CLEARSKY_LOAD_CHUNK(k, kernel + static_cast<std::size_t>(delta + u) * n_padded + w0);
          CLEARSKY_LOAD_CHUNK(x, source + static_cast<std::size_t>(jt + delta + u) * n_padded + w0);
          sum[u] += k * x;
        }
      }
      for (; delta < n_phi; ++delta) {
        CLEARSKY_LOAD_CHUNK(k, kernel + static_cast<std::size_t>(delta) * n_padded + w0);
        CLEARSKY_LOAD_CHUNK(x, source + static_cast<std::size_t>(jt + delta) * n_padded + w0);
        sum[0] += k * x;
      }
      add_to(accumulator + static_cast<std::size_t>(jt) * n_padded + w0,
             (sum[0] + sum[1]) + (sum[2] + sum[3]));
    }
  }
}

// As gather_isotropic, with a second source weighted by the Cornette-Shanks phase function of
// the angle between the sun and the direction target -> source (single-scattered Mie light,
// the source of order 2). mu = (a_s[js] - a_t[jt]) * inverse_distance[delta] with a = position
// . sun direction.
__attribute__((target_clones("avx2", "default"))) void gather_double(
    const float* kernel, const float* source_iso, const float* source_mie, const float* a_source,
    const float* a_target, const float* inverse_distance, float g, int n_phi, std::size_t n_padded,
    float* accumulator) {
  const int stored = n_phi / 2;
  const float g2 = g * g;
  const float phase_scale = 3.0f / (8.0f * static_cast<float>(kPi)) * (1.0f - g2) / (2.0f + g2);
  float phase[512];
  for (int jt = 0; jt < stored; ++jt) {
    for (int delta = 0; delta < n_phi; ++delta) {
      float mu = (a_source[jt + delta] - a_target[jt]) * inverse_distance[delta];
      mu = mu > 1.0f ? 1.0f : mu;
      mu = mu < -1.0f ? -1.0f : mu;
      const float x = 1.0f + g2 - 2.0f * g * mu;
      phase[delta] = phase_scale * (1.0f + mu * mu) / (x * std::sqrt(x));
    }
    for (std::size_t w0 = 0; w0 < n_padded; w0 += kChunk) {
      Chunk sum[4] = {};
      for (int delta = 0; delta < n_phi; ++delta) {
        const std::size_t offset = static_cast<std::size_t>(jt + delta) * n_padded + w0;
        CLEARSKY_LOAD_CHUNK(k, kernel + static_cast<std::size_t>(delta) * n_padded + w0);
        CLEARSKY_LOAD_CHUNK(si, source_iso + offset);
        CLEARSKY_LOAD_CHUNK(sm, source_mie + offset);
        sum[delta & 3] += k * (si + phase[delta] * sm);
      }
      add_to(accumulator + static_cast<std::size_t>(jt) * n_padded + w0,
             (sum[0] + sum[1]) + (sum[2] + sum[3]));
    }
  }
}

#undef CLEARSKY_LOAD_CHUNK

int mirror(int j, int n_phi) {
  const int m = ((j % n_phi) + n_phi) % n_phi;
  return m < n_phi / 2 ? m : n_phi - 1 - m;
}

// The phases of build_dome (Haber et al. 2005): single scattering into every cell,
// the optical lengths between gathering cells, then per order the radiance leaving the
// gathering cells, its gathering by every gathering cell, its spread to the other shells, and
// finally the dome seen by the viewer.

// What every phase reads: the grid, the atmosphere's spectra and the sun.
struct DomeProblem {
  const HaberGrid& grid;
  const AtmosphereSpectra& atmosphere;
  const PrecomputeContext& context;
  double sun_zenith_rad;
  Vec3 sun;        // unit vector towards the sun, in the plane of azimuth 0
  std::size_t n;   // wavelengths
  std::size_t np;  // wavelengths padded to whole chunks (float arrays of the gathering)
  int n_phi;       // azimuth sectors of the full circle
  int sectors;     // stored sectors (half circle, mirror-symmetric about the sun's plane)
  double iso;      // isotropic phase function, 1 / (4 pi)

  double transmittance_of(const OpticalLength& l, std::size_t w) const {
    return l.blocked ? 0.0
                     : std::exp(-(atmosphere.rayleigh_scattering_per_m[w] * l.rayleigh_m +
                                  atmosphere.mie_extinction_per_m[w] * l.mie_m));
  }
  std::size_t active_count() const { return grid.active().size(); }
};

// Single scattering: the power (W/nm) scattered in each cell by the attenuated sunlight,
// Rayleigh into iso_power (isotropic, with the orders >= 2 added later) and Mie
// (Cornette-Shanks) into mie_power.
void single_scattering_power(const DomeProblem& p, CellSpectra& iso_power, CellSpectra& mie_power) {
  const auto& cells = p.grid.ring_cells();
  const auto& layers = p.grid.layers();
  const Spectrum& sigma_r = p.atmosphere.rayleigh_scattering_per_m;
  const Spectrum& sigma_m = p.atmosphere.mie_scattering_per_m;
  parallel_for(
      cells.size(),
      [&](std::size_t c) {
        p.context.check_cancelled();
        const RingCell& cell = cells[c];
        for (int j = 0; j < p.sectors; ++j) {
          const Vec3 x = p.grid.centre(cell, p.grid.sector_azimuth_rad(j));
          const OpticalLength l = optical_length(layers, x, exit_point(layers, x, p.sun));
          const std::size_t index = c * p.sectors + j;
          for (std::size_t w = 0; w < p.n; ++w) {
            const double power = p.transmittance_of(l, w) *
                                 p.atmosphere.solar_irradiance_w_m2_nm[w] * cell.volume_m3;
            iso_power.at(index)[w] = power * sigma_r[w] * layers.rayleigh_density(cell.layer);
            mie_power.at(index)[w] = power * sigma_m[w] * layers.mie_density(cell.layer);
          }
        }
      },
      p.context.threads);
}

// Centres of the active (gathering) cells in all n_phi sectors, active cell s at s * n_phi + j.
std::vector<Vec3> active_cell_centres(const DomeProblem& p) {
  const auto& cells = p.grid.ring_cells();
  const auto& active = p.grid.active();
  std::vector<Vec3> positions(active.size() * p.n_phi);
  for (std::size_t s = 0; s < active.size(); ++s) {
    for (int j = 0; j < p.n_phi; ++j)
      positions[s * p.n_phi + j] = p.grid.centre(cells[active[s]], p.grid.sector_azimuth_rad(j));
  }
  return positions;
}

// Optical lengths between every pair of active ring cells and every azimuth offset, kept for
// all orders (they do not change). The optical length between target t in sector 0 and source
// s in sector delta is, by rotation about the vertical, that between s in sector 0 and t in
// sector -delta, so only the pairs t <= s are kept (a packed upper triangle, half the memory of
// the full matrix: this is the largest array of a sun's precomputation) and the pairs s < t are
// read from (s, t) at the mirrored offset. Each pair holds n_phi (l_R, l_M) float pairs;
// l_R < 0 marks a blocked path or the target itself.
class PairOpticalLengths {
 public:
  PairOpticalLengths(std::size_t active_cells, int n_phi)
      : n_active_(active_cells),
        n_phi_(n_phi),
        lengths_(active_cells * (active_cells + 1) / 2 * static_cast<std::size_t>(n_phi) * 2) {}

  // The n_phi (l_R, l_M) pairs from target t (t <= s) to source s, by azimuth offset.
  float* row(std::size_t t, std::size_t s) { return lengths_.data() + offset(t, s); }
  // (l_R, l_M) from target t in sector 0 to source s in sector delta, for any t and s.
  const float* at(std::size_t t, std::size_t s, int delta) const {
    if (t <= s) return lengths_.data() + offset(t, s) + 2 * static_cast<std::size_t>(delta);
    const int mirrored = (n_phi_ - delta) % n_phi_;
    return lengths_.data() + offset(s, t) + 2 * static_cast<std::size_t>(mirrored);
  }

 private:
  // Rows t of the packed triangle hold the sources s = t .. n_active - 1.
  std::size_t offset(std::size_t t, std::size_t s) const {
    const std::size_t pairs_before_row = t * (2 * n_active_ - t + 1) / 2;  // sum of n - r, r < t
    return (pairs_before_row + (s - t)) * static_cast<std::size_t>(n_phi_) * 2;
  }

  std::size_t n_active_;
  int n_phi_;
  std::vector<float> lengths_;
};

PairOpticalLengths pair_optical_lengths(const DomeProblem& p, const std::vector<Vec3>& positions) {
  const auto& layers = p.grid.layers();
  const std::size_t n_active = p.active_count();
  const int n_phi = p.n_phi;
  PairOpticalLengths pair_lengths(n_active, n_phi);
  parallel_for(
      n_active,
      [&](std::size_t t) {
        p.context.check_cancelled();
        for (std::size_t s = t; s < n_active; ++s) {
          float* forward = pair_lengths.row(t, s);
          for (int delta = 0; delta < n_phi; ++delta) {
            float rayleigh = -1.0f;
            float mie = 0.0f;
            if (!(s == t && delta == 0)) {
              const OpticalLength l =
                  optical_length(layers, positions[s * n_phi + delta], positions[t * n_phi]);
              rayleigh = l.blocked ? -1.0f : static_cast<float>(l.rayleigh_m);
              mie = static_cast<float>(l.mie_m);
            }
            forward[2 * delta] = rayleigh;
            forward[2 * delta + 1] = mie;
          }
        }
      },
      p.context.threads);
  return pair_lengths;
}

// Radiance leaving each active cell towards the others, per active ring cell: 2 n_phi sectors
// (mirrors duplicated, so that the gathering reads contiguously) x np floats. The source of
// order 2 keeps single-scattered Mie light apart (mie, with a = centre . sun per sector for its
// phase function); later orders are isotropic only.
struct SourceRadiance {
  std::size_t stride = 0;  // floats per active ring cell
  std::vector<float> iso;
  std::vector<float> mie;
  std::vector<float> a;  // centre . sun, 2 n_phi per active ring cell (order 2 only)
};

// The radiance leaving each active cell along a path as long as its radial width: the power
// it scatters (single-scattered for order 2, the previous order's otherwise) spread over the
// cell's volume.
void emitted_radiance(const DomeProblem& p, bool second, const CellSpectra& iso_power,
                      const CellSpectra& mie_power, const CellSpectra& last,
                      SourceRadiance& source) {
  const auto& cells = p.grid.ring_cells();
  const auto& active = p.grid.active();
  const std::size_t n_active = active.size();
  const int n_phi = p.n_phi;
  if (second) {
    source.mie.assign(n_active * source.stride, 0.0f);
    source.a.assign(n_active * 2 * n_phi, 0.0f);
  }
  for (std::size_t s = 0; s < n_active; ++s) {
    const RingCell& cell = cells[active[s]];
    const double to_radiance = cell.radial_width_m / cell.volume_m3;
    for (int js = 0; js < 2 * n_phi; ++js) {
      const std::size_t index = static_cast<std::size_t>(active[s]) * p.sectors + mirror(js, n_phi);
      float* si = source.iso.data() + s * source.stride + static_cast<std::size_t>(js) * p.np;
      if (second) {
        float* sm = source.mie.data() + s * source.stride + static_cast<std::size_t>(js) * p.np;
        for (std::size_t w = 0; w < p.n; ++w) {
          si[w] = static_cast<float>(iso_power.at(index)[w] * p.iso * to_radiance);
          sm[w] = static_cast<float>(mie_power.at(index)[w] * to_radiance);
        }
        source.a[s * 2 * n_phi + js] = static_cast<float>(
            dot(p.grid.centre(cell, p.grid.sector_azimuth_rad(mirror(js, n_phi))), p.sun));
      } else {
        for (std::size_t w = 0; w < p.n; ++w)
          si[w] = static_cast<float>(last.at(index)[w] * p.iso * to_radiance);
      }
    }
  }
}

// A spectrum as floats padded with zeros to np (the gathering's arrays).
std::vector<float> padded_floats(const Spectrum& spectrum, std::size_t np) {
  std::vector<float> out(np, 0.0f);
  std::copy(spectrum.begin(), spectrum.end(), out.begin());
  return out;
}

// One order of scattering at the active cells: each target gathers the radiance of every
// source cell in every sector, attenuated along the path and weighted by the solid angle of
// the source, and scatters the irradiance so received into `current` (power, W/nm). Progress
// counts finished targets over all orders (`done` of `total_targets`).
void gather_scattered_power(const DomeProblem& p, bool second, const SourceRadiance& source,
                            const std::vector<Vec3>& positions,
                            const PairOpticalLengths& pair_lengths, CellSpectra& current,
                            std::atomic<std::size_t>& done, std::size_t total_targets) {
  const auto& cells = p.grid.ring_cells();
  const auto& active = p.grid.active();
  const auto& layers = p.grid.layers();
  const std::size_t n_active = active.size();
  const int n_phi = p.n_phi;
  const int sectors = p.sectors;
  const std::size_t n = p.n;
  const std::size_t np = p.np;
  const Spectrum& sigma_r = p.atmosphere.rayleigh_scattering_per_m;
  const Spectrum& sigma_m = p.atmosphere.mie_scattering_per_m;
  const std::vector<float> sigma_r_f = padded_floats(sigma_r, np);
  const std::vector<float> sigma_m_ext_f = padded_floats(p.atmosphere.mie_extinction_per_m, np);
  parallel_for(
      n_active,
      [&](std::size_t t) {
        p.context.check_cancelled();
        const RingCell& target = cells[active[t]];
        const Vec3 target0 = positions[t * n_phi];
        std::vector<double> total(static_cast<std::size_t>(sectors) * n, 0.0);
        std::vector<float> acc(static_cast<std::size_t>(sectors) * np);
        std::vector<float> kernel(static_cast<std::size_t>(n_phi) * np);
        std::vector<float> inverse_distance(n_phi);
        std::vector<float> a_target(sectors);
        for (int jt = 0; jt < sectors; ++jt) {
          a_target[jt] =
              static_cast<float>(dot(p.grid.centre(target, p.grid.sector_azimuth_rad(jt)), p.sun));
        }
        for (std::size_t s = 0; s < n_active; ++s) {
          const RingCell& source_cell = cells[active[s]];
          for (int delta = 0; delta < n_phi; ++delta) {
            const float* lengths = pair_lengths.at(t, s, delta);
            const Vec3 x = positions[s * n_phi + delta];
            const Vec3 d = x - target0;
            const double distance2 = dot(d, d);
            inverse_distance[delta] =
                distance2 > 0.0 ? static_cast<float>(1.0 / std::sqrt(distance2)) : 0.0f;
            float* k = kernel.data() + static_cast<std::size_t>(delta) * np;
            if (lengths[0] < 0.0f) {
              std::fill(k, k + np, 0.0f);
              continue;
            }
            // Solid angle of the source cell seen from the target over 4 pi, as the study's
            // code computes it: (volume / radial width) / (4 pi distance^2).
            const auto solid_angle_fraction = static_cast<float>(
                source_cell.volume_m3 / (source_cell.radial_width_m * 4.0 * kPi * distance2));
            transmittance(sigma_r_f.data(), sigma_m_ext_f.data(), lengths[0], lengths[1],
                          solid_angle_fraction, k, np);
          }
          std::fill(acc.begin(), acc.end(), 0.0f);
          if (second) {
            gather_double(kernel.data(), source.iso.data() + s * source.stride,
                          source.mie.data() + s * source.stride, source.a.data() + s * 2 * n_phi,
                          a_target.data(), inverse_distance.data(),
                          static_cast<float>(p.atmosphere.parameters.mie_phase_g), n_phi, np,
                          acc.data());
          } else {
            gather_isotropic(kernel.data(), source.iso.data() + s * source.stride, n_phi, np,
                             acc.data());
          }
          for (int jt = 0; jt < sectors; ++jt) {
            for (std::size_t w = 0; w < n; ++w) total[jt * n + w] += acc[jt * np + w];
          }
        }
        // Power scattered by the target cells: irradiance x scattering coefficient x volume.
        for (int jt = 0; jt < sectors; ++jt) {
          double* out = current.at(static_cast<std::size_t>(active[t]) * sectors + jt);
          for (std::size_t w = 0; w < n; ++w) {
            const double scattering = sigma_r[w] * layers.rayleigh_density(target.layer) +
                                      sigma_m[w] * layers.mie_density(target.layer);
            out[w] = total[static_cast<std::size_t>(jt) * n + w] * scattering * target.volume_m3;
          }
        }
        const std::size_t finished = ++done;
        p.context.report(static_cast<double>(finished) / total_targets, "multiple scattering");
      },
      p.context.threads);
}

// The ratio of the source power of all cells to that of the gathering cells: the sources of
// an order were only the gathering cells, so the order is scaled by it (0 when they are dark).
double all_to_gathering_power_ratio(const DomeProblem& p, bool second, const CellSpectra& iso_power,
                                    const CellSpectra& mie_power, const CellSpectra& last) {
  const auto& cells = p.grid.ring_cells();
  double all_power = 0.0;
  double active_power = 0.0;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const bool is_active = cells[c].shell % p.grid.settings().shell_stride == 0;
    for (int j = 0; j < p.sectors; ++j) {
      const std::size_t index = c * p.sectors + j;
      double power = 0.0;
      for (std::size_t w = 0; w < p.n; ++w) {
        power += second ? iso_power.at(index)[w] + mie_power.at(index)[w] : last.at(index)[w];
      }
      all_power += power;
      if (is_active) active_power += power;
    }
  }
  return active_power > 0.0 ? all_power / active_power : 0.0;
}

// The cells between gathering shells: linear interpolation along the ring between the
// gathering shells below and above (the nearer one alone at the ends of a ring).
void interpolate_between_gathering_shells(const DomeProblem& p, CellSpectra& current) {
  const auto& cells = p.grid.ring_cells();
  const int sectors = p.sectors;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const RingCell& cell = cells[c];
    if (cell.shell % p.grid.settings().shell_stride == 0) continue;
    for (int j = 0; j < sectors; ++j) {
      double* out = current.at(c * sectors + j);
      const double* lower =
          cell.lower_active >= 0
              ? current.at(static_cast<std::size_t>(cell.lower_active) * sectors + j)
              : nullptr;
      const double* upper =
          cell.upper_active >= 0
              ? current.at(static_cast<std::size_t>(cell.upper_active) * sectors + j)
              : nullptr;
      for (std::size_t w = 0; w < p.n; ++w) {
        if (lower != nullptr && upper != nullptr) {
          out[w] = (1.0 - cell.upper_weight) * lower[w] + cell.upper_weight * upper[w];
        } else if (lower != nullptr) {
          out[w] = lower[w];
        } else if (upper != nullptr) {
          out[w] = upper[w];
        } else {
          out[w] = 0.0;
        }
      }
    }
  }
}

// Scales the order just computed and adds it to the isotropic power; the scaled order stays in
// `order` as the source of the next one.
void add_order(double scale, CellSpectra& order, CellSpectra& iso_power) {
  for (std::size_t x = 0; x < order.values.size(); ++x) {
    order.values[x] *= scale;
    iso_power.values[x] += order.values[x];
  }
}

// Orders 2 to scattering_orders, added into iso_power (Rayleigh and Mie scattered light both
// re-scatter isotropically in the model).
void multiple_scattering(const DomeProblem& p, CellSpectra& iso_power,
                         const CellSpectra& mie_power) {
  const int orders = p.grid.settings().scattering_orders;
  if (orders < 2) return;
  const std::size_t cell_count = p.grid.cell_count();
  const std::size_t n_active = p.active_count();
  // One array holds the last order (the source of the next) and then the next: the source is
  // read into `source` and its power ratio taken before the gathering overwrites it (every
  // gathering cell by the gathering, every other cell by the interpolation), so the order
  // being computed needs no array of its own (one cell_count x n array less at the peak).
  CellSpectra order_power(cell_count, p.n);
  const std::vector<Vec3> positions = active_cell_centres(p);
  const PairOpticalLengths pair_lengths = pair_optical_lengths(p, positions);
  SourceRadiance source;
  source.stride = static_cast<std::size_t>(2 * p.n_phi) * p.np;
  source.iso.resize(n_active * source.stride);
  std::atomic<std::size_t> done{0};
  for (int order = 2; order <= orders; ++order) {
    const bool second = order == 2;
    emitted_radiance(p, second, iso_power, mie_power, order_power, source);
    const double scale = all_to_gathering_power_ratio(p, second, iso_power, mie_power, order_power);
    gather_scattered_power(p, second, source, positions, pair_lengths, order_power, done,
                           n_active * (orders - 1));
    interpolate_between_gathering_shells(p, order_power);
    add_order(scale, order_power, iso_power);
  }
}

// The dome: light scattered towards the viewer by the cells along each (ring, sector) centre
// direction, attenuated to the viewer, as ring_count x sectors x n radiances.
std::vector<double> dome_radiance(const DomeProblem& p, const CellSpectra& iso_power,
                                  const CellSpectra& mie_power) {
  const auto& cells = p.grid.ring_cells();
  const auto& layers = p.grid.layers();
  const int sectors = p.sectors;
  const std::size_t n = p.n;
  const int rings = p.grid.ring_count();
  std::vector<double> dome(static_cast<std::size_t>(rings) * sectors * n, 0.0);
  const Vec3 viewer{0.0, 0.0, layers.earth_radius_m()};
  const double g = p.atmosphere.parameters.mie_phase_g;
  parallel_for(
      static_cast<std::size_t>(rings) * sectors,
      [&](std::size_t x) {
        const int i = static_cast<int>(x) / sectors;
        const int j = static_cast<int>(x) % sectors;
        const double view_zenith = (i + 0.5) * p.grid.angular_step_rad();
        const double view_azimuth = p.grid.sector_azimuth_rad(j);
        const double mu = clamp_cosine(std::cos(p.sun_zenith_rad) * std::cos(view_zenith) +
                                       std::sin(p.sun_zenith_rad) * std::sin(view_zenith) *
                                           std::cos(view_azimuth));
        const double mie_phase = cornette_shanks_phase(mu, g);
        double* out = dome.data() + x * n;
        for (int c = p.grid.ring_begin()[i]; c < p.grid.ring_begin()[i + 1]; ++c) {
          const RingCell& cell = cells[c];
          const std::size_t index = static_cast<std::size_t>(c) * sectors + j;
          const OpticalLength l = optical_length(layers, viewer, p.grid.centre(cell, view_azimuth));
          const double to_radiance = cell.radial_width_m / cell.volume_m3;
          for (std::size_t w = 0; w < n; ++w) {
            out[w] += p.transmittance_of(l, w) *
                      (iso_power.at(index)[w] * p.iso + mie_power.at(index)[w] * mie_phase) *
                      to_radiance;
          }
        }
      },
      p.context.threads);
  return dome;
}

}  // namespace

std::shared_ptr<const HaberDome> build_dome(const HaberGrid& grid,
                                            const AtmosphereSpectra& atmosphere,
                                            double sun_zenith_rad,
                                            const PrecomputeContext& context) {
  const int n_phi = grid.settings().azimuth_sectors;
  if (n_phi > 256) throw InvalidInput("azimuth_sectors", "must be at most 256");
  const std::size_t n = atmosphere.grid.size();
  const DomeProblem problem{grid,
                            atmosphere,
                            context,
                            sun_zenith_rad,
                            Vec3{std::sin(sun_zenith_rad), 0.0, std::cos(sun_zenith_rad)},
                            n,
                            (n + kChunk - 1) / kChunk * kChunk,
                            n_phi,
                            grid.stored_sectors(),
                            isotropic_phase()};
  CellSpectra iso_power(grid.cell_count(), n), mie_power(grid.cell_count(), n);
  single_scattering_power(problem, iso_power, mie_power);
  multiple_scattering(problem, iso_power, mie_power);
  std::vector<double> dome = dome_radiance(problem, iso_power, mie_power);
  context.report(1.0, "done");
  return std::make_shared<const HaberDome>(grid.ring_count(), grid.stored_sectors(),
                                           grid.angular_step_rad(), n, std::move(dome));
}

}  // namespace clearsky::haber
