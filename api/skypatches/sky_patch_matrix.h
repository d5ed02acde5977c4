// A sky matrix (docs/building-energy.md "Sky matrices"): one sky vector (sky_patch_vector.h)
// per step of a time series, the matrix a daylight-coefficient calculation multiplies by its
// coefficients (Radiance's gendaymtx and dctimestep: one row per patch, one column per step).
// Each daytime step prepares the model's state for its sun once (SkyModel::prepare_sun, as GET
// /v1/irradiance/series does; the models' tables are built once for the whole matrix) and
// computes the vector on it; a night step (sun zenith >= 90 degrees: no twilight, as the
// irradiance series) is a column of zeros, flagged. The values are kept as floats (Radiance's
// own precision), patch-major, in the encoder's output (patch_value_encoder.h).
// Not thread-safe while computed; immutable after.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "api/request/time_steps.h"
#include "api/skypatches/patch_value_encoder.h"
#include "api/skypatches/sky_patch_vector.h"

namespace clearsky::api {

// The sun of a step when it is its own source (SunHandling::separate, sun up).
struct SkyMatrixSun {
  std::array<double, 3> direction{};  // Radiance's frame: x East, y North, z up
  std::vector<double> value;          // the encoder's output of its disk's radiance
};

struct SkyPatchMatrix {
  std::size_t patch_count = 0, steps = 0, components = 0;
  // (patch x steps + step) x components + component.
  std::vector<float> values;
  std::vector<bool> answered;                     // per step; false: the model refused, zeros
  std::vector<std::size_t> sun_patch;             // per step; 0 at night
  std::vector<std::optional<SkyMatrixSun>> suns;  // per step, SunHandling::separate only
  std::size_t unanswered_steps = 0;

  float at(std::size_t patch, std::size_t step, std::size_t component) const {
    return values[(patch * steps + step) * components + component];
  }
};

// Values in a matrix: steps x patches x components (413 naming step above it). A year of
// hourly Tregenza vectors in RGB is 3.85 million; a float each.
inline constexpr std::size_t kMaxSkyMatrixValues = 4000000;

SkyPatchMatrix compute_sky_patch_matrix(const SkyModel& model, const TimeSteps& times,
                                        const Viewpoint& viewpoint, const SkyPatchScheme& scheme,
                                        SunHandling handling, double ground_reflectance,
                                        PatchValueEncoder& encoder);

}  // namespace clearsky::api
