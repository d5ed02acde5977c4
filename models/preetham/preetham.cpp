// Preetham: descriptor, per-sun state (Perez coefficients and zenith values) and queries.
#include "models/preetham/preetham.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <typeinfo>

#include "models/atmosphere/atmosphere_parameter_table.h"
#include "models/colour/colour_spaces.h"
#include "models/colour/daylight_spectrum.h"
#include "models/core/fast_exp.h"
#include "models/core/fit_domain.h"

namespace clearsky {
namespace {

ModelDescriptor make_descriptor() {
  return ModelDescriptor{
      .id = "preetham",
      .name = "Preetham 1999",
      .version = "2",
      .citation =
          "A. J. Preetham, P. Shirley, B. Smits. A Practical Analytic Model for Daylight. "
          "Proceedings of SIGGRAPH 1999, pages 91-100.",
      .summary =
          "Analytic sky luminance and chromaticity: Perez distributions fitted to Nishita96 "
          "skies, with zenith luminance and chromaticity as functions of turbidity and sun "
          "zenith; the spectrum is the CIE daylight basis S0 + M1 S1 + M2 S2 for the "
          "chromaticity, scaled to the luminance. As in the 2016 study: turbidity 2.53; the "
          "extraterrestrial spectrum, albedo and aerosol parameters are built into the fit and "
          "ignored. Ground views only, sun above the horizon.",
      .min_wavelength_nm = 360.0,  // the CIE daylight basis table
      .max_wavelength_nm = 830.0,
      .parameters =
          {
              // Below turbidity 2 the zenith luminance of a high sun turns negative.
              atmosphere_parameter_spec("turbidity", 2.0, 10.0),
              {.name = kClampNegativeFitOption,
               .description = "1: where the fitted spectrum turns negative (a low sun, views "
                              "near the horizon towards it) answer 0 there; 0: refuse those "
                              "samples (status outside_fit_domain)",
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

// One Perez distribution normalised by its value at the zenith: value(view) = scale x F(view).
struct ScaledPerez {
  preetham::PerezCoefficients p;
  double scale = 0;
};

class PreethamSunState final : public SunState {
 public:
  PreethamSunState(const SunPosition& sun, double turbidity)
      : SunState(sun), sun_direction(sun.unit_vector()) {
    const double zenith = sun.zenith_rad;
    const auto make = [&](const preetham::PerezCoefficients& p, double zenith_value) {
      return ScaledPerez{p, zenith_value / preetham::perez(p, 1.0, zenith)};
    };
    // kcd/m2 -> cd/m2.
    luminance = make(preetham::luminance_coefficients(turbidity),
                     1000.0 * preetham::zenith_luminance_kcd_m2(turbidity, zenith));
    chroma_x = make(preetham::chromaticity_x_coefficients(turbidity),
                    preetham::zenith_chromaticity_x(turbidity, zenith));
    chroma_y = make(preetham::chromaticity_y_coefficients(turbidity),
                    preetham::zenith_chromaticity_y(turbidity, zenith));
  }
  std::size_t memory_bytes() const override { return sizeof(*this); }

  Vec3 sun_direction;  // once per sun, not per query
  ScaledPerez luminance, chroma_x, chroma_y;
};

const PreethamSunState& as_preetham_state(const SunState& sun) {
  // The class is final: the same dynamic type is the only match, and comparing type_info
  // costs a few instructions where dynamic_cast walks the hierarchy on every query.
  if (typeid(sun) != typeid(PreethamSunState))
    throw std::invalid_argument("sun state was not prepared by the preetham model");
  return static_cast<const PreethamSunState&>(sun);
}

// F(theta, gamma) of the three distributions, split around their six exponentials so that
// a batch of views takes all of theirs in one vector pass (exp_in_place, within 2 ulp of
// std::exp: models/core/fast_exp.h) instead of six libm calls per view. The three share
// cos(theta), gamma and cos^2(gamma). No default initialisers: fit_radiance's chunk of 32 is
// written by perez_view before it is read, and would otherwise be zeroed on every query.
struct PerezView {
  double inverse_mu, gamma, cos2;
};
constexpr std::size_t kExponentsPerView = 6;

// The view's angles and its six exponents: B / cos(theta) and D gamma of each distribution.
PerezView perez_view(const PreethamSunState& s, double cos_theta, double cos_gamma,
                     double* exponents) {
  PerezView v;
  v.inverse_mu = 1.0 / std::max(cos_theta, 1e-9);
  v.gamma = std::acos(std::clamp(cos_gamma, -1.0, 1.0));
  v.cos2 = cos_gamma * cos_gamma;
  const ScaledPerez* distributions[] = {&s.luminance, &s.chroma_x, &s.chroma_y};
  for (const ScaledPerez* d : distributions) {
    *exponents++ = d->p.b * v.inverse_mu;
    *exponents++ = d->p.d * v.gamma;
  }
  return v;
}

// The three distributions from the view and its six exponentials, exp(B / cos(theta)) and
// exp(D gamma) of each in perez_view's order.
PreethamModel::LuminanceChromaticity perez_values(const PreethamSunState& s, const PerezView& v,
                                                  const double* exponentials) {
  const auto f = [&](const ScaledPerez& d, const double* e) {
    const auto& p = d.p;
    return d.scale * (1.0 + p.a * e[0]) * (1.0 + p.c * e[1] + p.e * v.cos2);
  };
  return {f(s.luminance, exponentials), f(s.chroma_x, exponentials + 2),
          f(s.chroma_y, exponentials + 4)};
}

PreethamModel::LuminanceChromaticity evaluate(const PreethamSunState& s, double cos_theta,
                                              double cos_gamma) {
  double e[kExponentsPerView];
  const PerezView v = perez_view(s, cos_theta, cos_gamma, e);
  exp_in_place(e, kExponentsPerView);
  return perez_values(s, v, e);
}

// l = k S0 + k1 S1 + k2 S2 over n wavelengths: three products and two sums per wavelength over
// contiguous arrays, which the compiler vectorises; on x86-64 an AVX2 clone (chosen once at
// load time) takes 4 wavelengths per instruction instead of 2. AVX2 without FMA: the clone
// rounds each product and sum as the baseline build does, so the spectra are the same bits.
// Returns whether every value is finite and not negative (-0 counted as negative), from the
// bits in the same pass: a double with the sign bit clear is finite exactly when adding
// 0x0010...0 to its bits leaves the sign bit clear (integer operations, which vectorise where
// the floating comparisons of apply_fit_domain(), under the default trapping math, do not).
// Then apply_fit_domain() would find nothing to do, and is not called.
#if defined(__x86_64__) && defined(__gnu_linux__)
__attribute__((target_clones("avx2", "default")))
#endif
bool combine_basis(std::size_t n, double k, double k1, double k2, const double* __restrict s0,
                   const double* __restrict s1, const double* __restrict s2,
                   double* __restrict l) {
  std::uint64_t flags = 0;
  for (std::size_t w = 0; w < n; ++w) {
    const double v = k * s0[w] + k1 * s1[w] + k2 * s2[w];
    l[w] = v;
    const auto bits = std::bit_cast<std::uint64_t>(v);
    flags |= bits | (bits + 0x0010000000000000u);
  }
  return (flags >> 63) == 0;
}

}  // namespace

const ModelDescriptor& preetham_descriptor() {
  static const ModelDescriptor descriptor = make_descriptor();
  return descriptor;
}

ModelFactory preetham_factory() {
  return make_model_factory<&preetham_descriptor, &PreethamModel::build, &no_precomputed_tables>();
}

std::shared_ptr<const PreethamModel> PreethamModel::create(const ModelConfig& config,
                                                           const PrecomputeContext& context) {
  return build(validated_config(preetham_descriptor(), config), context);
}

std::shared_ptr<const PreethamModel> PreethamModel::build(const ValidatedConfig& config,
                                                          const PrecomputeContext&) {
  // The descriptor's turbidity range [2, 10] is checked by validated_config.
  return std::shared_ptr<const PreethamModel>(new PreethamModel(config));
}

PreethamModel::PreethamModel(const ValidatedConfig& config)
    : SkyModel(config.config()),
      clamp_negative_fit_(config.option(kClampNegativeFitOption) != 0.0) {
  // The basis on the query grid, and its Y where the study integrates it: its 40 bins.
  const auto basis = [](const WavelengthGrid& grid) {
    const Spectrum s0 = daylight_relative_spectrum({0.0, 0.0}, grid);
    return std::array<Spectrum, 3>{s0, daylight_relative_spectrum({1.0, 0.0}, grid) - s0,
                                   daylight_relative_spectrum({0.0, 1.0}, grid) - s0};
  };
  const auto on_grid = basis(wavelengths());
  s0_ = on_grid[0];
  s1_ = on_grid[1];
  s2_ = on_grid[2];
  const WavelengthGrid bins = WavelengthGrid::paper_bins();
  const auto on_bins = basis(bins);
  y_s0_ = spectrum_to_xyz(on_bins[0], bins).y;
  y_s1_ = spectrum_to_xyz(on_bins[1], bins).y;
  y_s2_ = spectrum_to_xyz(on_bins[2], bins).y;
}

std::shared_ptr<const SunState> PreethamModel::compute_sun_state(const SunPosition& sun,
                                                                 const PrecomputeContext&) const {
  return std::make_shared<PreethamSunState>(sun, turbidity());
}

PreethamModel::LuminanceChromaticity PreethamModel::luminance_chromaticity(
    const SunState& sun, const ViewDirection& view) const {
  const PreethamSunState& state = as_preetham_state(sun);
  return evaluate(state, std::cos(view.zenith_rad), cos_angle_between(view, state.sun()));
}

void PreethamModel::fit_radiance(const SunState& sun, bool clamp_negative,
                                 std::span<const ViewDirection> views, SpectralBatch& out) const {
  const PreethamSunState& state = as_preetham_state(sun);
  const Vec3& sun_direction = state.sun_direction;
  const std::size_t n = s0_.size();
  const double* s0 = s0_.data();
  const double* s1 = s1_.data();
  const double* s2 = s2_.data();
  // Views in chunks: a chunk's exponentials in one exp_in_place pass (perez_view).
  constexpr std::size_t kChunk = 32;
  PerezView perez[kChunk];
  double exponentials[kChunk * kExponentsPerView];
  for (std::size_t begin = 0; begin < views.size(); begin += kChunk) {
    const std::size_t count = std::min(kChunk, views.size() - begin);
    for (std::size_t j = 0; j < count; ++j) {
      const Vec3 d = views[begin + j].unit_vector();
      perez[j] =
          perez_view(state, d.z, dot(d, sun_direction), exponentials + j * kExponentsPerView);
    }
    exp_in_place(exponentials, count * kExponentsPerView);
    for (std::size_t j = 0; j < count; ++j) {
      const std::size_t i = begin + j;
      const LuminanceChromaticity v =
          perez_values(state, perez[j], exponentials + j * kExponentsPerView);
      const preetham::BasisWeights m = preetham::daylight_basis_weights(v.chroma_x, v.chroma_y);
      // L = k (S0 + M1 S1 + M2 S2) with 683 k (Y_S0 + M1 Y_S1 + M2 Y_S2) = Y (cd/m2).
      const double k =
          v.luminance_cd_m2 / (kMaxLuminousEfficacy * (y_s0_ + m.m1 * y_s1_ + m.m2 * y_s2_));
      // The weights of the three basis spectra, once per view (combine_basis).
      const double k1 = k * m.m1, k2 = k * m.m2;
      auto spectrum = out.spectrum(i);
      // For a low sun, views near the horizon towards it get chromaticities far from the
      // daylight locus, where the basis combination turns negative at the short wavelengths
      // (fit_domain.h).
      out.status[i] = combine_basis(n, k, k1, k2, s0, s1, s2, spectrum.data())
                          ? SampleStatus::ok
                          : apply_fit_domain(spectrum, clamp_negative);
    }
  }
}

void PreethamModel::compute_sky_radiance(const SunState& sun, const Viewpoint&,
                                         std::span<const ViewDirection> views,
                                         SpectralBatch& out) const {
  fit_radiance(sun, clamp_negative_fit_, views, out);
}

void PreethamModel::radiance_to_integrate(const SunState& sun, const Viewpoint&,
                                          std::span<const ViewDirection> views,
                                          SpectralBatch& out) const {
  fit_radiance(sun, true, views, out);
}

Spectrum PreethamModel::compute_sun_irradiance(const SunState& sun, const Viewpoint&) const {
  Spectrum irradiance = atmosphere().solar_irradiance_w_m2_nm;
  for (std::size_t i = 0; i < irradiance.size(); ++i) {
    irradiance[i] *=
        preetham::sun_transmittance(turbidity(), sun.sun().zenith_rad, wavelengths()[i]);
  }
  return irradiance;
}

}  // namespace clearsky
