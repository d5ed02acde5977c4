// The per-sun precomputation of the Haber model (Haber et al. 2005) as the 2016 study
// implemented it (paper section "Haber Model"; models/haber/README.md):
//  - a spherical grid centred on the viewer: n_phi azimuth sectors (only n_phi / 2 stored, the
//    sky being symmetric about the sun's vertical plane), rings of the same angular width from
//    the zenith to just below the horizon, shells from 10 m growing by
//    (1 + pi / n_phi) / (1 - pi / n_phi) out to where the top of the 35 km atmosphere is seen
//    at the horizon; cells whose centre is below the ground or above the top are dropped;
//  - single scattering of sunlight in every cell, Rayleigh with the isotropic phase function,
//    Mie kept apart for Cornette-Shanks;
//  - each further order gathers, at the cells of every `shell_stride`-th shell, the light
//    scattered by the previous order in the same cells of all other directions, then fills
//    the other shells by linear interpolation along the shells and rescales by the ratio of
//    the source power of all cells to that of the active ones; orders >= 2 are isotropic;
//  - the sky dome: radiance towards each (ring, sector) centre, the sum of the cells' light
//    along that direction attenuated to the viewer, read bilinearly between the centres.
// The grid depends only on the parameters (HaberGrid, built once per model); the dome depends
// on the sun zenith too (HaberDome, immutable, shared between queries).
#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "models/atmosphere/atmosphere_spectra.h"
#include "models/core/precompute_context.h"
#include "models/haber/haber_functions.h"

namespace clearsky::haber {

struct HaberSettings {
  int layer_count = 50;
  double top_height_m = 35e3;
  int azimuth_sectors = 72;   // n_phi, even; the angular step of rings and sectors is 2 pi / n_phi
  int shell_stride = 4;       // multiple scattering gathered on every shell_stride-th shell
  int scattering_orders = 4;  // 1: single scattering only
  double min_shell_radius_m = 10.0;
};

// The cells of one (ring, shell) pair; the same in every azimuth sector.
struct RingCell {
  int ring = 0;
  int shell = 0;
  double radius_m = 0;   // distance of the centre from the viewer
  double volume_m3 = 0;  // of each of its n_phi cells
  double radial_width_m = 0;
  int layer = 0;
  // For a shell that does not gather: the gathering ring cells below and above it on the
  // same ring (-1 when absent) and the weight of the upper one.
  int lower_active = -1;
  int upper_active = -1;
  double upper_weight = 0;
};

class HaberGrid {
 public:
  HaberGrid(const HaberSettings& settings, double earth_radius_m, double rayleigh_scale_height_m,
            double mie_scale_height_m);

  const HaberSettings& settings() const { return settings_; }
  const LayeredAtmosphere& layers() const { return layers_; }
  int ring_count() const { return ring_count_; }
  int shell_count() const { return shell_count_; }
  int stored_sectors() const { return settings_.azimuth_sectors / 2; }
  double angular_step_rad() const { return angular_step_rad_; }
  // Ring cells in ring order, shells increasing within a ring.
  const std::vector<RingCell>& ring_cells() const { return ring_cells_; }
  // Indices (into ring_cells()) of the gathering ring cells.
  const std::vector<int>& active() const { return active_; }
  // First ring cell of each ring, and one past the last (ring_count() + 1 entries).
  const std::vector<int>& ring_begin() const { return ring_begin_; }
  // Total number of cells (ring cells x stored sectors).
  std::size_t cell_count() const {
    return ring_cells_.size() * static_cast<std::size_t>(stored_sectors());
  }
  // Centre of a ring cell at azimuth phi from the sun's vertical plane.
  Vec3 centre(const RingCell& cell, double phi_rad) const;
  // Azimuth of the centre of sector j (any integer; sectors beyond n_phi / 2 are mirrors).
  double sector_azimuth_rad(int j) const { return (j + 0.5) * angular_step_rad_; }

 private:
  HaberSettings settings_;
  LayeredAtmosphere layers_;
  double angular_step_rad_;
  int ring_count_;
  int shell_count_;
  std::vector<RingCell> ring_cells_;
  std::vector<int> active_;
  std::vector<int> ring_begin_;
};

// The sky dome of one sun zenith: ring_count x stored_sectors spectra at the (ring, sector)
// centres, W/(m2.sr.nm). Immutable; thread-safe.
class HaberDome {
 public:
  HaberDome(int rings, int sectors, double angular_step_rad, std::size_t wavelengths,
            std::vector<double> radiance)
      : rings_(rings),
        sectors_(sectors),
        step_(angular_step_rad),
        wavelengths_(wavelengths),
        radiance_(std::move(radiance)) {}

  // Bilinear between the centres, clamped at the edges; view_sun_azimuth in [0, pi].
  void radiance(double view_zenith_rad, double view_sun_azimuth_rad, std::span<double> out) const;
  std::span<const double> node(int ring, int sector) const {
    return {radiance_.data() + (static_cast<std::size_t>(ring) * sectors_ + sector) * wavelengths_,
            wavelengths_};
  }
  int rings() const { return rings_; }
  int sectors() const { return sectors_; }
  double angular_step_rad() const { return step_; }
  std::size_t wavelengths() const { return wavelengths_; }
  // Every node's spectrum, ring-major then sector (what node() reads).
  std::span<const double> values() const { return radiance_; }
  std::size_t memory_bytes() const { return sizeof(*this) + radiance_.size() * sizeof(double); }

 private:
  int rings_;
  int sectors_;
  double step_;
  std::size_t wavelengths_;
  std::vector<double> radiance_;
};

// Runs the per-sun precomputation on all workers of `context` (cancellable, with progress).
std::shared_ptr<const HaberDome> build_dome(const HaberGrid& grid,
                                            const AtmosphereSpectra& atmosphere,
                                            double sun_zenith_rad,
                                            const PrecomputeContext& context);

}  // namespace clearsky::haber
