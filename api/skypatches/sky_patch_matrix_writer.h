// A sky matrix (sky_patch_matrix.h) as GET /v1/skypatches answers it with start
// (docs/building-energy.md "Sky matrices"), written in blocks to a sink:
//  - json: `head` (the request as understood), then "patches" (each patch's geometry, once),
//    "times" (per step, i.e. per column: time_utc, time_local with tz, night, the sun's zenith
//    and azimuth, sun_patch, sun_source with sun=separate: null at night), "matrix" (one row per
//    patch, one value per step: a number for luminance, an array otherwise) and, last,
//    unanswered_steps;
//  - csv: a header line (patch, altitude_deg, azimuth_deg, solid_angle_sr, then one column per
//    step and component, named by the step's UTC time and, for rgb or spectral, _R/_G/_B or
//    _<wavelength>nm), a line named night (1 for a night step, 0 otherwise), then one line per
//    patch from 0;
//  - radiance: Radiance's matrix format as gendaymtx writes it for dctimestep and rmtxop
//    (#?RADIANCE, NROWS = patches, NCOLS = steps, NCOMP = components, FORMAT=ascii, then each
//    row's values column by column).
// With sun=separate the matrix is the sky alone (gendaymtx -s); only json carries the suns.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "api/http/api_types.h"
#include "api/skypatches/sky_patch_matrix.h"

namespace clearsky::api {

struct SkyMatrixAnswer {
  const SkyPatchMatrix& matrix;
  const TimeSteps& times;
  const SkyPatchScheme& scheme;
  // Suffixes of the CSV columns of one step's components ("" for luminance; "_R", "_G", "_B";
  // "_450nm", ...).
  std::vector<std::string> component_suffixes;
};

// Each returns false when the sink refused data (the client left).
bool write_sky_matrix_json(const SkyMatrixAnswer& answer, nlohmann::json head,
                           const ByteSink& sink);
bool write_sky_matrix_csv(const SkyMatrixAnswer& answer, const ByteSink& sink);
bool write_sky_matrix_radiance(const SkyMatrixAnswer& answer, const ByteSink& sink);

}  // namespace clearsky::api
