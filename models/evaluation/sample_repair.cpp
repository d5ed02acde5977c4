// Repair of known-defective samples (sample_repair.h).
#include "models/evaluation/sample_repair.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "models/core/numeric.h"

namespace clearsky {
namespace {

// Clockwise azimuth difference from a to b in (0, 2 pi].
double clockwise_gap(double a_rad, double b_rad) {
  double d = std::fmod(b_rad - a_rad, 2.0 * kPi);
  if (d <= 0) d += 2.0 * kPi;
  return d;
}

bool is_usable_neighbour(const MeasuredSample& s) {
  return (s.quality_flags & kSampleKnownDefective) == 0 || (s.quality_flags & kSampleRepaired) != 0;
}

}  // namespace

int repair_defective_samples(MeasuredCapture& capture) {
  constexpr double kSameRing = 0.01 * kDegree;
  int repaired = 0;
  for (MeasuredSample& target : capture.samples) {
    if ((target.quality_flags & kSampleKnownDefective) == 0 || (target.quality_flags & kSampleRepaired) != 0)
      continue;
    const MeasuredSample* after = nullptr;   // nearest clockwise
    const MeasuredSample* before = nullptr;  // nearest counter-clockwise
    double after_gap = 0, before_gap = 0;
    for (const MeasuredSample& other : capture.samples) {
      if (&other == &target || !is_usable_neighbour(other)) continue;
      if (std::abs(other.view.zenith_rad - target.view.zenith_rad) > kSameRing) continue;
      const double cw = clockwise_gap(target.view.azimuth_rad, other.view.azimuth_rad);
      const double ccw = clockwise_gap(other.view.azimuth_rad, target.view.azimuth_rad);
      if (after == nullptr || cw < after_gap) after = &other, after_gap = cw;
      if (before == nullptr || ccw < before_gap) before = &other, before_gap = ccw;
    }
    if (after == nullptr || before == nullptr || after == before)
      throw std::invalid_argument("capture " + capture.label + ": defective sample " +
                                  std::to_string(target.index) + " has no two ring neighbours");
    const TabulatedSpectrum& a = after->radiance;
    const TabulatedSpectrum& b = before->radiance;
    if (a.wavelengths_nm() != b.wavelengths_nm())
      throw std::invalid_argument("capture " + capture.label + ": the ring neighbours of sample " +
                                  std::to_string(target.index) + " have different wavelengths");
    std::vector<double> mean(a.values().size());
    for (std::size_t i = 0; i < mean.size(); ++i) mean[i] = 0.5 * (a.values()[i] + b.values()[i]);
    target.radiance = TabulatedSpectrum(a.wavelengths_nm(), std::move(mean));
    target.quality_flags |= kSampleRepaired;
    char step[200];
    std::snprintf(step, sizeof step,
                  "sample %d (zenith %.4f deg, azimuth %.4f deg) replaced by the mean of its ring "
                  "neighbours %d and %d",
                  target.index, target.view.zenith_rad / kDegree, target.view.azimuth_rad / kDegree,
                  before->index, after->index);
    capture.processing_steps.emplace_back(step);
    ++repaired;
  }
  return repaired;
}

}  // namespace clearsky
