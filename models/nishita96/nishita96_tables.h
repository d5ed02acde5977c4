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
// Near-horizontal directions (the sun's and anti-sun's at a sun near the horizon, the sun's
// +-90 at a sun near the zenith or nadir) get a second layout, "grazing": tan(a) grows without
// bound there and the sheared box slides off the atmosphere the views cross (from about
// 82 degrees from the zenith its lower corner, from 86.1 degrees its top), so that lookups
// were clamped to its edge and the radiance oscillated as the sun set (docs/stability.md,
// "Dense sun sweeps of the per-sun models"). The grazing layout is the box rotated in the
// sun's vertical plane so that its third axis runs along the direction: it covers the whole
// region the views sample (x in [-D, D], z in [R, R_top]) at every angle, and at exactly
// 90 degrees its columns are those of the horizontal layout (4 times as many across). Directions more than
// kGrazingBlendEndDeg from the horizontal keep the sheared layout alone (bit-identical to the
// study's); below kGrazingBlendStartDeg the grazing layout alone is used; in between both are
// built and the lookups blended with a smoothstep weight, so that the radiance is continuous
// in the sun zenith. The two fixed horizontal directions keep the study's horizontal layout.
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

// Elevations of a sampling direction above or below the horizontal (degrees) between which the
// sheared and the grazing layouts are blended. At 8 degrees (82 from the zenith) the sheared
// box still covers the views' region, at 12 degrees the grazing one is no coarser across the
// rays than the sheared one by more than a sixth (its node spacing across the direction is
// (2 D sin e + T cos e) / 32 against 2 D sin e / 32).
inline constexpr double kGrazingBlendStartDeg = 8.0;
inline constexpr double kGrazingBlendEndDeg = 12.0;
// Nodes across the direction in the grazing layout: (nodes - 1) x this + 1. Its node lines tilt
// with the sun, so that a lookup point's place between them moves as the sun moves; with the
// radiance steep in height near the ground (scale heights of 8 and 1.2 km against a node
// spacing of about 3 km across a direction 1.5 degrees from the horizontal at 33 nodes) the
// trilinear interpolation error then ripples with the sun zenith: measured at 33 nodes across,
// up to 5% between suns 0.05 degree apart (period 0.45 degree); four times finer leaves steps
// of 1 to 2%, the physical fall (tests/models/nishita96/nishita96_grazing_sun_test.cpp).
inline constexpr int kGrazingAcrossRefinement = 4;

class SamplingTable {
 public:
  // fixed_horizontal: one of the two horizontal directions, which do not move with the sun and
  // keep the study's horizontal layout; a sun-dependent direction that happens to be exactly
  // horizontal (the sun at 90 degrees, its +-90 at 0 and 180) takes the grazing layout like
  // its neighbours, so that the tables are continuous in the sun zenith there too.
  SamplingTable(double angle_rad, double earth_radius_m, double top_radius_m, int nodes,
                std::size_t wavelengths, bool fixed_horizontal);

  double angle_rad() const { return angle_rad_; }
  int nodes() const { return nodes_; }
  std::size_t wavelengths() const { return wavelengths_; }
  int grazing_across_nodes() const { return (nodes_ - 1) * kGrazingAcrossRefinement + 1; }
  // Weight of the grazing layout in the lookups: 0 (sheared only), 1 (grazing only) or, in the
  // blend band, in between.
  double grazing_weight() const { return grazing_weight_; }
  bool has_sheared() const { return grazing_weight_ < 1.0; }
  bool has_grazing() const { return grazing_weight_ > 0.0; }
  // Position of node (i, j, k), each in [0, nodes - 1]; k runs along the table's axis.
  Vec3 node_position(int i, int j, int k) const;
  // The grazing layout's: i in [0, grazing_across_nodes() - 1].
  Vec3 grazing_node_position(int i, int j, int k) const;
  // Trilinear radiance arriving at p from the sampling direction (clamped to the box).
  void lookup(Vec3 p, std::span<float> out) const;
  // Stored spectrum of node (i, j, k), j >= nodes / 2 (the stored half).
  std::span<float> node(int i, int j, int k);
  std::span<const float> node(int i, int j, int k) const;
  std::span<float> grazing_node(int i, int j, int k);
  // Every stored value of each layout (empty for a layout the table does not have), in storage
  // order: what the disk form of a table set copies (nishita96_sun_tables_blob.h).
  std::span<float> sheared_values() { return values_; }
  std::span<const float> sheared_values() const { return values_; }
  std::span<float> grazing_values() { return grazing_values_; }
  std::span<const float> grazing_values() const { return grazing_values_; }
  std::size_t memory_bytes() const {
    return (values_.size() + grazing_values_.size()) * sizeof(float);
  }

 private:
  std::size_t index(int i, int jj, int k) const {
    return ((static_cast<std::size_t>(i) * stored_rows_ + jj) * nodes_ + k) * wavelengths_;
  }
  void lookup_sheared(Vec3 p, std::span<float> out) const;
  void lookup_grazing(Vec3 p, std::span<float> out) const;
  void interpolate(const std::vector<float>& values, int u_nodes, double u, double v, double w,
                   std::span<float> out) const;

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
  double grazing_weight_;
  // Grazing layout: node (i, j, k) at o_i n + y_j + t_k d, d = -s (the axis runs against s),
  // n the unit normal to d in the sun's vertical plane pointing up.
  Vec3 grazing_normal_{};
  Vec3 grazing_axis_{};
  double o_min_ = 0.0, o_max_ = 0.0, t_min_ = 0.0, t_max_ = 0.0;
  std::vector<float> values_;
  std::vector<float> grazing_values_;
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

// The 8 tables of a sun zenith, laid out with every value 0: what build_sun_tables fills, and
// what a table set read back from its disk form is checked against.
std::vector<SamplingTable> empty_sampling_tables(const AtmosphereSpectra& atmosphere,
                                                 double sun_zenith_rad, int nodes);

// Builds the 8 tables on all workers of `context` (cancellable).
std::shared_ptr<const SunTables> build_sun_tables(const Nishita93Tables& optical_lengths,
                                                  const AtmosphereSpectra& atmosphere,
                                                  double sun_zenith_rad, int nodes,
                                                  int phase_theta_cells,
                                                  const PrecomputeContext& context);

}  // namespace clearsky::nishita96
