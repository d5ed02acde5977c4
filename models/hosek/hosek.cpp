// Hosek-Wilkie: descriptor, per-sun state (cooked distributions) and the model queries.
#include "models/hosek/hosek.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <typeinfo>

#include "models/atmosphere/atmosphere_parameter_table.h"
#include "models/core/fit_domain.h"
#include "models/core/quadrature.h"
#include "models/hosek/hosek_distributions.h"
#include "models/spectral/reference_spectra.h"

namespace clearsky {
namespace {

std::vector<double> band_wavelengths_nm() {
  std::vector<double> nm;
  for (int b = 0; b < hosek::kBandCount; ++b) nm.push_back(hosek::band_wavelength_nm(b));
  return nm;
}

ModelDescriptor make_descriptor() {
  return ModelDescriptor{
      .id = "hosek",
      .name = "Hosek-Wilkie 2012",
      .version = "1",
      .citation =
          "L. Hosek, A. Wilkie. An Analytic Model for Full Spectral Sky-Dome Radiance. "
          "ACM Transactions on Graphics 31(4) (SIGGRAPH 2012), article 95. Solar disc: L. "
          "Hosek, A. Wilkie. Adding a Solar-Radiance Function to the Hosek-Wilkie "
          "Skylight Model. IEEE Computer Graphics and Applications 33(3), 2013.",
      .summary =
          "Analytic sky radiance fitted to path-traced skies: a 9-coefficient distribution per "
          "band (11 bands, 320..720 nm every 40 nm), interpolated in turbidity, ground albedo and "
          "solar elevation. As in the 2016 study: turbidity 2.53, ground albedo of grass per "
          "wavelength, bands interpolated linearly at each grid wavelength and the result "
          "rescaled to the study's extraterrestrial spectrum (ratio to the fit's solar radiance "
          "times 6.87e-5 sr). Sun irradiance from the fit's solar disc radiance with limb "
          "darkening. Ground views only, sun above the horizon.",
      .native_wavelengths_nm = band_wavelengths_nm(),
      .min_wavelength_nm = hosek::kFirstBandNm,
      .max_wavelength_nm = hosek::kLastBandNm,
      .parameters =
          {
              atmosphere_parameter_spec("turbidity"),
              atmosphere_parameter_spec("albedo"),
              {.name = "native_bands",
               .description = "1: cook the 11 fitted bands once each (albedo at the band's "
                              "wavelength) and interpolate their radiances; 0: the study's one "
                              "state per grid wavelength",
               .default_value = 0.0,
               .min_value = 0.0,
               .max_value = 1.0,
               .integer = true},
              {.name = kClampNegativeFitOption,
               .description = "1: where the fit turns negative (the sun within a few degrees of "
                              "the horizon, views near the horizon) answer 0 there; 0: refuse "
                              "those samples (status outside_fit_domain)",
               .default_value = 0.0,
               .min_value = 0.0,
               .max_value = 1.0,
               .integer = true},
          },
      .capabilities =
          {
              .min_altitude_m = 0.0,
              .max_altitude_m = 0.0,
              .view_from_space = false,
              .view_below_horizon = false,
              .aerial_perspective = false,
              .max_sun_zenith_deg = 90.0,
              .scattering_orders = -1,
              .per_sun_precomputation = false,
              .sun_irradiance = true,
              .sky_irradiance = true,
          },
  };
}

// The cooked distributions of one sun position, stored coefficient by coefficient
// (hosek_distributions.h) so that the per-view loops vectorise; each distribution is evaluated
// once per view, then accumulated into the grid wavelengths.
class HosekSunState final : public SunState {
 public:
  explicit HosekSunState(const SunPosition& sun)
      : SunState(sun), sun_direction(sun.unit_vector()) {}
  std::size_t memory_bytes() const override {
    return sizeof(*this) + distributions.memory_bytes() + sums.capacity() * sizeof(WavelengthSum);
  }

  std::size_t size() const { return distributions.size(); }
  std::uint32_t add(const hosek::Coefficients& c) { return distributions.add(c); }

