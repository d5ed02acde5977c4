// Elek and Kmoch 2010, "Real-time spectral scattering in large-scale natural participating
// media" (SCCG 2010): the Bruneton 2008 method (models/bruneton) precomputed on 15 wavelengths
// and converted to RGB at the end of the precomputation. Bruneton 2016 ("Elek Model") runs it
// with the same implementation as Bruneton; on the paper's 40-wavelength grid both models are
// identical, and differ only by the native wavelengths used for the original RGB output.
//
// Native wavelengths: 15 samples from 360 nm every 24 nm (bins [360 + 24 i, 360 + 24 (i + 1))
// covering the study's 360..720 nm evaluation range), as the study's colour conversion for a
// model with 15 original wavelengths integrates the CIE functions with 15 uniform samples.
// Parameters, limits and thread-safety: those of BrunetonModel (models/bruneton/bruneton.h).
#pragma once

#include "models/bruneton/bruneton.h"
#include "models/colour/colour_spaces.h"

namespace clearsky {

const ModelDescriptor& elek_descriptor();
ModelFactory elek_factory();

// The 15 native wavelengths as a bin grid (360 nm, 24 nm wide).
WavelengthGrid elek_native_grid();
// The original RGB output: linear sRGB (cd/m2 scale, CIE 1931 with the bins' weights) of a
// radiance computed on elek_native_grid(). Because interpolation in the tables is linear,
// converting each looked-up spectrum equals converting the tables, as Elek does.
LinearSrgb elek_original_rgb(const Spectrum& radiance_on_native_grid);

}  // namespace clearsky
