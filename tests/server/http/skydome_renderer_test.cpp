// GET /v1/skydome's renderer options over loopback (api/skydome/skydome_options.h,
// docs/renderers.md), decoded with OpenEXR: the sun disc's pixels integrate to the direct normal
// illuminance of GET /v1/irradiance and the header carries the sun; zip and piz files decode to
// the pixels of the uncompressed one; photometric RGB is 683 x radiometric and its luminance
// weights give the luminance image; the ground below the horizon and its alpha.
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStdIO.h>
#include <OpenEXR/ImfVecAttribute.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "api/colour/xyz_weights.h"
#include "models/core/numeric.h"
#include "tests/server/http/decoded_exr.h"
#include "tests/server/http/server_fixture.h"

namespace clearsky::server {
namespace {

using testing::decode;
using testing::DecodedExr;

constexpr const char* kSky = "/v1/skydome?model=testsky&sun_zenith=50&sun_azimuth=100&";

class SkydomeRendererTest : public testing::ServerFixture {
 protected:
  std::string fetch(const std::string& query) {
    auto c = client();
    const auto r = c.Get(std::string(kSky) + query);
    EXPECT_TRUE(r);
    if (!r) return {};
    EXPECT_EQ(r->status, 200) << r->body;
    return r->body;
  }
  nlohmann::json error_of(const std::string& query) {
    auto c = client();
    const auto r = c.Get(std::string(kSky) + query);
    EXPECT_TRUE(r);
    if (!r) return {};
    EXPECT_EQ(r->status, 400) << r->body;
    return nlohmann::json::parse(r->body)["error"];
  }
};

// Solid angle of row y of an OpenEXR latlong map of height h and width w (ImfEnvmap.h: rows at
// latitude pi (1/2 - y/(h-1)), columns 2 pi/(w-1) apart).
double latlong_pixel_sr(int y, int w, int h) {
  const double d_lat = kPi / (h - 1);
  const double lat = kPi * (0.5 - static_cast<double>(y) / (h - 1));
  const double top = std::min(lat + d_lat / 2, kPi / 2),
               bottom = std::max(lat - d_lat / 2, -kPi / 2);
  return 2 * kPi / (w - 1) * (std::sin(top) - std::sin(bottom));
}

template <typename Attribute>
auto header_value(const std::string& bytes, const char* name) {
  Imf::StdISStream stream;
  stream.str(bytes);
  Imf::InputFile file(stream);
  const auto* a = file.header().findTypedAttribute<Attribute>(name);
  EXPECT_NE(a, nullptr) << name;
  using Value = std::decay_t<decltype(std::declval<const Attribute&>().value())>;
  return a ? a->value() : Value{};
}

TEST_F(SkydomeRendererTest, SunDiscCarriesTheDirectNormalIlluminance) {
  auto c = client();
  const auto irradiance = c.Get("/v1/irradiance?model=testsky&sun_zenith=50&sun_azimuth=100");
  ASSERT_TRUE(irradiance);
  ASSERT_EQ(irradiance->status, 200);
  const double direct_lx =
      nlohmann::json::parse(irradiance->body)["direct_normal"]["illuminance_lx"].get<double>();

  for (int size : {64, 512}) {  // the disc within one pixel, and over many
    const std::string query = "projection=latlong&channels=luminance&size=" + std::to_string(size);
    const DecodedExr sky = decode(fetch(query));
    const DecodedExr with_sun = decode(fetch(query + "&sun=disc"));
    ASSERT_EQ(with_sun.width, size);
    double carried = 0;
    int pixels = 0;
    for (int y = 0; y < with_sun.height; ++y)
      for (int x = 0; x < with_sun.width; ++x) {
        const std::size_t i = static_cast<std::size_t>(y * with_sun.width + x);
        const double added = with_sun.channels.at("Y")[i] - sky.channels.at("Y")[i];
        if (added == 0.0) continue;
        ++pixels;
        carried += added * latlong_pixel_sr(y, with_sun.width, with_sun.height);
      }
    EXPECT_NEAR(carried, direct_lx, 1e-3 * direct_lx) << size;
    EXPECT_GE(pixels, 1);
    if (size == 512) {
      EXPECT_LE(pixels, 16);
    }
  }
}

TEST_F(SkydomeRendererTest, HeaderCarriesTheSun) {
  const std::string bytes = fetch("projection=latlong&size=32&sun=disc");
  const DecodedExr exr = decode(bytes);
  ASSERT_EQ(exr.channels.count("R"), 1u);
  // OpenEXR's frame: +y up, +z North, +x West; sun at zenith 50, azimuth 100 (East of South-East).
  const auto d = header_value<Imf::V3fAttribute>(bytes, "sunDirection");
  const double z = degrees_to_radians(50.0), a = degrees_to_radians(100.0);
  EXPECT_NEAR(d.x, -std::sin(z) * std::sin(a), 1e-6);
  EXPECT_NEAR(d.y, std::cos(z), 1e-6);
  EXPECT_NEAR(d.z, std::sin(z) * std::cos(a), 1e-6);
  EXPECT_NEAR(header_value<Imf::FloatAttribute>(bytes, "sunAngularRadiusDeg"), 0.2666, 1e-6);
  const double lx = header_value<Imf::FloatAttribute>(bytes, "sunIlluminanceLx");
  const auto rgb = header_value<Imf::V3fAttribute>(bytes, "sunIrradianceRGB");
  EXPECT_NEAR(683 * (0.2126 * rgb.x + 0.7152 * rgb.y + 0.0722 * rgb.z), lx, 1e-3 * lx);
  const auto radiance = header_value<Imf::V3fAttribute>(bytes, "sunRadianceRGB");
  EXPECT_GT(radiance.y, 1e4 * rgb.y);  // E / (6.8e-5 sr)
  const auto colour = header_value<Imf::V3fAttribute>(bytes, "sunColour");
  EXPECT_NEAR(0.2126 * colour.x + 0.7152 * colour.y + 0.0722 * colour.z, 1.0, 1e-4);
  EXPECT_NE(exr.strings.at("clearskySun").find("disc"), std::string::npos);
}

TEST_F(SkydomeRendererTest, CompressedFilesDecodeToTheSamePixels) {
  for (const char* type : {"float", "half"}) {
    const std::string query =
        std::string("projection=latlong&size=128&pixel_type=") + type + "&compression=";
    const std::string plain_bytes = fetch(query + "none");
    const DecodedExr plain = decode(plain_bytes);
    for (const char* compression : {"zip", "piz"}) {
      const std::string bytes = fetch(query + compression);
      EXPECT_LT(bytes.size(), plain_bytes.size()) << compression << " " << type;
      const DecodedExr packed = decode(bytes);
      ASSERT_EQ(packed.channels.size(), plain.channels.size());
      for (const auto& [name, values] : plain.channels)
        EXPECT_EQ(packed.channels.at(name), values) << name << " " << compression << " " << type;
    }
  }
}

TEST_F(SkydomeRendererTest, PhotometricIs683TimesRadiometric) {
  const std::string query = "projection=fisheye&size=48&pixel_type=float";
  const DecodedExr radiometric = decode(fetch(query));
  const DecodedExr photometric = decode(fetch(query + "&units=photometric"));
  const DecodedExr luminance = decode(fetch("projection=fisheye&size=48&channels=luminance"));
  const auto& y = luminance.channels.at("Y");
  for (std::size_t i = 0; i < y.size(); ++i) {
    for (const char* c : {"R", "G", "B"}) {
      const double r = radiometric.channels.at(c)[i], p = photometric.channels.at(c)[i];
      EXPECT_NEAR(p, 683.0 * r, 1e-6 * p + 1e-9);
    }
    // Linear sRGB's luminance weights (IEC 61966-2-1) give cd/m2.
    const double from_rgb = 0.2126729 * photometric.channels.at("R")[i] +
                            0.7151522 * photometric.channels.at("G")[i] +
                            0.0721750 * photometric.channels.at("B")[i];
    EXPECT_NEAR(from_rgb, y[i], 1e-4 * y[i] + 1e-6);
  }
}

TEST_F(SkydomeRendererTest, GroundBelowTheHorizonAndItsAlpha) {
  const int w = 64, h = 32;  // rows 16.. are below the horizon
  const DecodedExr none = decode(fetch("projection=latlong&size=64&pixel_type=float&ground=none"));
  const DecodedExr albedo =
      decode(fetch("projection=latlong&size=64&pixel_type=float&ground=albedo"));
  EXPECT_EQ(none.strings.at("clearskyGround"), "none");
  EXPECT_EQ(albedo.strings.at("clearskyGround"), "albedo");

  // L = albedo / pi x (E_n cos(50 deg) + E_sky) with the test sky's closed forms
  // (tests/support/test_sky_model.h) and the default albedo (grass).
  const auto model = clearsky::testing::create_test_sky(ModelConfig{}, {});
  const WavelengthGrid& grid = model->wavelengths();
  std::vector<double> l(grid.size());
  for (std::size_t i = 0; i < grid.size(); ++i) {
    const double e_n = 1.5 * grid[i] / 500.0;
    const double e_sky = 0.01 * grid[i] / 500.0 * (kPi + 2.0 * kPi / 3.0);
    l[i] = model->atmosphere().ground_albedo[i] / kPi *
           (e_n * std::cos(degrees_to_radians(50.0)) + e_sky);
  }
  const LinearSrgb expected = xyz_to_linear_srgb(api::XyzWeights(grid).xyz(l));
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y * w + x);
      const bool below = y >= h / 2;
      EXPECT_EQ(none.channels.at("A")[i], below ? 0.0f : 1.0f);
      EXPECT_EQ(albedo.channels.at("A")[i], 1.0f);
      if (below) {
        EXPECT_EQ(none.channels.at("G")[i], 0.0f);
        EXPECT_NEAR(albedo.channels.at("R")[i], expected.r, 1e-5 * expected.r);
        EXPECT_NEAR(albedo.channels.at("G")[i], expected.g, 1e-5 * expected.g);
        EXPECT_NEAR(albedo.channels.at("B")[i], expected.b, 1e-5 * expected.b);
      } else {
        EXPECT_EQ(albedo.channels.at("G")[i], none.channels.at("G")[i]);
      }
    }
  }
}

TEST_F(SkydomeRendererTest, RefusalsNameTheParameter) {
  EXPECT_EQ(error_of("sun=bright")["parameter"], "sun");
  EXPECT_EQ(error_of("ground=model")["parameter"], "ground");  // the test sky has no ground
  EXPECT_EQ(error_of("compression=b44")["parameter"], "compression");
  EXPECT_EQ(error_of("channels=spectral&units=photometric")["parameter"], "units");
  EXPECT_EQ(error_of("sun=disc&pixel_type=half")["parameter"], "pixel_type");
}

}  // namespace
}  // namespace clearsky::server
