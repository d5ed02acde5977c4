// The JSON answer of GET/POST /v1/radiance (api/handlers/radiance_handler.cpp), written straight
// into one string (json_text.h) with the bytes nlohmann::json's DOM gave: {"altitude_m",
// "bin_width_nm" (bin grids), "fit" (when one applied), "grid", "model", "model_version",
// quality members (quality.h), "samples": [{"radiance", "view_azimuth_deg", "view_zenith_deg"}],
// "sun", "unit", "wavelengths_nm"}, keys in the DOM's sorted order. The DOM took about 65% of
// the handler's instructions for one view on Preetham, 54% on Bruneton (callgrind;
// docs/performance.md "A radiance request through the server");
// tests/api/encode/radiance_json_test.cpp holds the two to the same bytes.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "api/request/quality.h"
#include "api/request/sky_fit.h"
#include "api/request/sky_request.h"
#include "api/request/views.h"

namespace clearsky::api {

struct RadianceAnswer {
  const ModelDescriptor& descriptor;
  const SunSpec& sun;
  const Viewpoint& viewpoint;
  const WavelengthGrid& grid;  // the model's
  // The answered wavelengths and their indices into grid (ModelOnGrid).
  const std::vector<double>& wavelengths_nm;
  const std::vector<std::size_t>& indices;
  const ViewList& views;
  const SpectralBatch& batch;  // one spectrum per view, on grid
  const RequestQuality& quality;
  QualityLevel served_quality;
  const std::optional<AppliedFit>& fit;
};

std::string radiance_json(const RadianceAnswer& answer);

}  // namespace clearsky::api
