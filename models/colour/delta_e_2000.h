// CIELAB (CIE 15:2004 section 8.2.1) and the CIEDE2000 colour difference (CIE 142-2001), as
// written out step by step by Sharma, Wu and Dalal 2005, "The CIEDE2000 Color-Difference
// Formula: Implementation Notes, Supplementary Test Data, and Mathematical Observations" (Color
// Research and Application 30(1)), equations (1) to (22), with their notes on the mean hue and
// the hue difference when a chroma is 0. Parametric factors kL = kC = kH = 1.
// Pure functions; thread-safe.
#pragma once

#include "models/colour/colour_spaces.h"

namespace clearsky {

struct Lab {
  double l = 0, a = 0, b = 0;
};

// CIELAB of xyz relative to the white white_xyz (both in the same units; white_xyz.y > 0).
Lab xyz_to_lab(const Xyz& xyz, const Xyz& white_xyz);

// Delta E 2000 between two CIELAB colours (symmetric, 0 for equal colours).
double delta_e_2000(const Lab& first, const Lab& second);

}  // namespace clearsky
