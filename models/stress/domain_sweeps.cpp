// Sweep coordinates (domain_sweeps.h).
#include "models/stress/domain_sweeps.h"

#include <algorithm>
#include <cmath>

namespace clearsky::stress {

std::vector<double> steps_from_to(double first, double last, double step) {
  std::vector<double> out;
  const auto count = static_cast<std::size_t>(std::floor((last - first) / step + 1e-6));
  for (std::size_t i = 0; i <= count; ++i) out.push_back(first + static_cast<double>(i) * step);
  if (out.empty() || std::abs(out.back() - last) > 1e-9 * std::max(1.0, std::abs(last)))
    out.push_back(last);
  return out;
}

std::vector<double> thinned(const std::vector<double>& values, std::size_t max_points) {
  if (max_points == 0 || values.size() <= max_points) return values;
  if (max_points == 1) return {values.front()};
  std::vector<double> out;
  for (std::size_t i = 0; i < max_points; ++i) {
    const std::size_t index = static_cast<std::size_t>(
        std::llround(static_cast<double>(i) * static_cast<double>(values.size() - 1) /
                     static_cast<double>(max_points - 1)));
    if (out.empty() || values[index] != out.back()) out.push_back(values[index]);
  }
  return out;
}

std::vector<double> sun_zeniths_deg(double max_sun_zenith_deg) {
  return steps_from_to(0.0, max_sun_zenith_deg, kSunZenithStepDeg);
}

std::vector<double> sparse_sun_zeniths_deg(double max_sun_zenith_deg) {
  std::vector<double> out = steps_from_to(0.0, max_sun_zenith_deg, kSparseSunZenithStepDeg);
  for (double centre : {0.0, 90.0, max_sun_zenith_deg}) {
    const double from = std::max(0.0, centre - 1.0);
    const double to = std::min(max_sun_zenith_deg, centre + 1.0);
    if (from > to) continue;
    for (double z : steps_from_to(from, to, kSunZenithStepDeg)) out.push_back(z);
  }
  std::sort(out.begin(), out.end());
  // Values closer than rounding are one.
  out.erase(std::unique(out.begin(), out.end(),
                        [](double a, double b) { return std::abs(a - b) < 1e-9; }),
            out.end());
  return out;
}

std::vector<double> swept_sun_zeniths_deg(double max_sun_zenith_deg, bool per_sun_precomputation,
                                          bool dense_per_sun) {
  return per_sun_precomputation && !dense_per_sun ? sparse_sun_zeniths_deg(max_sun_zenith_deg)
                                                  : sun_zeniths_deg(max_sun_zenith_deg);
}

std::vector<double> view_zeniths_deg(double last_deg) {
  const double fine_from = 90.0 - kNearHorizonHalfWidthDeg;
  const double fine_to = 90.0 + kNearHorizonHalfWidthDeg;
  std::vector<double> out = steps_from_to(0.0, std::min(last_deg, fine_from), kViewZenithStepDeg);
  if (last_deg > fine_from) {
    std::vector<double> fine =
        steps_from_to(fine_from, std::min(last_deg, fine_to), kViewZenithNearHorizonStepDeg);
    out.insert(out.end(), fine.begin() + 1, fine.end());
  }
  if (last_deg > fine_to) {
    std::vector<double> coarse = steps_from_to(fine_to, last_deg, kViewZenithStepDeg);
    out.insert(out.end(), coarse.begin() + 1, coarse.end());
  }
  return out;
}

std::vector<double> azimuth_offsets_deg() {
  std::vector<double> out = steps_from_to(0.0, 360.0, kViewAzimuthStepDeg);
  out.pop_back();  // 360 is 0
  return out;
}

std::vector<double> altitudes_m(double max_altitude_m, double top_altitude_m) {
  std::vector<double> out = {0.0};
  const double highest = std::max(kAltitudeSweepTopM, max_altitude_m);
  for (double decade : steps_from_to(0.0, std::log10(highest), kAltitudeStepDecades))
    out.push_back(std::pow(10.0, decade));
  const double near_from = std::max(0.0, top_altitude_m - kNearTopHalfWidthM);
  const double near_to = std::min(highest, top_altitude_m + kNearTopHalfWidthM);
  if (near_from < near_to) {
    for (double h : steps_from_to(near_from, near_to, kNearTopStepM)) out.push_back(h);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

double parameter_sweep_top(const ParameterSpec& parameter, double base_value) {
  if (parameter.atmosphere || !parameter.integer || parameter.max_value <= 1.0)
    return parameter.max_value;
  return std::clamp(2.0 * base_value, parameter.min_value, parameter.max_value);
}

std::vector<double> parameter_values(const ParameterSpec& parameter, double highest,
                                     std::size_t count) {
  std::vector<double> out;
  count = std::max<std::size_t>(count, 2);
  for (std::size_t i = 0; i < count; ++i) {
    double v = parameter.min_value + (highest - parameter.min_value) * static_cast<double>(i) /
                                         static_cast<double>(count - 1);
    if (parameter.integer) v = std::round(v);
    v = std::clamp(v, parameter.min_value, highest);
    if (out.empty() || v != out.back()) out.push_back(v);
  }
  return out;
}

}  // namespace clearsky::stress
