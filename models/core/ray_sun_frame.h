// RaySunGeometry::from (ray_scattering.h) for the views of one sun and observer, a batch: the
// sun's cosine and sine are evaluated once instead of three trigonometric calls per view, and
// the view's zenith cosine once instead of twice. The same expressions as
// RaySunGeometry::from and cos_angle_between(view, sun), so the same values
// (tests/models/core/ray_sun_frame_test.cpp).
#pragma once

#include <cmath>

#include "models/core/geometry.h"
#include "models/core/numeric.h"
#include "models/core/ray_scattering.h"

namespace clearsky {

class RaySunFrame {
 public:
  RaySunFrame(double bottom_radius_m, const Viewpoint& viewpoint, const SunPosition& sun)
      : r_m_(bottom_radius_m + viewpoint.altitude_m),
        mu_s_(clamp_cosine(std::cos(sun.zenith_rad))),
        cos_sun_(std::cos(sun.zenith_rad)),
        sin_sun_(std::sin(sun.zenith_rad)),
        sun_azimuth_rad_(sun.azimuth_rad) {}

  RaySunGeometry ray(const ViewDirection& view) const {
    const double cos_view = std::cos(view.zenith_rad);
    return {r_m_, clamp_cosine(cos_view), mu_s_,
            clamp_cosine(cos_view * cos_sun_ + std::sin(view.zenith_rad) * sin_sun_ *
                                                   std::cos(view.azimuth_rad - sun_azimuth_rad_))};
  }

 private:
  double r_m_, mu_s_, cos_sun_, sin_sun_, sun_azimuth_rad_;
};

}  // namespace clearsky
