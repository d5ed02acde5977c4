// The broadband irradiance of one sun on the horizontal and a plane
// (broadband_plane_irradiance.h).
#include "api/irradiance/broadband_plane_irradiance.h"

namespace clearsky::api {

BroadbandHorizontalIrradiance broadband_horizontal_irradiance(
    const BroadbandExtension& extension, const HorizontalIrradiance& horizontal) {
  BroadbandHorizontalIrradiance out;
  if (horizontal.with_direct)
    out.direct_normal_w_m2 = extension.direct_normal_w_m2(horizontal.direct_normal);
  if (horizontal.with_sky) out.diffuse_w_m2 = extension.diffuse_w_m2(horizontal.diffuse);
  if (out.direct_normal_w_m2 && out.diffuse_w_m2)
    out.global_w_m2 = *out.direct_normal_w_m2 * horizontal.beam_factor + *out.diffuse_w_m2;
  return out;
}

BroadbandPlaneIrradiance broadband_plane_irradiance(
    const BroadbandExtension& extension, const HorizontalIrradiance& horizontal,
    const BroadbandHorizontalIrradiance& broadband_horizontal, const PlaneIrradiance& plane) {
  BroadbandPlaneIrradiance out;
  if (broadband_horizontal.direct_normal_w_m2)
    out.direct_w_m2 = *broadband_horizontal.direct_normal_w_m2 * plane.beam_factor;
  if (plane.with_sky) out.sky_diffuse_w_m2 = extension.diffuse_w_m2(plane.sky_diffuse);
  if (plane.with_ground && broadband_horizontal.global_w_m2) {
    const WavelengthGrid& grid = extension.grid();
    const double global_horizontal = model_range_w_m2(horizontal.global, grid, extension.indices());
    const double ground = model_range_w_m2(plane.ground_diffuse, grid, extension.indices());
    out.ground_diffuse_w_m2 = global_horizontal > 0.0
                                  ? ground / global_horizontal * *broadband_horizontal.global_w_m2
                                  : 0.0;
  }
  if (out.direct_w_m2 && out.sky_diffuse_w_m2)
    out.global_w_m2 =
        *out.direct_w_m2 + *out.sky_diffuse_w_m2 + out.ground_diffuse_w_m2.value_or(0.0);
  return out;
}

}  // namespace clearsky::api
