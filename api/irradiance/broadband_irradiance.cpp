// The broadband extension of a model's irradiance: api/irradiance/broadband_irradiance.h.
#include "api/irradiance/broadband_irradiance.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "models/atmosphere/spctral2.h"
#include "models/core/numeric.h"
#include "models/spectral/reference_spectra.h"

namespace clearsky::api {

namespace {

constexpr double kStepNm = 1.0;

// The model's answered range [lower edge of the first sample, upper edge of the last]: the
// integrated_range_nm of the answer.
struct Range {
  double lo_nm, hi_nm;
};

Range model_range(const ModelSpectrum& s) {
  return {s.grid.lower_edge_nm(s.indices.front()), s.grid.upper_edge_nm(s.indices.back())};
}

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

// Sum over the model's samples of weight x value x mean transmittance.
double absorbed_model_integral(const ModelSpectrum& s, const BroadbandConditions& c,
                               double pressure_ratio) {
  double sum = 0.0;
  for (std::size_t i : s.indices) {
    sum += s.grid.integration_weight_nm(i) * s.values[i] *
           mean_absorption(s.grid, i, c, pressure_ratio);
  }
  return sum;
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

double broadband_direct_normal_w_m2(const ModelSpectrum& direct_normal,
                                    const BroadbandConditions& c) {
  if (!(c.sun_zenith_rad < 0.5 * kPi)) return 0.0;
  const spctral2::Atmosphere atmosphere = spctral2_atmosphere(c);
  const Range r = model_range(direct_normal);
  const double inside = absorbed_model_integral(direct_normal, c, atmosphere.pressure_ratio);
  const auto spctral2_direct = [&](double nm) {
    return spctral2::spectral_irradiance(nm, c.sun_zenith_rad, atmosphere).direct_normal_w_m2_nm;
  };
  const double below =
      integral_nm(kBroadbandMinNm, std::min(r.lo_nm, kBroadbandMaxNm), spctral2_direct);
  const double above =
      integral_nm(std::max(r.hi_nm, kBroadbandMinNm), kBroadbandMaxNm, spctral2_direct);
  return c.earth_sun_distance_factor * (below + inside + above);
}

double broadband_diffuse_w_m2(const ModelSpectrum& diffuse, const BroadbandConditions& c) {
  const spctral2::Atmosphere atmosphere = spctral2_atmosphere(c);
  const Range r = model_range(diffuse);
  const double inside = absorbed_model_integral(diffuse, c, atmosphere.pressure_ratio);
  const auto spctral2_diffuse = [&](double nm) {
    return spctral2::spectral_irradiance(nm, c.sun_zenith_rad, atmosphere)
        .diffuse_horizontal_w_m2_nm;
  };
  // The scale of SPCTRAL2's diffuse to the model's at one end sample: the model's absorbed
  // diffuse over the sample's interval over SPCTRAL2's over the same interval (0 when
  // SPCTRAL2 has none there: a sun below the horizon, whose twilight the extension leaves out).
  const auto scale_at = [&](std::size_t i) {
    const double lo = diffuse.grid.lower_edge_nm(i), hi = diffuse.grid.upper_edge_nm(i);
    const double model =
        diffuse.values[i] * mean_absorption(diffuse.grid, i, c, atmosphere.pressure_ratio);
    const double reference = hi > lo ? integral_nm(lo, hi, spctral2_diffuse) / (hi - lo)
                                     : spctral2_diffuse(diffuse.grid[i]);
    return reference > 0.0 ? model / reference : 0.0;
  };
  const double below =
      r.lo_nm > kBroadbandMinNm
          ? scale_at(diffuse.indices.front()) *
                integral_nm(kBroadbandMinNm, std::min(r.lo_nm, kBroadbandMaxNm), spctral2_diffuse)
          : 0.0;
  const double above =
      r.hi_nm < kBroadbandMaxNm
          ? scale_at(diffuse.indices.back()) *
                integral_nm(std::max(r.hi_nm, kBroadbandMinNm), kBroadbandMaxNm, spctral2_diffuse)
          : 0.0;
  return c.earth_sun_distance_factor * (below + inside + above);
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
