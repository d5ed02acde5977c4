// The atlas's geometry set (atlas_geometry.h).
#include "models/atlas/atlas_geometry.h"

#include <algorithm>

#include "models/core/numeric.h"

namespace clearsky::atlas {

AtlasGeometry atlas_geometry(const ModelCapabilities& caps, bool coarse) {
  AtlasGeometry g;
  const double max_sun = std::min(caps.max_sun_zenith_deg, kAtlasMaxSunZenithDeg);
  // Models that precompute per sun (seconds per sun for Haber) get 5 suns of the 8.
  const std::vector<double> suns =
      coarse ? std::vector<double>{10.3, 52.7, 84.1}
      : caps.per_sun_precomputation
          ? std::vector<double>{0.0, 40.7, 75.4, 89.3, kAtlasMaxSunZenithDeg}
          : std::vector<double>{0.0, 20.3, 40.7, 60.2, 75.4, 84.6, 89.3, kAtlasMaxSunZenithDeg};
  for (double s : suns)
    if (s <= max_sun) g.sun_zeniths_deg.push_back(s);
  const std::vector<double> altitudes =
      coarse ? std::vector<double>{0.0, 10000.0}
             : std::vector<double>{0.0, 2000.0, 10000.0, 30000.0, 100000.0};
  for (double a : altitudes)
    if (a >= caps.min_altitude_m && a <= caps.max_altitude_m) g.altitudes_m.push_back(a);
  if (g.altitudes_m.empty()) g.altitudes_m.push_back(caps.min_altitude_m);
  std::vector<double> zeniths =
      coarse ? std::vector<double>{0.0, 45.0, 85.0, 89.5}
             : std::vector<double>{0.0, 15.0, 30.0, 45.0, 60.0, 75.0, 82.0, 86.0, 88.5, 89.7};
  if (caps.view_below_horizon) {
    const std::vector<double> below =
        coarse ? std::vector<double>{120.0} : std::vector<double>{90.5, 95.0, 110.0, 150.0};
    zeniths.insert(zeniths.end(), below.begin(), below.end());
  }
  const std::vector<double> offsets =
      coarse ? std::vector<double>{0.0, 90.0, 180.0}
             : std::vector<double>{0.0, 10.0, 30.0, 60.0, 90.0, 135.0, 180.0};
  for (double z : zeniths) {
    if (z == 0.0) {
      g.views.push_back({0.0, degrees_to_radians(kAtlasSunAzimuthDeg)});
      continue;
    }
    for (double o : offsets)
      g.views.push_back({degrees_to_radians(z), degrees_to_radians(kAtlasSunAzimuthDeg + o)});
  }
  return g;
}

std::vector<ViewDirection> batch_views_81() {
  std::vector<ViewDirection> views;
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 9; ++j)
      views.push_back({degrees_to_radians(10.0 * i), degrees_to_radians(40.0 * j)});
  return views;
}

}  // namespace clearsky::atlas
