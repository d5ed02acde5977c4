// The checks around every model query, and the default sky irradiance quadrature.
#include "models/core/sky_model.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "models/core/invalid_input.h"
#include "models/core/quadrature.h"
#include "models/core/sky_plane_quadrature.h"

namespace clearsky {
namespace {

bool answers_wavelength(const ModelDescriptor& d, double wavelength_nm) {
  return wavelength_nm >= d.min_wavelength_nm - 1e-9 && wavelength_nm <= d.max_wavelength_nm + 1e-9;
}

SampleStatus sun_status(const SunPosition& sun, const ModelDescriptor& d) {
  if (!(std::isfinite(sun.zenith_rad) && std::isfinite(sun.azimuth_rad)) || sun.zenith_rad < 0.0 ||
      sun.zenith_rad > kPi) {
    return SampleStatus::invalid_input;
  }
  if (sun.zenith_rad > degrees_to_radians(d.capabilities.max_sun_zenith_deg) + 1e-12) {
    return SampleStatus::sun_below_horizon_unsupported;
  }
  return SampleStatus::ok;
}

SampleStatus viewpoint_status(const Viewpoint& viewpoint, const ModelDescriptor& d) {
  if (!std::isfinite(viewpoint.altitude_m)) return SampleStatus::invalid_input;
  if (viewpoint.altitude_m < d.capabilities.min_altitude_m - 1e-9 ||
      viewpoint.altitude_m > d.capabilities.max_altitude_m + 1e-9) {
    return SampleStatus::viewpoint_unsupported;
  }
  return SampleStatus::ok;
}

// SkyModel::check_view with the descriptor's capability read once per batch.
SampleStatus view_status(const ViewDirection& view, bool view_below_horizon) {
  if (!(std::isfinite(view.zenith_rad) && std::isfinite(view.azimuth_rad)) ||
      view.zenith_rad < 0.0 || view.zenith_rad > kPi) {
    return SampleStatus::invalid_input;
  }
  if (view.zenith_rad > 0.5 * kPi + 1e-12 && !view_below_horizon) {
    return SampleStatus::view_below_horizon_unsupported;
  }
  return SampleStatus::ok;
}

}  // namespace

std::string ModelConfig::canonical_string() const {
  std::ostringstream out;
  out.precision(17);
  out << atmosphere.canonical_string() << ";grid=" << wavelengths.canonical_string();
  for (const auto& [name, value] : options) out << ';' << name << '=' << value;
  return out.str();
}

void SpectralBatch::resize(std::size_t samples, std::size_t wavelengths) {
  wavelength_count = wavelengths;
  values.assign(samples * wavelengths, 0.0);
  status.assign(samples, SampleStatus::ok);
}

SkyModel::SkyModel(ModelConfig config)
    : config_(std::move(config)),
      atmosphere_(AtmosphereSpectra::build(config_.atmosphere, config_.wavelengths)) {}

bool SkyModel::answers_wavelength(std::size_t i) const {
  return clearsky::answers_wavelength(descriptor(), config_.wavelengths[i]);
}

SampleStatus SkyModel::check_sun(const SunPosition& sun) const {
  return sun_status(sun, descriptor());
}

SampleStatus SkyModel::check_viewpoint(const Viewpoint& viewpoint) const {
  return viewpoint_status(viewpoint, descriptor());
}

SampleStatus SkyModel::check_view(const ViewDirection& view) const {
  return view_status(view, descriptor().capabilities.view_below_horizon);
}

bool SkyModel::sun_is_dark(const SunPosition& sun) const {
  const std::optional<double>& dark_beyond = descriptor().capabilities.dark_beyond_sun_zenith_deg;
  return dark_beyond.has_value() && sun.zenith_rad > degrees_to_radians(*dark_beyond);
}

std::shared_ptr<const SunState> SkyModel::prepare_sun(const SunPosition& sun,
                                                      const PrecomputeContext& context) const {
  const SampleStatus status = check_sun(sun);
  if (status != SampleStatus::ok) {
    throw InvalidInput("sun_zenith", std::string(describe(status)));
  }
  // The sky is exactly dark (ModelCapabilities::dark_beyond_sun_zenith_deg): nothing to build.
  if (context.dark_sun_at_once && sun_is_dark(sun)) {
    return std::make_shared<const SunState>(sun, true);
  }
  return compute_sun_state(sun, context);
}

std::shared_ptr<const SunState> SkyModel::compute_sun_state(const SunPosition& sun,
                                                            const PrecomputeContext&) const {
  return std::make_shared<const SunState>(sun);
}

namespace {

// Whether every value is finite and not negative (-0 counted as negative), from the bit
// patterns: a double with the sign bit clear is finite exactly when its bit pattern is below
// +infinity's, 0x7FF0...0, i.e. when adding 0x0010...0 leaves the sign bit clear. So the sign
// bit of bits | (bits + 0x0010...0) is set exactly for a negative (or -0), infinite or NaN
// value. Integer operations, which the compiler vectorises (floating comparisons under the
// default trapping math keep it from vectorising such a pass); on x86-64 an AVX2 clone (chosen
// once at load time) checks 4 values per instruction instead of 2, with the same answer.
#if defined(__x86_64__) && defined(__gnu_linux__)
__attribute__((target_clones("avx2", "default")))
#endif
bool is_usual_spectrum(std::span<const double> values) {
  std::uint64_t flags = 0;
  for (double v : values) {
    const auto bits = std::bit_cast<std::uint64_t>(v);
    flags |= bits | (bits + 0x0010000000000000u);
  }
  return (flags >> 63) == 0;
}

// Non-finite values are failures; negative values within rounding of zero are zeroed, others
// are failures (the model has a bug that must not reach a user as a number). Every sample of
// every query passes here (or, for a whole batch of usual spectra, is_usual_spectrum alone).
SampleStatus sanitize(std::span<double> values) {
  // The usual spectrum (every value finite and not negative, -0 excepted) in one integer pass.
  if (is_usual_spectrum(values)) return SampleStatus::ok;
  // Otherwise one pass for finite values with nothing negative (-0 included); the second only
  // when a value is negative.
  double largest = 0.0;
  bool finite = true, all_nonnegative = true;
  for (double v : values) {
    finite &= std::isfinite(v);
    all_nonnegative &= v >= 0.0;
    largest = std::max(largest, std::abs(v));
  }
  if (!finite) return SampleStatus::numerical_failure;
  if (all_nonnegative) return SampleStatus::ok;
  for (double& v : values) {
    if (v < 0.0) {
      if (v < -1e-9 * largest - 1e-300) return SampleStatus::numerical_failure;
      v = 0.0;
    }
  }
  return SampleStatus::ok;
}

using AnsweredRange = SkyModel::WavelengthRange;

// The wavelengths a model answers: a contiguous range [first, end) of the increasing grid,
// found with the descriptor read once (no allocation, no virtual call per wavelength).
AnsweredRange answered_range(const ModelDescriptor& d, const WavelengthGrid& grid) {
  AnsweredRange range{0, grid.size()};
  while (range.first < range.end && !answers_wavelength(d, grid[range.first])) ++range.first;
  while (range.end > range.first && !answers_wavelength(d, grid[range.end - 1])) --range.end;
  return range;
}

// Values outside the answered range are 0, whatever the model computed there.
void zero_outside(AnsweredRange range, std::span<double> values) {
  std::fill(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(range.first), 0.0);
  std::fill(values.begin() + static_cast<std::ptrdiff_t>(range.end), values.end(), 0.0);
}

void zero_out_of_range(const SkyModel& model, std::span<double> values) {
  zero_outside(model.answered_wavelengths(), values);
}

}  // namespace

SkyModel::WavelengthRange SkyModel::answered_wavelengths() const {
  return answered_range(descriptor(), wavelengths());
}

void SkyModel::sky_radiance(const SunState& sun, const Viewpoint& viewpoint,
                            std::span<const ViewDirection> views, SpectralBatch& out) const {
  const std::size_t n_wavelengths = wavelengths().size();
  out.resize(views.size(), n_wavelengths);
  // The descriptor once per call (a virtual call), not once per view and check.
  const ModelDescriptor& d = descriptor();
  SampleStatus common = sun_status(sun.sun(), d);
  if (common == SampleStatus::ok) common = viewpoint_status(viewpoint, d);
  std::size_t answerable_count = 0;
  if (common == SampleStatus::ok) {
    const bool below_horizon = d.capabilities.view_below_horizon;
    for (std::size_t i = 0; i < views.size(); ++i) {
      const SampleStatus s = view_status(views[i], below_horizon);
      out.status[i] = s;
      answerable_count += s == SampleStatus::ok ? 1 : 0;
    }
  } else {
    std::fill(out.status.begin(), out.status.end(), common);
  }
  // A dark sun: the answerable views keep their zeros, nothing is computed.
  if (answerable_count == 0 || sun.dark()) return;
  if (answerable_count == views.size()) {
    compute_sky_radiance(sun, viewpoint, views, out);
  } else {
    // Gather the answerable views so that the model computes only those, in one batch.
    std::vector<ViewDirection> answerable;
    std::vector<std::size_t> index;
    answerable.reserve(answerable_count);
    index.reserve(answerable_count);
    for (std::size_t i = 0; i < views.size(); ++i) {
      if (out.status[i] != SampleStatus::ok) continue;
      answerable.push_back(views[i]);
      index.push_back(i);
    }
    SpectralBatch partial;
    partial.resize(answerable.size(), n_wavelengths);
    compute_sky_radiance(sun, viewpoint, answerable, partial);
    for (std::size_t k = 0; k < index.size(); ++k) {
      std::copy(partial.spectrum(k).begin(), partial.spectrum(k).end(),
                out.spectrum(index[k]).begin());
      out.status[index[k]] = partial.status[k];
    }
  }
  // The wavelengths the model does not answer are 0 in every answered view.
  const AnsweredRange range = answered_range(d, wavelengths());
  if (range.first > 0 || range.end < n_wavelengths) {
    for (std::size_t i = 0; i < views.size(); ++i) {
      if (out.status[i] == SampleStatus::ok) zero_outside(range, out.spectrum(i));
    }
  }
  // The usual batch: every value of every view finite and not negative, found by one pass over
  // the whole batch (one call instead of one per view). Then sanitize() would leave every
  // spectrum as it is and answer ok; only the views the model itself refused (a fit domain)
  // are cleared.
  const bool usual = is_usual_spectrum(out.values);
  for (std::size_t i = 0; i < views.size(); ++i) {
    auto spectrum = out.spectrum(i);
    if (!usual && out.status[i] == SampleStatus::ok) out.status[i] = sanitize(spectrum);
    if (out.status[i] != SampleStatus::ok) std::fill(spectrum.begin(), spectrum.end(), 0.0);
  }
}

SpectralSample SkyModel::sun_irradiance(const SunState& sun, const Viewpoint& viewpoint) const {
  SpectralSample sample{Spectrum(wavelengths().size(), 0.0), check_viewpoint(viewpoint)};
  if (sample.status == SampleStatus::ok) sample.status = check_sun(sun.sun());
  if (sample.status != SampleStatus::ok) return sample;
  if (!descriptor().capabilities.sun_irradiance) {
    sample.status = SampleStatus::invalid_input;
    return sample;
  }
  if (sun.dark()) return sample;
  sample.value = compute_sun_irradiance(sun, viewpoint);
  zero_out_of_range(*this, {sample.value.data(), sample.value.size()});
  sample.status = sanitize({sample.value.data(), sample.value.size()});
  if (sample.status != SampleStatus::ok) sample.value = Spectrum(wavelengths().size(), 0.0);
  return sample;
}

SpectralSample SkyModel::sky_irradiance(const SunState& sun, const Viewpoint& viewpoint,
                                        const PlaneOrientation& plane) const {
  SpectralSample sample{Spectrum(wavelengths().size(), 0.0), check_viewpoint(viewpoint)};
  if (sample.status == SampleStatus::ok) sample.status = check_sun(sun.sun());
  if (!(std::isfinite(plane.tilt_rad) && std::isfinite(plane.azimuth_rad)) ||
      plane.tilt_rad < 0.0 || plane.tilt_rad > kPi) {
    sample.status = SampleStatus::invalid_input;
  }
  if (sample.status != SampleStatus::ok || sun.dark()) return sample;
  sample.value = compute_sky_irradiance(sun, viewpoint, plane);
  zero_out_of_range(*this, {sample.value.data(), sample.value.size()});
  sample.status = sanitize({sample.value.data(), sample.value.size()});
  if (sample.status != SampleStatus::ok) sample.value = Spectrum(wavelengths().size(), 0.0);
  return sample;
}

AerialPerspectiveSample SkyModel::aerial_perspective(const SunState& sun,
                                                     const Viewpoint& viewpoint,
                                                     const ViewDirection& view,
                                                     double distance_m) const {
  const std::size_t n = wavelengths().size();
  AerialPerspectiveSample sample{Spectrum(n, 0.0), Spectrum(n, 0.0), check_viewpoint(viewpoint)};
  if (sample.status == SampleStatus::ok) sample.status = check_sun(sun.sun());
  if (sample.status == SampleStatus::ok) sample.status = check_view(view);
  if (sample.status == SampleStatus::ok &&
      (!descriptor().capabilities.aerial_perspective || !(distance_m >= 0.0))) {
    sample.status = SampleStatus::invalid_input;
  }
  if (sample.status != SampleStatus::ok) return sample;
  ScatteringAlongRay result = compute_aerial_perspective(sun, viewpoint, view, distance_m);
  if (sun.dark()) std::fill(result.radiance.begin(), result.radiance.end(), 0.0);
  sample.radiance = std::move(result.radiance);
  sample.transmittance = std::move(result.transmittance);
  zero_out_of_range(*this, {sample.radiance.data(), n});
  zero_out_of_range(*this, {sample.transmittance.data(), n});
  sample.status = sanitize({sample.radiance.data(), n});
  if (sample.status == SampleStatus::ok) sample.status = sanitize({sample.transmittance.data(), n});
  if (sample.status != SampleStatus::ok) {
    sample.radiance = Spectrum(n, 0.0);
    sample.transmittance = Spectrum(n, 0.0);
  }
  return sample;
}

ScatteringAlongRay SkyModel::compute_aerial_perspective(const SunState&, const Viewpoint&,
                                                        const ViewDirection&, double) const {
  throw std::logic_error("model " + descriptor().id +
                         " declares aerial perspective but does not implement it");
}

Spectrum SkyModel::compute_sky_irradiance(const SunState& sun, const Viewpoint& viewpoint,
                                          const PlaneOrientation& plane) const {
  if (descriptor().capabilities.view_below_horizon)
    return sky_irradiance_by_quadrature(sun, viewpoint, plane);
  // Ground-view models: the sky a plane sees is a lune (sky_plane_quadrature.h). Horizontal:
  // 24 x 48 directions, within 0.01% of a 200 x 400 rule; tilted: 32 x 32, within 0.4% of a
  // fine rule up to a tilt of 150 degrees (measured on Preetham and Hosek, tests/models/*).
  const SkyRadianceBatch radiance = [&](std::span<const ViewDirection> views, SpectralBatch& out) {
    radiance_to_integrate(sun, viewpoint, views, out);
  };
  if (plane.tilt_rad < 1e-9)
    return sky_irradiance_on_plane(wavelengths().size(), radiance, plane, 24, 48);
  return sky_irradiance_on_plane(wavelengths().size(), radiance, plane, 32, 32);
}

void SkyModel::radiance_to_integrate(const SunState& sun, const Viewpoint& viewpoint,
                                     std::span<const ViewDirection> views,
                                     SpectralBatch& out) const {
  sky_radiance(sun, viewpoint, views, out);
}

Spectrum SkyModel::sky_irradiance_by_quadrature(const SunState& sun, const Viewpoint& viewpoint,
                                                const PlaneOrientation& plane, int zenith_nodes,
                                                int azimuth_nodes) const {
  // Directions on the plane's hemisphere: Gauss-Legendre in cos(theta') over (0, 1] times
  // the midpoint rule in azimuth (exact for trigonometric polynomials of degree <
  // azimuth_nodes), theta' measured from the plane normal. Each is rotated to the local sky
  // frame; directions the model does not answer (below the horizon for ground-only models)
  // contribute nothing, which is the sky-only irradiance.
  const Vec3 normal = SkyDirection{plane.tilt_rad, plane.azimuth_rad}.unit_vector();
  // An orthonormal frame (t, b, normal).
  const Vec3 helper = std::abs(normal.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{0, 1, 0};
  const Vec3 t = normalize(cross(helper, normal));
  const Vec3 b = cross(normal, t);
  const auto nodes = gauss_legendre(zenith_nodes, 0.0, 1.0);
  std::vector<ViewDirection> views;
  std::vector<double> weights;
  views.reserve(static_cast<std::size_t>(zenith_nodes * azimuth_nodes));
  for (const auto& [mu, w_mu] : nodes) {
    const double sin_theta = safe_sqrt(1.0 - mu * mu);
    for (int j = 0; j < azimuth_nodes; ++j) {
      const double phi = 2.0 * kPi * (j + 0.5) / azimuth_nodes;
      const Vec3 d =
          (sin_theta * std::cos(phi)) * t + (sin_theta * std::sin(phi)) * b + mu * normal;
      views.push_back(SkyDirection::from_unit_vector(d));
      weights.push_back(w_mu * mu * 2.0 * kPi / azimuth_nodes);
    }
  }
  SpectralBatch radiance;
  radiance.resize(views.size(), wavelengths().size());
  radiance_to_integrate(sun, viewpoint, views, radiance);
  Spectrum irradiance(wavelengths().size(), 0.0);
  for (std::size_t i = 0; i < views.size(); ++i) {
    if (radiance.status[i] != SampleStatus::ok) continue;
    const auto l = radiance.spectrum(i);
    for (std::size_t w = 0; w < irradiance.size(); ++w) irradiance[w] += weights[i] * l[w];
  }
  return irradiance;
}

}  // namespace clearsky
