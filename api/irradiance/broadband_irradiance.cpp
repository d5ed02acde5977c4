// The broadband extension of a model's irradiance: api/irradiance/broadband_irradiance.h.
#include "api/irradiance/broadband_irradiance.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

#include "models/atmosphere/spctral2.h"
#include "models/core/numeric.h"
#include "models/spectral/reference_spectra.h"

namespace clearsky::api {

namespace {

constexpr double kStepNm = 1.0;

spctral2::Atmosphere spctral2_atmosphere(const BroadbandConditions& c) {
  const AtmosphereParameters& a = c.atmosphere;
  spctral2::Atmosphere s;
  s.pressure_ratio = std::exp(-c.altitude_m / a.rayleigh_scale_height_m);
  s.absorbers = {a.precipitable_water_cm, a.ozone_atm_cm};
  s.angstrom_alpha = a.angstrom_alpha;
  s.angstrom_beta = a.angstrom_beta * std::exp(-c.altitude_m / a.mie_scale_height_m);
  s.aerosol_single_scattering_albedo = a.mie_single_scattering_albedo;
  s.aerosol_asymmetry_g = a.mie_phase_g;
  // A constant albedo as given; the grass spectrum's near-infrared value (its last row, held
  // beyond it as the models hold it) otherwise, where most of the extension lies.
  const TabulatedSpectrum& grass = ReferenceSpectra::get().grass_albedo;
  s.ground_albedo = a.ground_albedo.value_or(grass.values().back());
  return s;
}

// Midpoint rule on about kStepNm steps over [lo, hi] of f(wavelength_nm).
template <class F>
double integral_nm(double lo_nm, double hi_nm, F f) {
  if (!(hi_nm > lo_nm)) return 0.0;
  const auto steps = static_cast<std::size_t>(std::ceil((hi_nm - lo_nm) / kStepNm));
  const double h = (hi_nm - lo_nm) / static_cast<double>(steps);
  double sum = 0.0;
  for (std::size_t k = 0; k < steps; ++k) sum += f(lo_nm + (static_cast<double>(k) + 0.5) * h);
  return sum * h;
}

// The mean of the absorbers' transmittance over the sample's interval (its point value for a
// point grid's end samples, whose interval may be empty).
double mean_absorption(const WavelengthGrid& grid, std::size_t i, const BroadbandConditions& c,
                       double pressure_ratio) {
  const spctral2::Absorbers absorbers{c.atmosphere.precipitable_water_cm,
                                      c.atmosphere.ozone_atm_cm};
  const auto t = [&](double nm) {
    return spctral2::absorption_transmittance(nm, absorbers, c.sun_zenith_rad, pressure_ratio);
  };
  const double lo = grid.lower_edge_nm(i), hi = grid.upper_edge_nm(i);
  if (!(hi > lo)) return t(grid[i]);
  return integral_nm(lo, hi, t) / (hi - lo);
}

}  // namespace

std::optional<std::string> broadband_unavailable_reason(const ModelDescriptor& descriptor) {
  const bool angstrom_aerosols =
      std::any_of(descriptor.parameters.begin(), descriptor.parameters.end(),
                  [](const ParameterSpec& p) { return p.atmosphere && p.name == "beta"; });
  if (angstrom_aerosols) return std::nullopt;
  return descriptor.id +
         " is a fit over the visible range whose atmosphere is a turbidity, not an extinction "
         "the 300..4000 nm extension can continue (docs/http-api.md \"Broadband "
         "irradiance\")";
}

BroadbandIntegrals broadband_integrals(const WavelengthGrid& grid,
                                       const std::vector<std::size_t>& indices,
                                       const BroadbandConditions& conditions) {
  const spctral2::Atmosphere atmosphere = spctral2_atmosphere(conditions);
  BroadbandIntegrals out;
  out.mean_absorption.reserve(indices.size());
  for (std::size_t i : indices)
    out.mean_absorption.push_back(mean_absorption(grid, i, conditions, atmosphere.pressure_ratio));
  // The model's answered range [lower edge of the first sample, upper edge of the last]: the
  // integrated_range_nm of the answer.
  const double lo_nm = grid.lower_edge_nm(indices.front());
  const double hi_nm = grid.upper_edge_nm(indices.back());
  const double zenith = conditions.sun_zenith_rad;
  const bool sun_up = zenith < 0.5 * kPi;
  // SPCTRAL2's direct normal and diffuse together, one evaluation per wavelength: each of the
  // two integrals is the midpoint sum it would be alone.
  const auto both = [&](double lo, double hi) {
    double direct = 0.0;
    const double diffuse = integral_nm(lo, hi, [&](double nm) {
      const spctral2::SpectralIrradiance e = spctral2::spectral_irradiance(nm, zenith, atmosphere);
      direct += e.direct_normal_w_m2_nm;
      return e.diffuse_horizontal_w_m2_nm;
    });
    const auto steps = hi > lo ? std::ceil((hi - lo) / kStepNm) : 1.0;
    return std::pair{direct * ((hi - lo) / steps), diffuse};
  };
  const auto spctral2_diffuse = [&](double nm) {
    return spctral2::spectral_irradiance(nm, zenith, atmosphere).diffuse_horizontal_w_m2_nm;
  };
  // SPCTRAL2's mean diffuse over one end sample's interval (its point value for a point grid's
  // end samples, whose interval may be empty).
  const auto mean_diffuse = [&](std::size_t i) {
    const double lo = grid.lower_edge_nm(i), hi = grid.upper_edge_nm(i);
    return hi > lo ? integral_nm(lo, hi, spctral2_diffuse) / (hi - lo) : spctral2_diffuse(grid[i]);
  };
  const auto [direct_below, diffuse_below] =
      both(kBroadbandMinNm, std::min(lo_nm, kBroadbandMaxNm));
  const auto [direct_above, diffuse_above] =
      both(std::max(hi_nm, kBroadbandMinNm), kBroadbandMaxNm);
  if (sun_up) {
    out.direct_below_w_m2 = direct_below;
    out.direct_above_w_m2 = direct_above;
  }
  if (lo_nm > kBroadbandMinNm) {
    out.diffuse_below_w_m2 = diffuse_below;
    out.diffuse_first_w_m2_nm = mean_diffuse(indices.front());
  }
  if (hi_nm < kBroadbandMaxNm) {
    out.diffuse_above_w_m2 = diffuse_above;
    out.diffuse_last_w_m2_nm = mean_diffuse(indices.back());
  }
  return out;
}

BroadbandExtension::BroadbandExtension(const WavelengthGrid& grid, std::vector<std::size_t> indices,
                                       const BroadbandConditions& conditions)
    : BroadbandExtension(grid, indices, conditions,
                         broadband_integrals(grid, indices, conditions)) {}

BroadbandExtension::BroadbandExtension(const WavelengthGrid& grid, std::vector<std::size_t> indices,
                                       const BroadbandConditions& conditions,
                                       BroadbandIntegrals integrals)
    : grid_(grid),
      indices_(std::move(indices)),
      conditions_(conditions),
      sun_up_(conditions.sun_zenith_rad < 0.5 * kPi),
      integrals_(std::move(integrals)) {}

double BroadbandExtension::absorbed_model_integral(const Spectrum& values) const {
  double sum = 0.0;
  for (std::size_t k = 0; k < indices_.size(); ++k) {
    const std::size_t i = indices_[k];
    sum += grid_.integration_weight_nm(i) * values[i] * integrals_.mean_absorption[k];
  }
  return sum;
}

double BroadbandExtension::direct_normal_w_m2(const Spectrum& direct_normal) const {
  if (!sun_up_) return 0.0;
  const double inside = absorbed_model_integral(direct_normal);
  return conditions_.earth_sun_distance_factor *
         (integrals_.direct_below_w_m2 + inside + integrals_.direct_above_w_m2);
}

// The scale of SPCTRAL2's diffuse to the model's at one end sample: the model's absorbed diffuse
// over the sample's interval over SPCTRAL2's over the same interval (0 when SPCTRAL2 has none
// there: a sun below the horizon, whose twilight the extension leaves out).
double BroadbandExtension::diffuse_scale(const Spectrum& diffuse, std::size_t position,
                                         double reference) const {
  const double model = diffuse[indices_[position]] * integrals_.mean_absorption[position];
  return reference > 0.0 ? model / reference : 0.0;
}

double BroadbandExtension::diffuse_w_m2(const Spectrum& diffuse) const {
  const double inside = absorbed_model_integral(diffuse);
  const BroadbandIntegrals& g = integrals_;
  const double below =
      g.diffuse_below_w_m2 > 0.0
          ? diffuse_scale(diffuse, 0, g.diffuse_first_w_m2_nm) * g.diffuse_below_w_m2
          : 0.0;
  const double above = g.diffuse_above_w_m2 > 0.0
                           ? diffuse_scale(diffuse, indices_.size() - 1, g.diffuse_last_w_m2_nm) *
                                 g.diffuse_above_w_m2
                           : 0.0;
  return conditions_.earth_sun_distance_factor * (below + inside + above);
}

double day_of_year_utc(double unix_time_utc_s) {
  using namespace std::chrono;
  const sys_seconds t{seconds{static_cast<long long>(std::floor(unix_time_utc_s))}};
  const sys_days day = floor<days>(t);
  const year_month_day ymd{day};
  const sys_days first = sys_days{ymd.year() / January / 1};
  const double seconds_into_day =
      unix_time_utc_s - static_cast<double>(duration_cast<seconds>(day.time_since_epoch()).count());
  return 1.0 + static_cast<double>((day - first).count()) + seconds_into_day / 86400.0;
}

}  // namespace clearsky::api
