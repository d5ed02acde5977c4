// GET /v1/irradiance/series (docs/building-energy.md "Irradiance time series"): the
// irradiance of one place from start to end every step, on the horizontal and on several
// planes, one row per step with pvlib's column names, as JSON or CSV, written as it is
// computed. The parameters:
//
// clang-format off
// | parameter                         | unit     | default  | range                   | meaning                                              |
// |-----------------------------------|----------|----------|-------------------------|------------------------------------------------------|
// | model and its parameters, quality |          |          | as GET /v1/irradiance   | the sky model and its table quality                  |
// | lat, lon, altitude, pressure, ... |          |          | api/request/place_time.h | the place (time is refused: start, end, step)       |
// | start, end, tz, step              |          |          | api/request/time_steps.h | the instants: start to end every step               |
// | planes                            | degree   | none     | tilt:azimuth,...        | planes besides the horizontal (api/irradiance/plane_list.h) |
// | ground_reflection, ground_albedo  |          |          | ground_reflection_request.h | the isotropic ground on the planes               |
// | precipitable_water_cm, ozone_atm_cm | cm, atm-cm | 1.42, 0.34 | broadband_request.h | the absorbers of the broadband columns           |
// | format                            |          | json     | json, csv               | the encoding                                         |
// clang-format on
//
// At most kMaxSeriesSteps rows (413 naming step). Models that prepare each sun
// (per_sun_precomputation: Haber, Nishita96) take at most kMaxPerSunDaySteps steps with the
// sun up (413 naming end). Night rows (apparent sun zenith >= 90 degrees) are zeros with
// night true. Everything is checked before the first byte; a step the model then cannot
// answer is written with null values (empty in CSV) and counted in unanswered_steps.
//
// ghi, dni, dhi and the planes' poa_* are broadband, 300..4000 nm (broadband_plane_irradiance.h,
// the computation of GET /v1/irradiance), for the models that can go broadband; the figures over
// the model's own range are the model_range_* columns. For a model that cannot
// (broadband_unavailable_reason), the broadband columns are null in every row and the answer
// says why (JSON: broadband_unavailable; CSV: the header Clearsky-Broadband-Unavailable).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "api/http/api_types.h"
#include "api/irradiance/plane_irradiance.h"
#include "api/irradiance/plane_list.h"
#include "api/request/place_time.h"
#include "api/request/quality.h"
#include "api/request/sky_fit.h"
#include "api/request/time_steps.h"

namespace clearsky::api {

struct IrradianceSeriesRequest {
  ModelOnGrid grid;
  RequestQuality quality;
  std::optional<AppliedFit> fit;  // the request's fit=, when given
  Viewpoint viewpoint;
  TimeSteps times;  // the instants and the sun of each
  std::vector<SeriesPlane> planes;
  GroundReflection ground;
  AtmosphereParameters absorbers;  // the request's precipitable water and ozone
  // Why the model cannot go broadband; nullopt when it can.
  std::optional<std::string> broadband_unavailable;
  bool csv = false;
  // The tilted planes' sky irradiance interpolated in tables (more daytime steps than a
  // table has nodes) rather than queried at each step.
  bool tabulated_sky = false;
  // The broadband integrals interpolated over the sun zenith (broadband_zenith_table.h), for
  // the same reason.
  bool tabulated_broadband = false;
  std::vector<std::string> columns() const;
};

IrradianceSeriesRequest parse_irradiance_series(const ApiContext& context,
                                                const ApiRequest& request);

// Writes the whole answer to sink; false when the sink refused data (the client left).
bool write_irradiance_series(const IrradianceSeriesRequest& series, const ByteSink& sink);

}  // namespace clearsky::api
