// GET /v1/skydome?format=png over loopback: the streamed PNG decodes with libpng, has the
// requested size, alpha 0 outside the fisheye circle, every pixel equals the direct evaluation
// exposed, tone-mapped and sRGB-encoded (api/colour/display_tone_mapping.h), the sun's side of
// the sky is brighter, the exposure changes the image, bad parameters are 400s naming them, and a
// client leaving mid-image ends libpng's writing (its error path) with the server still serving.
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "api/colour/display_tone_mapping.h"
#include "api/colour/xyz_weights.h"
#include "api/skydome/skydome_projection.h"
#include "models/core/numeric.h"
#include "tests/server/http/decoded_png.h"
#include "tests/server/http/server_fixture.h"

namespace clearsky::server {
namespace {

using clearsky::testing::TestSky;
using testing::decode_png;
using testing::DecodedPng;

constexpr const char* kSky = "/v1/skydome?model=testsky&sun_zenith=50&sun_azimuth=100&format=png&";

class SkydomePngTest : public testing::ServerFixture {
 protected:
  DecodedPng fetch(const std::string& query) {
    auto c = client();
    const auto r = c.Get(std::string(kSky) + query);
    EXPECT_TRUE(r);
    if (!r) return {};
    EXPECT_EQ(r->status, 200) << r->body;
    EXPECT_EQ(r->get_header_value("Content-Type"), "image/png");
    EXPECT_EQ(r->get_header_value("Transfer-Encoding"), "chunked");
    EXPECT_EQ(r->get_header_value("Content-Disposition"), "inline; filename=\"sky.png\"");
    return decode_png(r->body);
  }
  // The error answer of a refused query: its status and the parameter it names.
  std::pair<int, std::string> refusal(const std::string& query) {
    auto c = client();
    const auto r = c.Get(std::string(kSky) + query);
    if (!r) return {0, ""};
    const auto body = nlohmann::json::parse(r->body, nullptr, false);
    if (body.is_discarded() || !body.contains("error")) return {r->status, ""};
    return {r->status, body["error"].value("parameter", "")};
  }
  // Mean of R + G + B over the answered pixels whose azimuth is within 45 degrees of az_deg.
  static double mean_towards(const DecodedPng& png, double az_deg) {
    const api::SkydomeProjection projection(api::Projection::fisheye, png.width);
    double sum = 0;
    int n = 0;
    for (int y = 0; y < png.height; ++y) {
      for (int x = 0; x < png.width; ++x) {
        SkyDirection d;
        if (!projection.direction(x, y, d) || d.zenith_rad < degrees_to_radians(30.0)) continue;
        const double off = std::remainder(radians_to_degrees(d.azimuth_rad) - az_deg, 360.0);
        if (std::abs(off) > 45.0) continue;
        const auto* p = png.pixel(x, y);
        sum += p[0] + p[1] + p[2];
        ++n;
      }
    }
    return n > 0 ? sum / n : 0.0;
  }
  static double mean_brightness(const DecodedPng& png) {
    double sum = 0;
    for (std::size_t i = 0; i < png.rgba.size(); i += 4)
      sum += png.rgba[i] + png.rgba[i + 1] + png.rgba[i + 2];
    return sum / static_cast<double>(png.rgba.size() / 4);
  }
  const SkyDirection sun{degrees_to_radians(50.0), degrees_to_radians(100.0)};
};

TEST_F(SkydomePngTest, FisheyeEqualsToneMappedDirectEvaluation) {
  const DecodedPng png = fetch("size=64&exposure=11");
  ASSERT_EQ(png.width, 64);
  ASSERT_EQ(png.height, 64);
  const api::SkydomeProjection projection(api::Projection::fisheye, 64);
  const auto grid = WavelengthGrid::paper_bins();
  const api::XyzWeights xyz(grid);
  const api::DisplayToneMapping display(11.0, api::ToneCurve::aces);
  int compared = 0, off_by_one = 0;
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x) {
      const std::uint8_t* p = png.pixel(x, y);
      SkyDirection d;
      if (!projection.direction(x, y, d)) {
        EXPECT_EQ(p[3], 0);
        continue;
      }
      EXPECT_EQ(p[3], 255);
      std::vector<double> l(grid.size());
      for (std::size_t w = 0; w < grid.size(); ++w) l[w] = TestSky::radiance(1.0, grid[w], d, sun);
      // The server rounds through float (the band); a value on a rounding edge may differ by 1.
      const LinearSrgb c = xyz_to_linear_srgb(xyz.xyz(l));
      const auto expected = display.display({static_cast<float>(std::max(0.0, c.r)),
                                             static_cast<float>(std::max(0.0, c.g)),
                                             static_cast<float>(std::max(0.0, c.b))});
      for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(p[k], expected[static_cast<std::size_t>(k)], 1) << x << "," << y;
        off_by_one += p[k] != expected[static_cast<std::size_t>(k)];
      }
      ++compared;
    }
  }
  EXPECT_GT(compared, 3000);
  EXPECT_LT(off_by_one, compared / 100);
}

