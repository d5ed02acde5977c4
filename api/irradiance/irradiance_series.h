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
// | start, end                        | ISO 8601 | required | end >= start            | first and last instant (inclusive); an offset or Z, or local in tz |
// | tz                                | IANA     | none     | a zone name             | local times of start/end and the time_local column   |
// | step                              | ISO 8601 | PT1H     | > 0                     | duration between rows (PT10M, PT1H, P1D)             |
// | planes                            | degree   | none     | tilt:azimuth,...        | planes besides the horizontal (api/irradiance/plane_list.h) |
// | ground_reflection, ground_albedo  |          |          | ground_reflection_request.h | the isotropic ground on the planes               |
// | format                            |          | json     | json, csv               | the encoding                                         |
// clang-format on
//
// At most kMaxSeriesSteps rows (413 naming step). Models that prepare each sun
// (per_sun_precomputation: Haber, Nishita96) take at most kMaxPerSunDaySteps steps with the
// sun up (413 naming end). Night rows (apparent sun zenith >= 90 degrees) are zeros with
// night true. Everything is checked before the first byte; a step the model then cannot
// answer is written with null values (empty in CSV) and counted in unanswered_steps.
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

namespace clearsky::api {

// A leap year at 10-minute steps.
inline constexpr std::size_t kMaxSeriesSteps = 8784 * 6;
inline constexpr std::size_t kMaxPerSunDaySteps = 96;

struct IrradianceSeriesRequest {
  ModelOnGrid grid;
  RequestQuality quality;
  std::optional<AppliedFit> fit;  // the request's fit=, when given
  Viewpoint viewpoint;
  SolarPositionInput position;  // the place; unix_time_utc_s set per step
  bool delta_t_from_time = false;
  double start_unix_s = 0;
  long long step_s = 3600;
  std::string step_text = "PT1H";
  std::size_t steps = 0;
  std::optional<std::string> tz;
  std::vector<SeriesPlane> planes;
  GroundReflection ground;
  bool csv = false;
  // The tilted planes' sky irradiance interpolated in tables (more daytime steps than a
  // table has nodes) rather than queried at each step.
  bool tabulated_sky = false;
  // The apparent sun of each step, degrees.
  std::vector<double> zenith_deg, azimuth_deg;

  std::vector<std::string> columns() const;
};

IrradianceSeriesRequest parse_irradiance_series(const ApiContext& context,
                                                const ApiRequest& request);

// Writes the whole answer to sink; false when the sink refused data (the client left).
bool write_irradiance_series(const IrradianceSeriesRequest& series, const ByteSink& sink);

}  // namespace clearsky::api
