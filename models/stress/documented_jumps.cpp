// Documented jumps of the models (documented_jumps.h).
#include "models/stress/documented_jumps.h"

#include <cmath>

#include "models/core/numeric.h"
#include "models/nishita93/nishita93_tables.h"

namespace clearsky::stress {

std::vector<DocumentedJump> documented_jumps(const SkyModel& model, std::string_view coordinate,
                                             double altitude_m) {
  std::vector<DocumentedJump> out;
  const ModelCapabilities& caps = model.descriptor().capabilities;
  const double radius_m = model.config().atmosphere.earth_radius_m;
  const double horizon_deg =
      90.0 + radians_to_degrees(safe_acos(radius_m / (radius_m + std::max(altitude_m, 0.0))));
  if (coordinate == "view_zenith_deg" && caps.view_below_horizon)
    out.push_back({"ground_horizon", horizon_deg});
  if (coordinate == "sun_zenith_deg" && caps.max_sun_zenith_deg > 90.0)
    out.push_back({"sunset", horizon_deg});
  if (coordinate == "sun_zenith_deg" &&
      model.descriptor().find_parameter("sun_zenith_bucket_deg") != nullptr) {
    const double width_deg =
        option_or_default(model.descriptor(), model.config(), "sun_zenith_bucket_deg");
    if (width_deg > 0.0) {
      for (double edge = 0.5 * width_deg; edge < caps.max_sun_zenith_deg; edge += width_deg)
        out.push_back({"sun_zenith_bucket", edge});
    }
  }
  return out;
}

std::vector<DocumentedJump> documented_altitude_jumps(const SkyModel& model, double view_zenith_deg,
                                                      const std::string& chain) {
  std::vector<DocumentedJump> out;
  const AtmosphereParameters& a = model.config().atmosphere;
  const ModelDescriptor& d = model.descriptor();
  if (view_zenith_deg <= 90.0 && d.find_parameter("study_viewer_sample") != nullptr &&
      d.find_parameter("spheres") != nullptr &&
      option_or_default(d, model.config(), "study_viewer_sample") != 0.0) {
    const int spheres = static_cast<int>(option_or_default(d, model.config(), "spheres"));
    const std::vector<double> radii_m = Nishita93Tables::sphere_radii_m(a, spheres);
    for (std::size_t i = 1; i + 1 < radii_m.size(); ++i)
      out.push_back({"study_viewer_sample_sphere", radii_m[i] - a.earth_radius_m, chain});
  }
  if (!(view_zenith_deg > 90.0) || !d.capabilities.view_below_horizon) return out;
  const double sine = std::sin(degrees_to_radians(view_zenith_deg));
  if (sine > 0.0) {
    out.push_back({"ground_horizon", a.earth_radius_m / sine - a.earth_radius_m, chain});
    out.push_back({"atmosphere_limb", a.top_radius_m / sine - a.earth_radius_m, chain});
  }
  return out;
}

}  // namespace clearsky::stress
