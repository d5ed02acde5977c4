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

}  // namespace

std::shared_ptr<const HaberDome> build_dome(const HaberGrid& grid,
                                            const AtmosphereSpectra& atmosphere,
                                            double sun_zenith_rad,
                                            const PrecomputeContext& context) {
  const std::size_t n = atmosphere.grid.size();
  const int n_phi = grid.settings().azimuth_sectors;
  if (n_phi > 256) throw InvalidInput("azimuth_sectors", "must be at most 256");
  const int sectors = grid.stored_sectors();
  const auto& cells = grid.ring_cells();
  const auto& layers = grid.layers();
  const std::size_t ring_cell_count = cells.size();
  const std::size_t cell_count = grid.cell_count();
  const Vec3 sun{std::sin(sun_zenith_rad), 0.0, std::cos(sun_zenith_rad)};
  const Spectrum& sigma_r = atmosphere.rayleigh_scattering_per_m;
  const Spectrum& sigma_m = atmosphere.mie_scattering_per_m;
  const Spectrum& sigma_m_ext = atmosphere.mie_extinction_per_m;
  const double iso = isotropic_phase();
  const auto transmittance_of = [&](const OpticalLength& l, std::size_t w) {
    return l.blocked ? 0.0 : std::exp(-(sigma_r[w] * l.rayleigh_m + sigma_m_ext[w] * l.mie_m));
  };

  // Single scattering: the power (W/nm) scattered in each cell, Rayleigh (isotropic, with
  // the orders >= 2 added later) and Mie (Cornette-Shanks) apart.
  CellSpectra iso_power(cell_count, n), mie_power(cell_count, n), last(cell_count, n),
      current(cell_count, n);
  parallel_for(
      ring_cell_count,
      [&](std::size_t c) {
        context.check_cancelled();
        const RingCell& cell = cells[c];
        for (int j = 0; j < sectors; ++j) {
          const Vec3 p = grid.centre(cell, grid.sector_azimuth_rad(j));
          const OpticalLength l = optical_length(layers, p, exit_point(layers, p, sun));
          const std::size_t index = c * sectors + j;
          for (std::size_t w = 0; w < n; ++w) {
            const double power =
                transmittance_of(l, w) * atmosphere.solar_irradiance_w_m2_nm[w] * cell.volume_m3;
            iso_power.at(index)[w] = power * sigma_r[w] * layers.rayleigh_density(cell.layer);
            mie_power.at(index)[w] = power * sigma_m[w] * layers.mie_density(cell.layer);
          }
        }
      },
      context.threads);

  const int orders = grid.settings().scattering_orders;
  const auto& active = grid.active();
  const std::size_t n_active = active.size();
  // Float spectra of the gathering, padded with zeros to whole chunks.
  const std::size_t np = (n + kChunk - 1) / kChunk * kChunk;
  std::vector<float> sigma_r_f(np, 0.0f), sigma_m_ext_f(np, 0.0f);
  std::copy(sigma_r.begin(), sigma_r.end(), sigma_r_f.begin());
  std::copy(sigma_m_ext.begin(), sigma_m_ext.end(), sigma_m_ext_f.begin());
  // Optical lengths between every pair of active ring cells and every azimuth offset, kept
  // for all orders (they do not change): (target, source, delta) -> (l_R, l_M); l_R < 0 marks
  // a blocked path or the target itself.
  std::vector<float> pair_lengths;
  if (orders >= 2) pair_lengths.resize(n_active * n_active * n_phi * 2);
  // Source radiance per active ring cell: 2 n_phi sectors (mirrors duplicated) x n.
  const std::size_t source_stride = static_cast<std::size_t>(2 * n_phi) * np;
  std::vector<float> source_iso(n_active * source_stride), source_mie;
  std::vector<float> a_source;  // position . sun, 2 n_phi per active ring cell
  std::atomic<std::size_t> done{0};
  // Centres of the active cells in all n_phi sectors.
  std::vector<Vec3> positions(n_active * n_phi);
  for (std::size_t s = 0; s < n_active; ++s) {
    for (int j = 0; j < n_phi; ++j)
      positions[s * n_phi + j] = grid.centre(cells[active[s]], grid.sector_azimuth_rad(j));
  }
  // The optical length between target t in sector 0 and source s in sector delta is, by
  // rotation about the vertical, that between s in sector 0 and t in sector -delta: each
  // unordered pair is integrated once. Task t writes rows (t, s >= t) and (s > t, t) only.
  if (orders >= 2) {
    parallel_for(
        n_active,
        [&](std::size_t t) {
          context.check_cancelled();
          for (std::size_t s = t; s < n_active; ++s) {
            float* forward = pair_lengths.data() + (t * n_active + s) * n_phi * 2;
            float* backward = pair_lengths.data() + (s * n_active + t) * n_phi * 2;
            for (int delta = 0; delta < n_phi; ++delta) {
              const int mirrored = (n_phi - delta) % n_phi;
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
              backward[2 * mirrored] = rayleigh;
              backward[2 * mirrored + 1] = mie;
            }
          }
        },
        context.threads);
  }
  for (int order = 2; order <= orders; ++order) {
    const bool second = order == 2;
    // Radiance leaving each source cell along a path as long as its radial width.
    if (second) {
      source_mie.assign(n_active * source_stride, 0.0f);
      a_source.assign(n_active * 2 * n_phi, 0.0f);
    }
    for (std::size_t s = 0; s < n_active; ++s) {
      const RingCell& cell = cells[active[s]];
      const double to_radiance = cell.radial_width_m / cell.volume_m3;
      for (int js = 0; js < 2 * n_phi; ++js) {
        const std::size_t index = static_cast<std::size_t>(active[s]) * sectors + mirror(js, n_phi);
        float* si = source_iso.data() + s * source_stride + static_cast<std::size_t>(js) * np;
        if (second) {
          float* sm = source_mie.data() + s * source_stride + static_cast<std::size_t>(js) * np;
          for (std::size_t w = 0; w < n; ++w) {
            si[w] = static_cast<float>(iso_power.at(index)[w] * iso * to_radiance);
            sm[w] = static_cast<float>(mie_power.at(index)[w] * to_radiance);
          }
          a_source[s * 2 * n_phi + js] = static_cast<float>(
              dot(grid.centre(cell, grid.sector_azimuth_rad(mirror(js, n_phi))), sun));
        } else {
          for (std::size_t w = 0; w < n; ++w)
            si[w] = static_cast<float>(last.at(index)[w] * iso * to_radiance);
        }
      }
    }
    parallel_for(
        n_active,
        [&](std::size_t t) {
          context.check_cancelled();
          const RingCell& target = cells[active[t]];
          const Vec3 target0 = positions[t * n_phi];
          std::vector<double> total(static_cast<std::size_t>(sectors) * n, 0.0);
          std::vector<float> acc(static_cast<std::size_t>(sectors) * np);
          std::vector<float> kernel(static_cast<std::size_t>(n_phi) * np);
          std::vector<float> inverse_distance(n_phi);
          std::vector<float> a_target(sectors);
          for (int jt = 0; jt < sectors; ++jt) {
            a_target[jt] =
                static_cast<float>(dot(grid.centre(target, grid.sector_azimuth_rad(jt)), sun));
          }
          for (std::size_t s = 0; s < n_active; ++s) {
            const RingCell& source = cells[active[s]];
            const float* lengths = pair_lengths.data() + (t * n_active + s) * n_phi * 2;
            for (int delta = 0; delta < n_phi; ++delta) {
              const Vec3 p = positions[s * n_phi + delta];
              const Vec3 d = p - target0;
              const double distance2 = dot(d, d);
              inverse_distance[delta] =
                  distance2 > 0.0 ? static_cast<float>(1.0 / std::sqrt(distance2)) : 0.0f;
              float* k = kernel.data() + static_cast<std::size_t>(delta) * np;
              if (lengths[2 * delta] < 0.0f) {
                std::fill(k, k + np, 0.0f);
                continue;
              }
              // Solid angle of the source cell seen from the target over 4 pi, as the study's
              // code computes it: (volume / radial width) / (4 pi distance^2).
              const auto solid_angle_fraction = static_cast<float>(
                  source.volume_m3 / (source.radial_width_m * 4.0 * kPi * distance2));
              transmittance(sigma_r_f.data(), sigma_m_ext_f.data(), lengths[2 * delta],
                            lengths[2 * delta + 1], solid_angle_fraction, k, np);
            }
            std::fill(acc.begin(), acc.end(), 0.0f);
            if (second) {
              gather_double(kernel.data(), source_iso.data() + s * source_stride,
                            source_mie.data() + s * source_stride, a_source.data() + s * 2 * n_phi,
                            a_target.data(), inverse_distance.data(),
                            static_cast<float>(atmosphere.parameters.mie_phase_g), n_phi, np,
                            acc.data());
            } else {
              gather_isotropic(kernel.data(), source_iso.data() + s * source_stride, n_phi, np,
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
          context.report(static_cast<double>(finished) / (n_active * (orders - 1)),
                         "multiple scattering");
        },
        context.threads);

    // Other shells: linear interpolation along the ring between the gathering shells, then
    // the whole order scaled by the ratio of the source power of all cells to that of the
    // gathering cells (the sources were only the gathering cells).
    double all_power = 0.0;
    double active_power = 0.0;
    for (std::size_t c = 0; c < ring_cell_count; ++c) {
      const bool is_active = cells[c].shell % grid.settings().shell_stride == 0;
      for (int j = 0; j < sectors; ++j) {
        const std::size_t index = c * sectors + j;
        double power = 0.0;
        for (std::size_t w = 0; w < n; ++w) {
          power += second ? iso_power.at(index)[w] + mie_power.at(index)[w] : last.at(index)[w];
        }
        all_power += power;
        if (is_active) active_power += power;
      }
    }
    const double scale = active_power > 0.0 ? all_power / active_power : 0.0;
    for (std::size_t c = 0; c < ring_cell_count; ++c) {
      const RingCell& cell = cells[c];
      if (cell.shell % grid.settings().shell_stride == 0) continue;
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
        for (std::size_t w = 0; w < n; ++w) {
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
    for (std::size_t x = 0; x < current.values.size(); ++x) {
      const double value = current.values[x] * scale;
      iso_power.values[x] += value;
      last.values[x] = value;
      current.values[x] = 0.0;
    }
  }

  // The dome: light scattered towards the viewer by the cells along each (ring, sector)
  // centre direction, attenuated to the viewer.
  const int rings = grid.ring_count();
  std::vector<double> dome(static_cast<std::size_t>(rings) * sectors * n, 0.0);
  const Vec3 viewer{0.0, 0.0, layers.earth_radius_m()};
  const double g = atmosphere.parameters.mie_phase_g;
  parallel_for(
      static_cast<std::size_t>(rings) * sectors,
      [&](std::size_t x) {
        const int i = static_cast<int>(x) / sectors;
        const int j = static_cast<int>(x) % sectors;
        const double view_zenith = (i + 0.5) * grid.angular_step_rad();
        const double view_azimuth = grid.sector_azimuth_rad(j);
        const double mu =
            clamp_cosine(std::cos(sun_zenith_rad) * std::cos(view_zenith) +
                         std::sin(sun_zenith_rad) * std::sin(view_zenith) * std::cos(view_azimuth));
        const double mie_phase = cornette_shanks_phase(mu, g);
        double* out = dome.data() + x * n;
        for (int c = grid.ring_begin()[i]; c < grid.ring_begin()[i + 1]; ++c) {
          const RingCell& cell = cells[c];
          const std::size_t index = static_cast<std::size_t>(c) * sectors + j;
          const OpticalLength l = optical_length(layers, viewer, grid.centre(cell, view_azimuth));
          const double to_radiance = cell.radial_width_m / cell.volume_m3;
          for (std::size_t w = 0; w < n; ++w) {
            out[w] += transmittance_of(l, w) *
                      (iso_power.at(index)[w] * iso + mie_power.at(index)[w] * mie_phase) *
                      to_radiance;
          }
        }
      },
      context.threads);
  context.report(1.0, "done");
  return std::make_shared<const HaberDome>(rings, sectors, grid.angular_step_rad(), n,
                                           std::move(dome));
}

}  // namespace clearsky::haber
