// The irradiance of one sun on horizontal and tilted planes, the one computation behind
// GET /v1/irradiance and GET /v1/irradiance/series (docs/building-energy.md "Irradiance on
// planes"):
//  - direct_normal: the model's direct sun irradiance on a plane normal to the sun;
//  - direct = direct_normal x max(0, cos incidence), 0 with the sun below the horizon;
//  - sky_diffuse = the model's sky irradiance on the plane (its own, anisotropic radiance
//    over the part of the sky the plane sees);
//  - ground_diffuse = albedo x global horizontal x (1 - cos tilt) / 2: a Lambertian ground of
//    infinite extent, lit by the model's global horizontal irradiance, seen by the plane over
//    the view factor (1 - cos tilt) / 2 (pvlib's get_ground_diffuse; Duffie and Beckman,
//    Solar Engineering of Thermal Processes, section 2.16). The albedo is the request's
//    ground_albedo (a constant), otherwise the model's own ground albedo spectrum, the one its
//    lit ground uses (the atmosphere parameter albedo: the spectral albedo of grass by
//    default; docs/model-contract.md "The atmosphere parameter table");
//  - global = direct + sky_diffuse + ground_diffuse.
// Spectra are W/(m2.nm) on the model's grid; integrated() sums them over the answered grid
// and weighs them by the CIE photopic function. Thread-safe (const inputs only).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "api/colour/xyz_weights.h"
#include "api/irradiance/plane_sky_irradiance_table.h"
#include "models/core/sky_model.h"

namespace clearsky::api {

// How the ground's reflection enters the tilted planes.
struct GroundReflection {
  bool included = true;
  std::optional<double> albedo;  // ground_albedo; absent: the model's ground albedo spectrum
};

// The albedo spectrum the ground reflection uses, on the model's grid.
Spectrum ground_albedo_spectrum(const SkyModel& model, const GroundReflection& ground);

// The horizontal figures of one sun. direct_normal is zero unless asked (with_direct), the
// sky diffuse unless asked (with_sky); the global horizontal is their sum (cos zenith
// weighting the direct part).
struct HorizontalIrradiance {
  Spectrum direct_normal;
  Spectrum direct;                             // on the horizontal plane
  Spectrum diffuse;                            // the sky's, on the horizontal plane
  Spectrum global;                             // direct + diffuse
  bool with_direct = false, with_sky = false;  // which parts were asked
  double beam_factor = 0;                      // direct / direct_normal: max(0, cos zenith)
};

// The model's answers for one prepared sun, with a sample the model cannot answer turned into
// an ApiError naming `parameter` (altitude for a viewpoint it does not answer).
HorizontalIrradiance horizontal_irradiance(const SkyModel& model, const SunState& sun,
                                           const Viewpoint& viewpoint, bool with_direct,
                                           bool with_sky, const std::string& parameter);

struct PlaneIrradiance {
  Spectrum direct;
  Spectrum sky_diffuse;
  Spectrum ground_diffuse;
  Spectrum global;                             // direct + sky_diffuse + ground_diffuse
  bool with_sky = false, with_ground = false;  // which terms were computed
  // direct / direct_normal: max(0, cos incidence), 0 with the sun below the horizon.
  double beam_factor = 0;
};

// One plane at that sun. A horizontal plane (tilt 0) reuses the horizontal figures; others
// query the model's sky irradiance on the plane when with_sky, or interpolate it in `table`
// when one is given and covers the sun (long series: plane_sky_irradiance_table.h). The
// ground term needs the global horizontal (both parts of `horizontal`); it is zero when
// ground.included is false.
PlaneIrradiance plane_irradiance(const SkyModel& model, const SunState& sun,
                                 const Viewpoint& viewpoint, const PlaneOrientation& plane,
                                 const HorizontalIrradiance& horizontal, const Spectrum& albedo,
                                 const GroundReflection& ground, bool with_sky,
                                 const std::string& parameter,
                                 const PlaneSkyIrradianceTable* table = nullptr);

// A spectrum (W/(m2.nm) on grid) summed over the samples `indices` with the grid's integration
// weights: W/m2 over the answered range.
double model_range_w_m2(const Spectrum& e, const WavelengthGrid& grid,
                        const std::vector<std::size_t>& indices);

// A spectrum summed over the requested wavelengths (W/m2) and its illuminance (lx).
struct IntegratedIrradiance {
  double irradiance_w_m2 = 0;
  double illuminance_lx = 0;
};
IntegratedIrradiance integrated(const Spectrum& e, const SkyModel& model,
                                const std::vector<std::size_t>& indices, const XyzWeights& xyz);

}  // namespace clearsky::api
