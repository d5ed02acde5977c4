// The one fixed geometry set over which the atlas compares a setting with its model's
// reference (docs/performance.md "Numerical error"): sun zeniths from 0 to the model's largest
// declared one (capped at 93.1 degrees: deeper in twilight the sky holds too little light for
// a relative error to mean anything), views across the whole sky and through the horizon
// (below it where the model answers such views), and observer altitudes from 0 to 100 km
// where the model answers them. The sun stands at azimuth 180 degrees; view azimuths are
// offsets from it. Sun zeniths are off the round numbers, so that sun buckets and table
// nodes are probed between their nodes.
#pragma once

#include <vector>

#include "models/core/sky_model.h"

namespace clearsky::atlas {

struct AtlasGeometry {
  std::vector<double> sun_zeniths_deg;
  std::vector<double> altitudes_m;
  std::vector<ViewDirection> views;  // azimuths relative to the sun's azimuth of 180 degrees
};

inline constexpr double kAtlasSunAzimuthDeg = 180.0;
inline constexpr double kAtlasMaxSunZenithDeg = 93.1;

// coarse: the quick atlas's set (3 suns, 2 altitudes, 13 to 16 views). The full set has 8 suns
// (5 for models that precompute per sun), 5 altitudes and 64 to 92 views.
AtlasGeometry atlas_geometry(const ModelCapabilities& capabilities, bool coarse);

// The 81 directions of a batch timing: 9 zeniths (0 to 80 degrees) by 9 azimuths.
std::vector<ViewDirection> batch_views_81();

}  // namespace clearsky::atlas
