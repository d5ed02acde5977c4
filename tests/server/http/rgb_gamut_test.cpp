// Out-of-gamut colours through the real `clearsky serve` (api/colour/srgb_gamut.h,
// docs/http-api.md "RGB"): O'Neal's sky with the sun at the horizon has saturated colours whose
// linear sRGB has a negative component. /v1/rgb sends none, and flags exactly the samples it
// clipped (checked against the colour computed here from /v1/radiance's spectra); the RGB
// skydome has no negative pixel and says how it maps the gamut.
#include <gtest/gtest.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <thread>

#include "api/colour/xyz_weights.h"
#include "models/core/sky_model.h"
#include "tests/server/http/decoded_exr.h"
#include "tests/server/http/watched_serve_process.h"

namespace clearsky::server {
namespace {

using testing::WatchedServeProcess;

TEST(RgbGamut, NegativeComponentsAreClippedAndFlaggedExactly) {
  WatchedServeProcess server({"--models", "oneal", "--prebuild-three", "false"});
  ASSERT_GT(server.port(), 0) << server.log();
  auto c = server.client();
  // Answers wait for the model's tables (O'Neal's ground irradiance table is built at start).
  for (int i = 0; i < 600; ++i) {
    const auto ready = c.Get("/readyz");
    if (ready && ready->status == 200) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  nlohmann::json views = nlohmann::json::array();
  for (int zenith = 0; zenith <= 90; zenith += 10)
    for (int azimuth = -180; azimuth < 180; azimuth += 30) views.push_back({zenith, azimuth});
  std::size_t clipped_anywhere = 0;
  for (const double sun_zenith : {89.5, 92.0, 95.0}) {
    SCOPED_TRACE(sun_zenith);
    const nlohmann::json request = {
        {"model", "oneal"}, {"sun_zenith", sun_zenith}, {"sun_azimuth", 0}, {"views", views}};
    const auto rgb = c.Post("/v1/rgb", request.dump(), "application/json");
    const auto radiance = c.Post("/v1/radiance", request.dump(), "application/json");
    ASSERT_TRUE(rgb && radiance);
    ASSERT_EQ(rgb->status, 200) << rgb->body;
    ASSERT_EQ(radiance->status, 200) << radiance->body;
    const auto colours = nlohmann::json::parse(rgb->body);
    const auto spectra = nlohmann::json::parse(radiance->body);
    // The default grid, on which both answered.
    const api::XyzWeights xyz(ModelConfig{}.wavelengths);
    std::size_t clipped = 0;
    for (std::size_t i = 0; i < views.size(); ++i) {
      const auto& sample = colours["samples"][i];
      const auto spectrum = spectra["samples"][i]["radiance"].get<std::vector<double>>();
      const LinearSrgb exact = xyz_to_linear_srgb(xyz.xyz(spectrum));
      const double components[] = {exact.r, exact.g, exact.b};
      bool negative = false;
      for (std::size_t k = 0; k < 3; ++k) {
        const double sent = sample["rgb"][k].get<double>();
        EXPECT_GE(sent, 0.0) << sample;
        EXPECT_NEAR(sent, std::max(0.0, components[k]), 1e-9 * std::abs(components[k]) + 1e-15)
            << sample;
        negative = negative || components[k] < 0.0;
      }
      EXPECT_EQ(sample["gamut_clipped"].get<bool>(), negative) << sample;
      clipped += negative ? 1 : 0;
    }
    EXPECT_EQ(colours["gamut_clipped_samples"], clipped);
    clipped_anywhere += clipped;
  }
  // The case this test is about happened (measured: 48, 9 and 9 of 120 views clipped).
  EXPECT_GT(clipped_anywhere, 0u);

  const auto image = c.Get(
      "/v1/skydome?model=oneal&sun_zenith=89.5&sun_azimuth=0&size=64&channels=rgb&"
      "pixel_type=float");
  ASSERT_TRUE(image);
  ASSERT_EQ(image->status, 200) << image->body.substr(0, 300);
  const testing::DecodedExr exr = testing::decode(image->body);
  EXPECT_NE(exr.strings.at("clearskyGamutMapping").find("clipped to 0"), std::string::npos);
  std::size_t zero_components = 0;
  for (const char* channel : {"R", "G", "B"}) {
    for (std::size_t i = 0; i < exr.channels.at(channel).size(); ++i) {
      const float value = exr.channels.at(channel)[i];
      EXPECT_GE(value, 0.0f) << channel << " pixel " << i;
      if (exr.channels.at("A")[i] == 1.0f && value == 0.0f) ++zero_components;
    }
  }
  // Answered pixels with a clipped component.
  EXPECT_GT(zero_components, 0u);
}

}  // namespace
}  // namespace clearsky::server
