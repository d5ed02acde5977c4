// Interpolation of a quantity measured on the 81 directions of the Kider et al. 2014 scan over the
// whole hemisphere, as the 2016 study did for its sun-azimuth estimate
// (models/evaluation/README.md): the 81 directions are the 9x9 nodes of the unit square mapped to
// the disk by the Shirley-Chiu concentric map, disk radius r -> zenith acos(1 - r^2). They lie on
// rings k = 0..4 at r = k / 4.5 (zenith 0, 18.08, 36.63, 56.25, 77.88 degrees), ring k holding 8k
// samples at clockwise azimuths m * 360 / (8k) degrees. A value in direction (zenith, azimuth)
// is a Catmull-Rom cubic, in u = 4.5 sqrt(1 - cos(zenith)), of the values of the four nearest
// rings at that azimuth, each itself a periodic Catmull-Rom cubic of its ring's samples. Ring
// -1 is the extrapolation that makes the function differentiable at the zenith (ring 1 minus
// twice the zenith slope estimated from ring 1), rings beyond 4 the extrapolations that keep
// the second difference constant, up to the horizon.
// Thread-safety: immutable after construction; operator() is const and thread-safe.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

#include "models/core/geometry.h"
#include "models/core/numeric.h"
#include "models/evaluation/measured_sky.h"

namespace clearsky {

constexpr int kConcentricRingCount = 5;       // rings 0 (zenith) .. 4 (lowest)
constexpr double kConcentricRingScale = 4.5;  // ring k at disk radius k / 4.5

// Zenith angle (radians) of ring k of the concentric layout.
inline double concentric_ring_zenith_rad(int ring) {
  const double r = ring / kConcentricRingScale;
  return safe_acos(1.0 - r * r);
}
inline std::size_t concentric_ring_size(int ring) {
  return ring == 0 ? 1 : 8 * static_cast<std::size_t>(ring);
}

// For each ring, the indices (into samples) of its samples by increasing clockwise azimuth.
// Throws std::invalid_argument when the samples are not the 81 directions of the layout
// (within 0.01 degree) or a direction is missing or repeated.
std::array<std::vector<std::size_t>, kConcentricRingCount> arrange_concentric_rings(
    std::span<const MeasuredSample> samples);

// Whether the samples are the 81 directions of the layout (arrange_concentric_rings accepts
// them).
bool is_concentric_layout(std::span<const MeasuredSample> samples);

// T: double or Spectrum (needs T + T, T - T, T * double).
template <typename T>
class ConcentricSkyInterpolant {
 public:
  // rings[k] holds the concentric_ring_size(k) values of ring k by increasing azimuth.
  explicit ConcentricSkyInterpolant(std::array<std::vector<T>, kConcentricRingCount> rings)
      : rings_(std::move(rings)) {
    for (int k = 0; k < kConcentricRingCount; ++k) {
      if (rings_[k].size() != concentric_ring_size(k))
        throw std::invalid_argument("concentric interpolant: ring " + std::to_string(k) +
                                    " needs " + std::to_string(concentric_ring_size(k)) +
                                    " values");
    }
  }

  // Value in a direction of the upper hemisphere (views below the horizon are evaluated at
  // the horizon).
  T operator()(const ViewDirection& view) const {
    const double cos_zenith = std::max(0.0, std::cos(view.zenith_rad));
    double u = kConcentricRingScale * safe_sqrt(1.0 - cos_zenith);
    const int ring = static_cast<int>(std::floor(u));
    u -= ring;
    return catmull_rom(u, ring_value(ring - 1, view.azimuth_rad),
                       ring_value(ring, view.azimuth_rad), ring_value(ring + 1, view.azimuth_rad),
                       ring_value(ring + 2, view.azimuth_rad));
  }

 private:
  // Catmull-Rom cubic through p0 (u = 0) and p1 (u = 1), with pm1 and p2 the outer neighbours.
  static T catmull_rom(double u, const T& pm1, const T& p0, const T& p1, const T& p2) {
    const T c1 = p1 - pm1;
    const T c2 = pm1 * 2.0 - p0 * 5.0 + p1 * 4.0 - p2;
    const T c3 = (p0 - p1) * 3.0 + p2 - pm1;
    return (p0 * 2.0 + (c1 + (c2 + c3 * u) * u) * u) * 0.5;
  }

  const T& sample(int ring, long m) const {
    const long n = static_cast<long>(concentric_ring_size(ring));
    return rings_[ring][static_cast<std::size_t>(((m % n) + n) % n)];
  }

  // Value of ring `ring` (any integer >= -1) at a clockwise azimuth.
  T ring_value(int ring, double azimuth_rad) const {
    if (ring == 0) return rings_[0][0];
    if (ring < 0) return ring_value(1, azimuth_rad) - zenith_slope(azimuth_rad) * 2.0;
    if (ring >= kConcentricRingCount) {
      return ring_value(ring - 3, azimuth_rad) - ring_value(ring - 2, azimuth_rad) * 3.0 +
             ring_value(ring - 1, azimuth_rad) * 3.0;
    }
    double u = azimuth_rad / (2.0 * kPi) * static_cast<double>(concentric_ring_size(ring));
    const double m = std::floor(u);
    u -= m;
    const long i = static_cast<long>(m);
    return catmull_rom(u, sample(ring, i - 1), sample(ring, i), sample(ring, i + 1),
                       sample(ring, i + 2));
  }

  // Change per ring step at the zenith in the direction of azimuth: the gradient estimated
  // from the 8 samples of ring 1, sum_m v_m (cos a_m, sin a_m) / (2 (1 + sqrt 2)), projected on
  // the azimuth. (Its sum over the ring weighs the axial and the diagonal samples as central
  // differences over two ring steps.)
  T zenith_slope(double azimuth_rad) const {
    const double scale = 0.5 / (1.0 + std::sqrt(2.0));
    T slope = rings_[1][0] * (scale * std::cos(azimuth_rad));
    for (std::size_t m = 1; m < 8; ++m) {
      const double a = static_cast<double>(m) * kPi / 4.0;
      slope = slope + rings_[1][m] * (scale * std::cos(a - azimuth_rad));
    }
    return slope;
  }

  std::array<std::vector<T>, kConcentricRingCount> rings_;
};

}  // namespace clearsky
