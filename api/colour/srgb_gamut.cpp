// Clipping of negative linear sRGB components (api/colour/srgb_gamut.h).
#include "api/colour/srgb_gamut.h"

namespace clearsky::api {

GamutMappedSrgb clip_to_srgb_gamut(const LinearSrgb& colour) {
  GamutMappedSrgb out{colour, false};
  for (double* component : {&out.rgb.r, &out.rgb.g, &out.rgb.b}) {
    if (*component < 0.0) {
      *component = 0.0;
      out.clipped = true;
    } else if (*component == 0.0) {
      *component = 0.0;  // -0 is sent as 0, not "-0.0" (the same value, no clipping)
    }
  }
  return out;
}

}  // namespace clearsky::api
