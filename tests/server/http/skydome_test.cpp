// GET /v1/skydome over loopback: the streamed EXR decodes with OpenEXR, carries the header
// attributes, and every pixel equals the direct evaluation; a client that disconnects
// mid-stream leaves the server serving.
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "api/colour/xyz_weights.h"
#include "api/skydome/skydome_projection.h"
#include "api/skydome/skydome_render.h"
#include "models/core/numeric.h"
#include "tests/server/http/decoded_exr.h"
#include "tests/server/http/server_fixture.h"

namespace clearsky::server {
namespace {

using clearsky::testing::TestSky;
using testing::decode;
using testing::DecodedExr;

class SkydomeTest : public testing::ServerFixture {
 protected:
  std::string fetch(const std::string& query) {
    auto c = client();
    const auto r = c.Get("/v1/skydome?model=testsky&sun_zenith=50&sun_azimuth=100&" + query);
    EXPECT_TRUE(r);
    if (!r) return {};
    EXPECT_EQ(r->status, 200) << r->body;
    EXPECT_EQ(r->get_header_value("Content-Type"), "image/x-exr");
    EXPECT_EQ(r->get_header_value("Transfer-Encoding"), "chunked");
    return r->body;
  }
  const SkyDirection sun{degrees_to_radians(50.0), degrees_to_radians(100.0)};
};

TEST_F(SkydomeTest, RgbFisheyeEqualsDirectEvaluation) {
  const DecodedExr exr = decode(fetch("projection=fisheye&size=64&channels=rgb&pixel_type=float"));
  ASSERT_EQ(exr.width, 64);
  ASSERT_EQ(exr.height, 64);
  const api::SkydomeProjection projection(api::Projection::fisheye, 64);
  const auto grid = WavelengthGrid::paper_bins();
  const api::XyzWeights xyz(grid);
  int compared = 0;
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x) {
      const std::size_t i = static_cast<std::size_t>(y * 64 + x);
      SkyDirection d;
      if (!projection.direction(x, y, d)) {
        EXPECT_EQ(exr.channels.at("R")[i], 0.0f);
        EXPECT_EQ(exr.channels.at("A")[i], 0.0f);
        continue;
      }
      EXPECT_EQ(exr.channels.at("A")[i], 1.0f);
      std::vector<double> l(grid.size());
      for (std::size_t w = 0; w < grid.size(); ++w) l[w] = TestSky::radiance(1.0, grid[w], d, sun);
      const LinearSrgb c = xyz_to_linear_srgb(xyz.xyz(l));
      EXPECT_NEAR(exr.channels.at("R")[i], c.r, 1e-6 * std::abs(c.r) + 1e-9);
      EXPECT_NEAR(exr.channels.at("G")[i], c.g, 1e-6 * std::abs(c.g) + 1e-9);
      EXPECT_NEAR(exr.channels.at("B")[i], c.b, 1e-6 * std::abs(c.b) + 1e-9);
      ++compared;
    }
  }
  EXPECT_GT(compared, 3000);
}

TEST_F(SkydomeTest, SpectralLatlongCarriesFichetLayout) {
  const DecodedExr exr =
      decode(fetch("projection=latlong&size=32&channels=spectral&wavelengths=450,550"));
  ASSERT_EQ(exr.width, 32);
  ASSERT_EQ(exr.height, 16);
  EXPECT_EQ(exr.strings.at("spectralLayoutVersion"), "1.0");
  EXPECT_EQ(exr.strings.at("emissiveUnits"), "W.m^-2.sr^-1");
  ASSERT_EQ(exr.channels.size(), 3u);  // two wavelengths and the coverage A
  const auto& c550 = exr.channels.at("S0.550,000000nm");
  const auto& alpha = exr.channels.at("A");
  const api::SkydomeProjection projection(api::Projection::latlong, 32);
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 32; ++x) {
      SkyDirection d;
      projection.direction(x, y, d);
      const double expected = d.zenith_rad <= kPi / 2 ? TestSky::radiance(1.0, 550.0, d, sun) : 0.0;
      EXPECT_NEAR(c550[static_cast<std::size_t>(y * 32 + x)], expected, 1e-7) << x << "," << y;
      // The test sky answers views above the horizon only: below, no value, and A says so.
      EXPECT_EQ(alpha[static_cast<std::size_t>(y * 32 + x)], d.zenith_rad <= kPi / 2 ? 1.0f : 0.0f)
          << x << "," << y;
    }
  }
}

TEST_F(SkydomeTest, LuminanceCubemapAndHalfRgb) {
  const DecodedExr cube = decode(fetch("projection=cubemap&size=8&channels=luminance"));
  EXPECT_EQ(cube.width, 8);
  EXPECT_EQ(cube.height, 48);
  ASSERT_TRUE(cube.channels.contains("Y"));
  float largest = 0;
  for (float v : cube.channels.at("Y")) largest = std::max(largest, v);
  EXPECT_GT(largest, 0.0f);
  const DecodedExr rgb = decode(fetch("projection=fisheye&size=16"));
  EXPECT_EQ(rgb.channels.size(), 4u);  // R, G, B and the coverage A
  EXPECT_EQ(rgb.strings.count("clearskyAlpha"), 1u);
}

TEST_F(SkydomeTest, ErrorsComeBeforeTheStream) {
  auto c = client();
  auto r = c.Get("/v1/skydome?model=testsky&sun_zenith=50&sun_azimuth=100&size=8192");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 413);
  EXPECT_EQ(nlohmann::json::parse(r->body)["error"]["parameter"], "size");
  r = c.Get("/v1/skydome?model=testsky&sun_zenith=95&sun_azimuth=100");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 422);
  r = c.Get("/v1/skydome?model=testsky&sun_zenith=50&sun_azimuth=100&channels=rgb&wavelengths=500");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  EXPECT_EQ(nlohmann::json::parse(r->body)["error"]["parameter"], "wavelengths");
}

TEST_F(SkydomeTest, ClientDisconnectingMidStreamLeavesTheServerServing) {
  for (int attempt = 0; attempt < 3; ++attempt) {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    ASSERT_GE(fd, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<uint16_t>(port));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    ASSERT_EQ(::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
    const std::string request =
        "GET /v1/skydome?model=testsky&sun_zenith=50&sun_azimuth=100&size=1024&channels=spectral "
        "HTTP/1.1\r\n"
        "Host: 127.0.0.1\r\n\r\n";
    ASSERT_EQ(::send(fd, request.data(), request.size(), 0), static_cast<ssize_t>(request.size()));
    char buffer[4096];
    std::size_t received = 0;
    while (received < 20000) {
      const ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
      if (n <= 0) break;
      received += static_cast<std::size_t>(n);
    }
    EXPECT_GE(received, 20000u);
    ::close(fd);
  }
  auto c = client();
  for (int i = 0; i < 20; ++i) {
    const auto r = c.Get("/healthz");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 200);
  }
  const DecodedExr exr = decode(fetch("size=16"));
  EXPECT_EQ(exr.width, 16);
}

}  // namespace
}  // namespace clearsky::server
