// GET /v1/irradiance/series: the request checked completely (api/irradiance/irradiance_series.h),
// then the rows computed and streamed (chunked) as the client reads them, a day of hourly rows
// at a time; nothing beyond one block of rows is held, so the answer takes nothing from the
// answer memory budget.
#include <memory>

#include "api/handlers/handlers.h"
#include "api/irradiance/irradiance_series.h"

namespace clearsky::api {

ApiResponse irradiance_series(const ApiContext& context, const ApiRequest& request) {
  auto series =
      std::make_shared<const IrradianceSeriesRequest>(parse_irradiance_series(context, request));
  ApiResponse response;
  response.content_type = series->csv ? "text/csv" : "application/json";
  response.model_id = series->grid.model->descriptor().id;
  add_quality_headers(response.headers, series->quality, series->grid.served_quality);
  add_fit_headers(response.headers, series->fit);
  // A CSV has no place for the reason of its empty broadband columns but a header
  // (docs/building-energy.md "Irradiance time series").
  if (series->csv && series->broadband_unavailable)
    response.headers.emplace_back("Clearsky-Broadband-Unavailable", *series->broadband_unavailable);
  response.stream = [series](const ByteSink& sink) {
    return write_irradiance_series(*series, sink);
  };
  return response;
}

}  // namespace clearsky::api