TEST_F(SkydomePngTest, NotBlankAndBrighterTowardsTheSun) {
  const DecodedPng png = fetch("size=96&exposure=11");
  std::uint8_t lowest = 255, highest = 0;
  for (std::size_t i = 0; i < png.rgba.size(); i += 4) {
    if (png.rgba[i + 3] == 0) continue;
    lowest = std::min(lowest, png.rgba[i + 2]);
    highest = std::max(highest, png.rgba[i + 2]);
  }
  EXPECT_GT(highest - lowest, 20) << "a blank or flat image";
  EXPECT_GT(mean_towards(png, 100.0), mean_towards(png, 280.0) + 10.0);
}

TEST_F(SkydomePngTest, ExposureAndToneCurveChangeTheImage) {
  const double ev10 = mean_brightness(fetch("size=48&exposure=10"));
  const double ev13 = mean_brightness(fetch("size=48&exposure=13"));
  EXPECT_GT(ev10, ev13 + 20.0) << "a higher EV100 is a darker image";
  const DecodedPng aces = fetch("size=48&exposure=11&tone_map=aces");
  const DecodedPng reinhard = fetch("size=48&exposure=11&tone_map=reinhard");
  EXPECT_NE(aces.rgba, reinhard.rgba);
}

TEST_F(SkydomePngTest, LatlongAndCubemapHaveTheirSizes) {
  const DecodedPng latlong = fetch("size=64&projection=latlong");
  EXPECT_EQ(latlong.width, 64);
  EXPECT_EQ(latlong.height, 32);
  const DecodedPng cube = fetch("size=16&projection=cubemap");
  EXPECT_EQ(cube.width, 16);
  EXPECT_EQ(cube.height, 96);
}

// The renderer options that apply to the display image as to the EXR (one band computation):
// the albedo ground fills the lower half of a latlong image, which is transparent without it.
TEST_F(SkydomePngTest, TheAlbedoGroundAppliesToThePng) {
  const DecodedPng sky = fetch("size=32&projection=latlong&ground=none");
  const DecodedPng ground = fetch("size=32&projection=latlong&ground=albedo");
  ASSERT_EQ(sky.height, 16);
  ASSERT_EQ(ground.height, 16);
  const int below = 14;  // a row well below the horizon
  EXPECT_EQ(sky.pixel(5, below)[3], 0);
  EXPECT_EQ(ground.pixel(5, below)[3], 255);
  EXPECT_GT(ground.pixel(5, below)[0] + ground.pixel(5, below)[1] + ground.pixel(5, below)[2], 0);
  EXPECT_EQ(sky.pixel(5, 2)[3], 255);
}

TEST_F(SkydomePngTest, BadParametersAreRefusedByName) {
  EXPECT_EQ(refusal("size=32&exposure=99"), std::make_pair(400, std::string("exposure")));
  EXPECT_EQ(refusal("size=32&exposure=-11"), std::make_pair(400, std::string("exposure")));
  EXPECT_EQ(refusal("size=32&exposure=nan"), std::make_pair(400, std::string("exposure")));
  EXPECT_EQ(refusal("size=32&exposure=bright"), std::make_pair(400, std::string("exposure")));
  EXPECT_EQ(refusal("size=32&tone_map=filmic"), std::make_pair(400, std::string("tone_map")));
  EXPECT_EQ(refusal("size=32&channels=spectral"), std::make_pair(400, std::string("channels")));
  EXPECT_EQ(refusal("size=32&pixel_type=half"), std::make_pair(400, std::string("pixel_type")));
  // The EXR's renderer options that a display image cannot honour (docs/http-api.md "The PNG
  // skydome"): photometric units (the exposure is the scale) and OpenEXR compression.
  EXPECT_EQ(refusal("size=32&units=photometric"), std::make_pair(400, std::string("units")));
  EXPECT_EQ(refusal("size=32&compression=zip"), std::make_pair(400, std::string("compression")));
  EXPECT_EQ(refusal("size=999999").second, "size");
  // The EXR takes no exposure: an unused parameter is refused (docs/request-parsing.md).
  auto c = client();
  const auto r =
      c.Get("/v1/skydome?model=testsky&sun_zenith=50&sun_azimuth=100&size=32&exposure=11");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  EXPECT_EQ(nlohmann::json::parse(r->body)["error"]["parameter"], "exposure");
}

TEST_F(SkydomePngTest, ClientDisconnectingMidImageLeavesTheServerServing) {
  for (int attempt = 0; attempt < 3; ++attempt) {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    ASSERT_GE(fd, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<uint16_t>(port));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    ASSERT_EQ(::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
    const std::string request = std::string("GET ") + kSky +
                                "size=2048 HTTP/1.1\r\n"
                                "Host: 127.0.0.1\r\n\r\n";
    ASSERT_EQ(::send(fd, request.data(), request.size(), 0), static_cast<ssize_t>(request.size()));
    char buffer[4096];
    std::size_t received = 0;
    while (received < 2000) {
      const ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
      if (n <= 0) break;
      received += static_cast<std::size_t>(n);
    }
    EXPECT_GE(received, 2000u);
    ::close(fd);  // unread data: the kernel resets the connection, the next write fails
  }
  auto c = client();
  for (int i = 0; i < 20; ++i) {
    const auto r = c.Get("/healthz");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 200);
  }
  EXPECT_EQ(fetch("size=16").width, 16);
}

}  // namespace
}  // namespace clearsky::server
