// The gamut mapping of every linear sRGB value the service sends (GET/POST /v1/rgb, the RGB
// skydome). A colour outside the sRGB triangle (the saturated orange and red of a low sun) has
// a negative linear sRGB component; the service sends no negative value and clamps nothing
// without saying so: each negative component is clipped to 0 (the others are kept, so the
// colour moves to the nearest edge of the gamut along that axis only) and the answer reports it
// (docs/http-api.md "RGB"). Components above 1 are kept: the values are radiometric, not
// display-referred.
#pragma once

#include "models/colour/colour_spaces.h"

namespace clearsky::api {

struct GamutMappedSrgb {
  LinearSrgb rgb;
  bool clipped = false;  // a component was negative and is now 0
};

GamutMappedSrgb clip_to_srgb_gamut(const LinearSrgb& colour);

}  // namespace clearsky::api