  // The distributions one wavelength adds (one band, or two with their weights): its radiance is
  // (0 + first_weight f[first]) + second_weight f[second], the order in which adding each band
  // to a zeroed spectrum sums them, kept in registers instead of stored and reloaded per band.
  struct WavelengthSum {
    std::uint32_t wavelength;
    std::uint32_t first, second;
    double first_weight, second_weight;
    bool two;
  };

  Vec3 sun_direction;  // once per sun, not per query
  hosek::Distributions distributions;
  std::vector<WavelengthSum> sums;
};

const HosekSunState& as_hosek_state(const SunState& sun) {
  // The class is final: the same dynamic type is the only match, and comparing type_info
  // costs a few instructions where dynamic_cast walks the hierarchy on every query.
  if (typeid(sun) != typeid(HosekSunState))
    throw std::invalid_argument("sun state was not prepared by the hosek model");
  return static_cast<const HosekSunState&>(sun);
}

double solar_elevation(const SunPosition& sun) { return std::max(0.5 * kPi - sun.zenith_rad, 0.0); }

}  // namespace

const ModelDescriptor& hosek_descriptor() {
  static const ModelDescriptor descriptor = make_descriptor();
  return descriptor;
}

ModelFactory hosek_factory() {
  return make_model_factory<&hosek_descriptor, &HosekModel::build, &no_precomputed_tables>();
}

std::shared_ptr<const HosekModel> HosekModel::create(const ModelConfig& config,
                                                     const PrecomputeContext& context) {
  return build(validated_config(hosek_descriptor(), config), context);
}

std::shared_ptr<const HosekModel> HosekModel::build(const ValidatedConfig& config,
                                                    const PrecomputeContext&) {
  return std::shared_ptr<const HosekModel>(new HosekModel(config));
}

HosekModel::HosekModel(const ValidatedConfig& validated) : SkyModel(validated.config()) {
  const ModelConfig& config = validated.config();
  native_bands_ = validated.option("native_bands") != 0.0;
  clamp_negative_fit_ = validated.option(kClampNegativeFitOption) != 0.0;
  const auto& tables = hosek::Tables::get();
  const auto& grass = ReferenceSpectra::get().grass_albedo;
  std::array<double, hosek::kBandCount> disc_solid_angle{};
  for (int b = 0; b < hosek::kBandCount; ++b) {
    const double nm = hosek::band_wavelength_nm(b);
    band_albedo_[b] = config.atmosphere.ground_albedo ? *config.atmosphere.ground_albedo
                                                      : grass.at(nm, OutOfRange::hold_end_values);
    disc_solid_angle[b] = hosek::limb_darkened_disc_solid_angle(b);
  }
  const WavelengthGrid& grid = wavelengths();
  terms_.resize(grid.size());
  for (std::size_t i = 0; i < grid.size(); ++i) {
    WavelengthTerms& w = terms_[i];
    if (!answers_wavelength(i)) continue;
    // The authors' band lookup: floor((lambda - 320) / 40), the remainder as the weight of
    // the next band; 720 nm is band 10 alone.
    const double x = std::clamp((grid[i] - hosek::kFirstBandNm) / hosek::kBandSpacingNm, 0.0,
                                static_cast<double>(hosek::kBandCount - 1));
    w.in_range = true;
    w.band = std::min(static_cast<int>(x), hosek::kBandCount - 1);
    w.fraction = x - w.band;
    if (w.band == hosek::kBandCount - 1) w.fraction = 0.0;
    const int next = std::min(w.band + 1, hosek::kBandCount - 1);
    w.albedo = atmosphere().ground_albedo[i];
    const double original = (1.0 - w.fraction) * tables.original_solar_radiance[w.band] +
                            w.fraction * tables.original_solar_radiance[next];
    const double disc =
        (1.0 - w.fraction) * disc_solid_angle[w.band] + w.fraction * disc_solid_angle[next];
    const double solar = atmosphere().solar_irradiance_w_m2_nm[i];
    w.sky_correction = solar / (original * hosek::kStudySunSolidAngleSr);
    w.disc_correction = solar / (original * disc);
  }
}

std::shared_ptr<const SunState> HosekModel::compute_sun_state(const SunPosition& sun,
                                                              const PrecomputeContext&) const {
  auto state = std::make_shared<HosekSunState>(sun);
  const auto& bands = hosek::Tables::get().spectral;
  const double elevation = solar_elevation(sun);
  const double t = turbidity();
  // Below this weight the authors' code uses the lower band alone.
  constexpr double kSingleBand = 1e-6;
  std::array<int, hosek::kBandCount> band_term;
  band_term.fill(-1);
  const auto add_term = [&](int band, double albedo) {
    const hosek::Configuration config = hosek::cook(bands[band], t, albedo, elevation);
    return std::pair{state->add(config.coefficients), config.radiance_scale};
  };
  std::array<double, hosek::kBandCount> band_scale{};
  auto& sums = state->sums;
  for (std::size_t i = 0; i < terms_.size(); ++i) {
    const WavelengthTerms& w = terms_[i];
    if (!w.in_range) continue;
    for (int k = 0; k < 2; ++k) {
      const int band = w.band + k;
      const double weight = k == 0 ? 1.0 - w.fraction : w.fraction;
      if (k == 1 && !(w.fraction >= kSingleBand)) break;
      std::uint32_t term = 0;
      double term_weight = 0.0;
      if (native_bands_) {
        if (band_term[band] < 0) {
          const auto [added, scale] = add_term(band, band_albedo_[band]);
          band_term[band] = static_cast<int>(added);
          band_scale[band] = scale;
        }
        term = static_cast<std::uint32_t>(band_term[band]);
        term_weight = weight * band_scale[band] * w.sky_correction;
      } else {
        const auto [added, scale] = add_term(band, w.albedo);
        term = added;
        term_weight = weight * scale * w.sky_correction;
      }
      if (k == 0) {
        sums.push_back({static_cast<std::uint32_t>(i), term, 0, term_weight, 0.0, false});
      } else {
        sums.back().second = term;
        sums.back().second_weight = term_weight;
        sums.back().two = true;
      }
    }
  }
  return state;
}

void HosekModel::compute_sky_radiance(const SunState& sun, const Viewpoint&,
                                      std::span<const ViewDirection> views,
                                      SpectralBatch& out) const {
  fit_radiance(sun, clamp_negative_fit_, views, out);
}

void HosekModel::radiance_to_integrate(const SunState& sun, const Viewpoint&,
                                       std::span<const ViewDirection> views,
                                       SpectralBatch& out) const {
  fit_radiance(sun, true, views, out);
}

void HosekModel::fit_radiance(const SunState& sun, bool clamp_negative,
                              std::span<const ViewDirection> views, SpectralBatch& out) const {
  const HosekSunState& state = as_hosek_state(sun);
  const Vec3& sun_direction = state.sun_direction;
  const std::size_t n = state.size();
  // hosek::distribution() over all distributions at once, in vector passes
  // (hosek_distributions.h), the exponentials included (fast_exp.h).
  std::vector<double> exponents(2 * n), f(n);
  for (std::size_t i = 0; i < views.size(); ++i) {
    const Vec3 d = views[i].unit_vector();
    const hosek::ViewTerms v = hosek::view_terms(d.z, dot(d, sun_direction));
    state.distributions.evaluate(v, exponents.data(), f.data());
    auto spectrum = out.spectrum(i);
    std::fill(spectrum.begin(), spectrum.end(), 0.0);
    for (const auto& sum : state.sums) {
      double value = 0.0 + sum.first_weight * f[sum.first];
      if (sum.two) value += sum.second_weight * f[sum.second];
      spectrum[sum.wavelength] = value;
    }
    // The fit dips below zero at the horizon when the sun is within a few degrees of it (its
    // constant term C is negative there and the zenith term sqrt(cos theta) vanishes).
    out.status[i] = apply_fit_domain(spectrum, clamp_negative);
  }
}

Spectrum HosekModel::sun_disc_radiance(const SunState& sun, const ViewDirection& view) const {
  Spectrum radiance(wavelengths().size(), 0.0);
  if (check_sun(sun.sun()) != SampleStatus::ok) return radiance;
  const double mu = hosek::solar_surface_cosine(safe_acos(cos_angle_between(view, sun.sun())));
  if (mu < 0.0) return radiance;
  const auto centres = hosek::solar_centre_radiances(turbidity(), 0.5 * kPi - view.zenith_rad);
  for (std::size_t i = 0; i < terms_.size(); ++i) {
    const WavelengthTerms& w = terms_[i];
    if (!w.in_range) continue;
    const int next = std::min(w.band + 1, hosek::kBandCount - 1);
    const double centre = (1.0 - w.fraction) * centres[w.band] + w.fraction * centres[next];
    const double darkening = (1.0 - w.fraction) * hosek::limb_darkening(w.band, mu) +
                             w.fraction * hosek::limb_darkening(next, mu);
    radiance[i] = centre * darkening * w.disc_correction;
  }
  return radiance;
}

Spectrum HosekModel::compute_sun_irradiance(const SunState& sun, const Viewpoint&) const {
  // The disc in polar coordinates about its centre: Gauss-Legendre in the solar-surface
  // cosine mu (d Omega = 2 pi S^2 mu / cos(gamma) d mu, S = sin(radius)) times the midpoint
  // rule in the position angle psi. Each point is seen at its own elevation, so that a disc
  // cut by the horizon (zero below it) or on a steep part of the fit is integrated faithfully.
  constexpr int kRadialNodes = 8;
  constexpr int kAngularNodes = 16;
  const double s = std::sin(hosek::kSolarRadiusRad);
  const double sun_elevation = 0.5 * kPi - sun.sun().zenith_rad;
  const double t = turbidity();
  struct Node {
    double weight;
    std::array<double, hosek::kBandCount> centre;
    std::array<double, hosek::kBandCount> darkening;
  };
  std::vector<Node> nodes;
  nodes.reserve(kRadialNodes * kAngularNodes);
  for (const auto& [mu, w_mu] : gauss_legendre(kRadialNodes, 0.0, 1.0)) {
    const double sin_gamma = s * std::sqrt(1.0 - mu * mu);
    const double cos_gamma = std::sqrt(1.0 - sin_gamma * sin_gamma);
    for (int j = 0; j < kAngularNodes; ++j) {
      const double psi = 2.0 * kPi * (j + 0.5) / kAngularNodes;
      const double sin_elevation =
          std::sin(sun_elevation) * cos_gamma + std::cos(sun_elevation) * sin_gamma * std::cos(psi);
      const double elevation = std::asin(std::clamp(sin_elevation, -1.0, 1.0));
      Node node;
      node.weight = w_mu * s * s * mu / cos_gamma * (2.0 * kPi / kAngularNodes);
      node.centre = hosek::solar_centre_radiances(t, elevation);
      for (int b = 0; b < hosek::kBandCount; ++b) node.darkening[b] = hosek::limb_darkening(b, mu);
      nodes.push_back(node);
    }
  }
  Spectrum irradiance(wavelengths().size(), 0.0);
  for (std::size_t i = 0; i < terms_.size(); ++i) {
    const WavelengthTerms& w = terms_[i];
    if (!w.in_range) continue;
    const int next = std::min(w.band + 1, hosek::kBandCount - 1);
    double sum = 0.0;
    for (const Node& node : nodes) {
      const double centre =
          (1.0 - w.fraction) * node.centre[w.band] + w.fraction * node.centre[next];
      const double darkening =
          (1.0 - w.fraction) * node.darkening[w.band] + w.fraction * node.darkening[next];
      sum += node.weight * centre * darkening;
    }
    irradiance[i] = sum * w.disc_correction;
  }
  return irradiance;
}

}  // namespace clearsky
