// Names of the model states.
#include "api/service/model_provider.h"

namespace clearsky::api {

std::string_view to_string(ModelState::Status status) {
  switch (status) {
    case ModelState::Status::queued:
      return "queued";
    case ModelState::Status::precomputing:
      return "precomputing";
    case ModelState::Status::ready:
      return "ready";
    case ModelState::Status::failed:
      return "failed";
  }
  return "unknown";
}

}  // namespace clearsky::api
