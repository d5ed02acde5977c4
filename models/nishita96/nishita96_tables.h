// The per-sun precomputation of Nishita96 as the 2016 study implemented it (paper section
// "Nishita96 Model", "Our Implementation"; models/nishita96/README.md): for each of the
// 8 sampling directions s, a table of the single-scattered radiance arriving from s (sunlight
// scattered once along the ray towards s, plus the sunlit ground seen along it, Lambertian
// with the ground albedo), per unit solar irradiance, W/(m2.sr.nm) per W/(m2.nm).
//
// Each table is a box of nodes x nodes x nodes (33: the 32^3 voxels of the paper) over the
// whole sky dome: x, y in [-D, D] with D = sqrt(R_top^2 - R^2) = 875.7 km (the distance to the
// horizon of the top of the atmosphere), and the third axis z from the ground to the top
// (60 km), sheared along x so that it runs parallel to s: a node at (u, v, w) in [0, 1]^3 is at
// ((2u - 1) D + tan(a) h, (2v - 1) D, R + h) with h = w' (R_top - R) (w' = 1 - w when s points
// up, so that the axis runs against s); for the horizontal directions the axis is x itself
// and the heights run along u. Along that axis the radiance is computed incrementally, node
// to node (the integral from a node back to the end of the ray is the previous node's times
// the transmittance between them, plus the trapezoid over the step), starting from where the
// ray towards s leaves the atmosphere or meets the ground. Sun transmittances come from the
// Nishita93 optical-length tables.
//
// The sky is symmetric about the sun's vertical plane (y = 0): only y >= 0 is stored
// (17 of the 33 node rows), in single precision: 8 x 33 x 17 x 33 x 40 x 4 bytes = 23.7 MB
// on the paper's grid. Immutable; thread-safe.
#pragma once

#include <array>
#include <memory>
#include <span>
#include <vector>

#include "models/atmosphere/atmosphere_spectra.h"
#include "models/core/precompute_context.h"
#include "models/nishita93/nishita93_tables.h"
#include "models/nishita96/nishita96_functions.h"

namespace clearsky::nishita96 {

class SamplingTable {
 public:
  SamplingTable(double angle_rad, double earth_radius_m, double top_radius_m, int nodes,
                std::size_t wavelengths);

  double angle_rad() const { return angle_rad_; }
  int nodes() const { return nodes_; }
  // Position of node (i, j, k), each in [0, nodes - 1]; k runs along the table's axis.
  Vec3 node_position(int i, int j, int k) const;
  // Trilinear radiance arriving at p from the sampling direction (clamped to the box).
  void lookup(Vec3 p, std::span<float> out) const;
  // Stored spectrum of node (i, j, k), j >= nodes / 2 (the stored half).
  std::span<float> node(int i, int j, int k);
  std::span<const float> node(int i, int j, int k) const;
  std::size_t memory_bytes() const { return values_.size() * sizeof(float); }

 private:
  std::size_t index(int i, int jj, int k) const {
    return ((static_cast<std::size_t>(i) * stored_rows_ + jj) * nodes_ + k) * wavelengths_;
  }

  double angle_rad_;
  double earth_radius_m_;
  double top_radius_m_;
  double half_width_m_;  // D
  bool horizontal_;
  bool axis_against_height_;  // w' = 1 - w
  double tan_angle_;
  int nodes_;
  int stored_rows_;
  std::size_t wavelengths_;
  std::vector<float> values_;
};

// The 8 tables of one sun zenith. Immutable; thread-safe.
class SunTables {
 public:
  SunTables(double sun_zenith_rad, std::vector<SamplingTable> tables, int phase_theta_cells);
  double sun_zenith_rad() const { return sun_zenith_rad_; }
  const SamplingTable& table(int k) const { return tables_[static_cast<std::size_t>(k)]; }
  const std::array<Vec3, kSamplingDirections>& directions() const { return directions_; }
  // The phase-integration directions binned to the sampling directions of this sun.
  const PhaseBins& phase_bins() const { return phase_bins_; }
  std::size_t memory_bytes() const;

 private:
  double sun_zenith_rad_;
  std::vector<SamplingTable> tables_;
  std::array<Vec3, kSamplingDirections> directions_;
  PhaseBins phase_bins_;
};

// Builds the 8 tables on all workers of `context` (cancellable).
std::shared_ptr<const SunTables> build_sun_tables(const Nishita93Tables& optical_lengths,
                                                  const AtmosphereSpectra& atmosphere,
                                                  double sun_zenith_rad, int nodes,
                                                  int phase_theta_cells,
                                                  const PrecomputeContext& context);

}  // namespace clearsky::nishita96
