// The OpenAPI description of GET /v1/evaluations/{id} (api/openapi/evaluations_operations.cpp) matches what
// the handler takes (api/evaluation/evaluations_api.h): every documented query parameter and
// value is accepted, a value outside the documented enum is refused, and the per-sample answer
// and its absence for older runs are described.
#include <gtest/gtest.h>

#include "api/error/api_error.h"
#include "api/evaluation/evaluations_api.h"
#include "api/openapi/openapi_document.h"

namespace clearsky::api {
namespace {

// Query parameters from (name, value) pairs.
Parameters query(const std::vector<std::pair<std::string, std::string>>& pairs) {
  Parameters p("GET /test");
  for (const auto& [name, value] : pairs) p.add(name, value);
  return p;
}

TEST(EvaluationOpenApi, ShowRunParametersAreThoseTheHandlerTakes) {
  const nlohmann::ordered_json& operation =
      openapi_document()["paths"]["/v1/evaluations/{id}"]["get"];
  std::vector<std::string> query_names;
  for (const auto& parameter : operation["parameters"]) {
    if (parameter["in"] != "query") continue;
    const std::string name = parameter["name"];
    query_names.push_back(name);
    if (parameter["schema"].contains("enum")) {
      for (const auto& value : parameter["schema"]["enum"])
        EXPECT_NO_THROW(parse_show_evaluation_options(query({{name, value.get<std::string>()}})))
            << name << "=" << value;
    } else {
      EXPECT_NO_THROW(parse_show_evaluation_options(query({{name, "x"}}))) << name;
    }
  }
  EXPECT_EQ(query_names, (std::vector<std::string>{"samples", "capture"}));
  EXPECT_THROW(parse_show_evaluation_options(query({{"samples", "all"}})), ApiError);
  EXPECT_THROW(parse_show_evaluation_options(query({{"errors", "true"}})), ApiError);

  const auto& samples = operation["parameters"][1];
  EXPECT_EQ(samples["schema"]["enum"], nlohmann::ordered_json::array({"false", "true", "spectra"}));
  const std::string description = samples["description"];
  for (const char* word : {"view_zenith", "bias", "errors", "wavelengths_nm", "null"})
    EXPECT_NE(description.find(word), std::string::npos) << word;
  EXPECT_TRUE(operation["responses"].contains("404"));
}

}  // namespace
}  // namespace clearsky::api
