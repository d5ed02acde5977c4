// What a request that creates a resource answers: its body and the URL of the new resource,
// which the HTTP layer sends as the Location header (RFC 9110 section 10.2.2) of the 201 or 202.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace clearsky::api {

struct CreatedResource {
  nlohmann::ordered_json body;
  std::string location;  // absolute path, e.g. "/v1/jobs/3"
};

}  // namespace clearsky::api
