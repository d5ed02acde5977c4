// The RGB of the Radiance lighting simulation system (Ward 1994, "The RADIANCE Lighting
// Simulation and Rendering System", SIGGRAPH 94; Larson and Shakespeare 1998, "Rendering with
// Radiance"), the three components its sky vectors and daylight coefficients carry
// (docs/building-energy.md): primaries at CIE 1931 chromaticities R (0.640, 0.330),
// G (0.290, 0.600), B (0.150, 0.060) with the equal-energy white (1/3, 1/3), in radiometric
// W/(m2.sr) such that the luminance is 179 lm/W x (0.265 R + 0.670 G + 0.065 B) (Radiance's
// white efficacy). From a radiometric XYZ (models/colour/colour_spaces.h, luminance 683 Y):
// RGB = (683 / 179) M^-1 XYZ, M the matrix of the primaries scaled to the white.
// A colour outside the primaries' triangle has a negative component; it is clipped to 0 and
// flagged, as for sRGB (docs/http-api.md "RGB").
// Pure functions; thread-safe.
#pragma once

#include "models/colour/colour_spaces.h"

namespace clearsky::api {

inline constexpr double kRadianceWhiteEfficacy = 179.0;  // lm/W

struct RadianceRgb {
  double r = 0, g = 0, b = 0;
};

// Unclipped: components may be negative.
RadianceRgb xyz_to_radiance_rgb(const Xyz& xyz);
// 179 (R_y R + G_y G + B_y B): cd/m2 (the Y row of M, about 0.265, 0.670, 0.065).
double radiance_rgb_luminance(const RadianceRgb& rgb);

struct ClippedRadianceRgb {
  RadianceRgb rgb;
  bool clipped = false;  // a component was negative and is now 0
};
ClippedRadianceRgb clip_radiance_rgb(const RadianceRgb& rgb);

}  // namespace clearsky::api
