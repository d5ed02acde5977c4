// The HTTP contract of fitted models outside their domain (models/core/fit_domain.h): a view
// where Preetham's fitted spectrum turns negative is answered 422 naming the view and the
// option, never a silent 0; the option clamp_negative_fit=1 answers it, with 0 at the negative
// wavelengths.
#include <gtest/gtest.h>

#include <algorithm>

#include "api/handlers/handlers.h"
#include "models/preetham/preetham.h"
#include "tests/support/synchronous_provider.h"

namespace clearsky::api {
namespace {

ApiResponse get_radiance(const clearsky::testing::SynchronousProvider& provider,
                         std::vector<std::pair<std::string, std::string>> query) {
  const Limits limits{100, 500, 1024};
  const ApiContext context{provider, limits};
  try {
    return radiance(context, ApiRequest{"GET", "/v1/radiance", std::move(query), ""});
  } catch (const ApiError& e) {
    return error_response(e);
  }
}

TEST(FitDomain, PreethamOutsideItsFitIsRefusedUnlessClampingIsAsked) {
  const clearsky::testing::SynchronousProvider provider({preetham_factory()});
  // Turbidity 10, the sun at the zenith: the fit's chromaticity 80 degrees from the zenith is far
  // from the daylight locus (models/preetham/README.md).
  std::vector<std::pair<std::string, std::string>> query = {
      {"model", "preetham"},        {"sun_zenith", "0"},   {"sun_azimuth", "0"},
      {"view_zenith", "80"},        {"view_azimuth", "0"}, {"turbidity", "10"},
      {"wavelengths", "360:720:10"}};
  const ApiResponse refused = get_radiance(provider, query);
  ASSERT_EQ(refused.status, 422) << refused.body;
  const auto error = nlohmann::json::parse(refused.body)["error"];
  EXPECT_EQ(error["parameter"], "view_zenith");
  EXPECT_NE(error["message"].get<std::string>().find("clamp_negative_fit"), std::string::npos)
      << refused.body;

  query.emplace_back("clamp_negative_fit", "1");
  const ApiResponse clamped = get_radiance(provider, query);
  ASSERT_EQ(clamped.status, 200) << clamped.body;
  const auto values =
      nlohmann::json::parse(clamped.body)["samples"][0]["radiance"].get<std::vector<double>>();
  ASSERT_EQ(values.size(), 37u);
  EXPECT_EQ(*std::min_element(values.begin(), values.end()), 0.0);
  EXPECT_GT(*std::max_element(values.begin(), values.end()), 0.0);

  // Inside the fit's domain the option changes nothing.
  for (auto& [key, value] : query)
    if (key == "view_zenith") value = "30";
  const ApiResponse inside_clamped = get_radiance(provider, query);
  query.pop_back();
  const ApiResponse inside = get_radiance(provider, query);
  ASSERT_EQ(inside.status, 200) << inside.body;
  EXPECT_EQ(nlohmann::json::parse(inside.body)["samples"],
            nlohmann::json::parse(inside_clamped.body)["samples"]);
}

}  // namespace
}  // namespace clearsky::api
