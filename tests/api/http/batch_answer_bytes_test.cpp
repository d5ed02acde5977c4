// The memory estimate of a radiance or RGB batch answer (api/http/batch_answer_bytes.h).
#include "api/http/batch_answer_bytes.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace clearsky::api {
namespace {

// What the estimate must cover at least: the encoded body of a radiance answer of `views`
// views of `wavelengths` values of the longest text (17 significant digits and an exponent).
std::size_t radiance_body_bytes(std::size_t views, std::size_t wavelengths) {
  nlohmann::json samples = nlohmann::json::array();
  for (std::size_t v = 0; v < views; ++v) {
    nlohmann::json values = nlohmann::json::array();
    for (std::size_t w = 0; w < wavelengths; ++w) values.push_back(-1.2345678901234567e-300);
    samples.push_back({{"view_zenith_deg", 12.345678901234567},
                       {"view_azimuth_deg", 123.45678901234567},
                       {"radiance", std::move(values)}});
  }
  return nlohmann::json{{"samples", std::move(samples)}}.dump().size();
}

TEST(BatchAnswerBytes, ASingleViewAtTheDefaultGridsIsNotCounted) {
  // Bruneton's and the other spectral models' grids: 40 bins, up to 81 points.
  EXPECT_LT(batch_answer_bytes(1, 81, 81), kUncountedAnswerBytes);
  EXPECT_LT(batch_answer_bytes(1, 81, 5), kUncountedAnswerBytes);
}

TEST(BatchAnswerBytes, CoversTheEncodedBodyAndTheComputedSpectra) {
  for (const auto& [views, wavelengths] :
       {std::pair<std::size_t, std::size_t>{1, 40}, {100, 40}, {1000, 3}, {10, 2000}}) {
    const std::size_t estimate = batch_answer_bytes(views, wavelengths, wavelengths);
    EXPECT_GT(estimate, radiance_body_bytes(views, wavelengths) + views * wavelengths * 8)
        << views << " views x " << wavelengths;
  }
}

TEST(BatchAnswerBytes, GrowsWithViewsAndWavelengths) {
  EXPECT_LT(batch_answer_bytes(100, 40, 40), batch_answer_bytes(200, 40, 40));
  EXPECT_LT(batch_answer_bytes(100, 40, 5), batch_answer_bytes(100, 40, 40));
  EXPECT_LT(batch_answer_bytes(100, 40, 5), batch_answer_bytes(100, 81, 5));
  // The largest batch the default limits let through (10,000 views x 2,000 wavelengths) is
  // above the default budget of 256 MiB: refused 413 instead of being built.
  EXPECT_GT(batch_answer_bytes(10000, 2000, 2000), std::size_t{256} << 20);
}

}  // namespace
}  // namespace clearsky::api
