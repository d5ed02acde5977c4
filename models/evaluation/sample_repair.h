// Repair of samples known to be defective, as the 2016 study did for Kider's North sample
// (models/evaluation/README.md: sample 0 is replaced, before anything else, by the mean
// of its two ring neighbours, file azimuths 11.25 and 348.75; it stays one of the 81). It is an
// explicit, recorded step of an evaluation, never applied by a loader.
#pragma once

#include "models/evaluation/measured_sky.h"

namespace clearsky {

// Replaces the spectrum of every sample flagged kSampleKnownDefective and not yet repaired by
// the mean of its two nearest neighbours on the same ring (same zenith within 0.01 degree, one
// on each side in azimuth), sets kSampleRepaired and appends a line to processing_steps.
// Returns the number of samples repaired. Throws std::invalid_argument when a defective sample
// has no usable neighbours or the neighbours' wavelength tables differ.
int repair_defective_samples(MeasuredCapture& capture);

}  // namespace clearsky
