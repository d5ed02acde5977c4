// GET /v1/sun and GET /v1/skydome in the route table (route_handlers.h).
#include <memory>

#include "api/handlers/handlers.h"
#include "api/http/answer_memory_reservation.h"
#include "api/routes/route_handlers.h"
#include "api/skydome/skydome_render.h"

namespace clearsky::api {

// Without `time` the answer is the sun of the current instant: a new answer at every call,
// which no cache may keep (the route's caching is for answers with an explicit time).
ApiResponse get_sun_route(const ApiContext& context, const ApiRequest& request) {
  ApiResponse response = get_sun(context, request);
  bool timed = false;
  for (const auto& [name, value] : request.query) timed = timed || name == "time";
  if (!timed) response.headers.emplace_back("Cache-Control", "no-store");
  return response;
}

// The image is checked completely before the answer starts (errors are ordinary error
// answers); then its band's bytes are reserved, and it is computed band by band as the client
// reads it (api/skydome/).
ApiResponse get_skydome(const ApiContext& context, const ApiRequest& request) {
  auto job = std::make_shared<const SkydomeRender>(prepare_skydome(context, request));
  // The band's bytes, held until the answer ends or its connection is cut.
  auto reservation = reserve_answer_memory(context, job->band_bytes(), "the image",
                                           "ask for a smaller size or fewer wavelengths");
  ApiResponse response;
  response.content_type = job->content_type();
  response.model_id = job->model_id();
  job->add_quality_headers(response.headers);
  job->add_fit_headers(response.headers);
  response.headers.emplace_back("Content-Disposition",
                                std::string("inline; filename=\"") + job->file_name() + "\"");
  // The stream owns the reservation: it is released when the answer is destroyed, after the
  // last byte or when the connection was cut.
  response.stream = [job, reservation, warn = context.warn](const ByteSink& sink) {
    std::size_t unanswered = 0;
    const bool complete = job->write(sink, 0, &unanswered);
    if (unanswered > 0 && warn)
      warn("skydome " + job->model_id() + ": " + std::to_string(unanswered) +
           " pixels without a value, written as 0");
    return complete;
  };
  return response;
}

}  // namespace clearsky::api
