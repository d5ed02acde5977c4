// The broadband (300..4000 nm) irradiance of GET /v1/irradiance from a model's spectral answer
// over its own range (docs/http-api.md "Broadband irradiance", docs/building-energy.md
// "Broadband irradiance and the pyranometer"). The models have no molecular absorption (the
// 2016 study's atmosphere) and answer a visible range; a building-energy user needs the
// whole solar spectrum, absorbed by water vapour, ozone and the mixed gases. The method:
//  - inside the model's range, the model's own direct normal and diffuse spectra, each bin
//    multiplied by the mean over the bin of the absorbers' transmittance T_o T_w T_u of Bird
//    and Riordan 1986 (models/atmosphere/spctral2.h) at the sun's air mass;
//  - outside it, direct normal: the SPCTRAL2 extraterrestrial spectrum through the model's
//    own extinction (Rayleigh optical depth of Bird and Riordan eq. 2-4 at the site's pressure
//    exp(-altitude / rayleigh_scale_height), aerosol optical depth beta lambda_um^-alpha
//    exp(-altitude / mie_scale_height)) and the same absorbers;
//  - outside it, diffuse: SPCTRAL2's diffuse horizontal spectrum with the model's aerosols,
//    scaled at each end so that it equals the model's absorbed diffuse over the model's first
//    (below) or last (above) bin: the spectral shape is SPCTRAL2's, the level and the plane's
//    share of the sky are the model's;
//  - the whole multiplied by the Earth-Sun distance factor of the date (Spencer 1971, Bird and
//    Riordan eq. 2-2) when the request gives a time, 1 (1 au, as the models) otherwise.
// Integrated by the midpoint rule on 1 nm steps outside the model's range and within each of
// its bins for the transmittances. Thread-safe.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "models/atmosphere/atmosphere_parameters.h"
#include "models/core/model_descriptor.h"
#include "models/spectral/spectrum.h"
#include "models/spectral/wavelength_grid.h"

namespace clearsky::api {

inline constexpr double kBroadbandMinNm = 300.0;
inline constexpr double kBroadbandMaxNm = 4000.0;

// Why a model's answer cannot be extended to 300..4000 nm, or nullopt when it can: the
// extension continues the model's own extinction, which it can only for the models whose
// aerosols are an Angstrom optical depth (they list the atmosphere parameter "beta").
std::optional<std::string> broadband_unavailable_reason(const ModelDescriptor& descriptor);

// Where, when and through what the model's answer was computed.
struct BroadbandConditions {
  double sun_zenith_rad = 0;
  double altitude_m = 0;
  AtmosphereParameters atmosphere;
  double earth_sun_distance_factor = 1.0;  // (1 au / r)^2
};

// What the extension integrates at one sun for a model's grid (W/m2 and W/(m2.nm) at 1 au), the
// samples `indices` (ascending and contiguous: the answer's integrated_range_nm): the absorbers'
// mean transmittance over each model bin, and SPCTRAL2's direct normal and diffuse on 1 nm steps
// outside the model's range (about 3,700 evaluations of SPCTRAL2, which gives both at once).
struct BroadbandIntegrals {
  std::vector<double> mean_absorption;  // per position in indices
  double direct_below_w_m2 = 0, direct_above_w_m2 = 0;
  double diffuse_below_w_m2 = 0, diffuse_above_w_m2 = 0;
  // SPCTRAL2's mean diffuse over the model's first and last samples.
  double diffuse_first_w_m2_nm = 0, diffuse_last_w_m2_nm = 0;
};

BroadbandIntegrals broadband_integrals(const WavelengthGrid& grid,
                                       const std::vector<std::size_t>& indices,
                                       const BroadbandConditions& conditions);

// The broadband extension at one sun: its integrals, done once (at construction, or
// interpolated in a BroadbandZenithTable for a long series), then each spectrum costs a sum
// over the model's bins, so the direct normal, the horizontal and every plane's diffuse of one
// sun share them (tests/bench/broadband_irradiance_bench.cpp). Immutable after construction;
// thread-safe. grid must outlive it.
class BroadbandExtension {
 public:
  BroadbandExtension(const WavelengthGrid& grid, std::vector<std::size_t> indices,
                     const BroadbandConditions& conditions);
  // With the integrals given (those of conditions' sun, or interpolated to it).
  BroadbandExtension(const WavelengthGrid& grid, std::vector<std::size_t> indices,
                     const BroadbandConditions& conditions, BroadbandIntegrals integrals);

  // The broadband direct normal irradiance (W/m2) of the model's direct normal spectrum
  // (W/(m2.nm) on the grid); 0 with the sun at or below the horizon.
  double direct_normal_w_m2(const Spectrum& direct_normal) const;
  // The broadband diffuse irradiance (W/m2) on the plane the model's diffuse spectrum is for.
  double diffuse_w_m2(const Spectrum& diffuse) const;

  const BroadbandConditions& conditions() const { return conditions_; }
  const WavelengthGrid& grid() const { return grid_; }
  const std::vector<std::size_t>& indices() const { return indices_; }

 private:
  // Sum over the model's samples of weight x value x mean transmittance.
  double absorbed_model_integral(const Spectrum& values) const;
  // SPCTRAL2's diffuse scaled to the model's absorbed diffuse over one end sample.
  double diffuse_scale(const Spectrum& diffuse, std::size_t position, double reference) const;

  const WavelengthGrid& grid_;
  std::vector<std::size_t> indices_;
  BroadbandConditions conditions_;
  bool sun_up_ = false;
  BroadbandIntegrals integrals_;
};

// Day of the year (1 on 1 January, fractional) of a UTC instant, for the Earth-Sun distance.
double day_of_year_utc(double unix_time_utc_s);

}  // namespace clearsky::api
