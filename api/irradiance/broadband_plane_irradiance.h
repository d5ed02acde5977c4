// The broadband (300..4000 nm) irradiance of one sun on the horizontal and on a plane, from the
// model's spectra of plane_irradiance.h: the one broadband step behind GET /v1/irradiance and
// GET /v1/irradiance/series (docs/http-api.md "Broadband irradiance", docs/building-energy.md):
//  - direct_normal, horizontal diffuse and the plane's sky diffuse: the model's spectra
//    continued by the sun's BroadbandExtension (broadband_irradiance.h);
//  - direct = direct_normal x the plane's beam factor (max(0, cos incidence), 0 with the sun
//    below the horizon), global horizontal = direct_normal x max(0, cos zenith) + diffuse;
//  - ground_diffuse: the ground reflects the global horizontal, so its broadband figure is its
//    model-range share of the model-range global horizontal (the albedo and the view factor of
//    plane_irradiance.h, summed from the spectra plane_irradiance computed) applied to the
//    broadband global horizontal. Beyond the model's range the albedo is thus taken as its
//    range's mean.
// A figure is absent when the spectra it needs were not asked (HorizontalIrradiance::with_*,
// PlaneIrradiance::with_*). Pure functions, thread-safe.
#pragma once

#include <optional>

#include "api/irradiance/broadband_irradiance.h"
#include "api/irradiance/plane_irradiance.h"

namespace clearsky::api {

struct BroadbandHorizontalIrradiance {
  std::optional<double> direct_normal_w_m2;  // DNI
  std::optional<double> diffuse_w_m2;        // DHI, the sky's
  std::optional<double> global_w_m2;         // GHI: both parts asked
};

BroadbandHorizontalIrradiance broadband_horizontal_irradiance(
    const BroadbandExtension& extension, const HorizontalIrradiance& horizontal);

struct BroadbandPlaneIrradiance {
  std::optional<double> direct_w_m2;
  std::optional<double> sky_diffuse_w_m2;
  std::optional<double> ground_diffuse_w_m2;
  std::optional<double> global_w_m2;  // direct + sky_diffuse (+ ground_diffuse when computed)
};

// `broadband_horizontal` is broadband_horizontal_irradiance(extension, horizontal), computed
// once per sun and shared by its planes.
BroadbandPlaneIrradiance broadband_plane_irradiance(
    const BroadbandExtension& extension, const HorizontalIrradiance& horizontal,
    const BroadbandHorizontalIrradiance& broadband_horizontal, const PlaneIrradiance& plane);

}  // namespace clearsky::api
