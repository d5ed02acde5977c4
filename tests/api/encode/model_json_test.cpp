// Descriptor JSON: every field present, infinite limits as null, never NaN.
#include "api/encode/model_json.h"

#include <gtest/gtest.h>

#include <limits>

namespace clearsky::api {
namespace {

TEST(ModelJson, EncodesEveryDescriptorField) {
  ModelDescriptor d;
  d.id = "example";
  d.name = "Example 2024";
  d.version = "3";
  d.citation = "A. Author, Journal 2024";
  d.native_wavelengths_nm = {440, 550, 680};
  d.min_wavelength_nm = 320;
  d.parameters = {{"turbidity", "", "Linke turbidity", 2.53, 1.0, 10.0, false, true}};
  d.capabilities.max_sun_zenith_deg = 108;
  d.capabilities.scattering_orders = -1;
  const nlohmann::json j = descriptor_to_json(d);
  EXPECT_EQ(j["id"], "example");
  EXPECT_EQ(j["version"], "3");
  EXPECT_EQ(j["wavelength_range_nm"][0], 320.0);
  EXPECT_TRUE(j["wavelength_range_nm"][1].is_null()) << "infinite upper limit";
  EXPECT_EQ(j["parameters"][0]["name"], "turbidity");
  EXPECT_EQ(j["parameters"][0]["kind"], "atmosphere");
  EXPECT_EQ(j["parameters"][0]["default"], 2.53);
  EXPECT_EQ(j["capabilities"]["sun_below_horizon"], true);
  EXPECT_EQ(j["capabilities"]["scattering_orders"], "all");
  EXPECT_EQ(j["native_wavelengths_nm"].size(), 3u);
  // No dark sun zenith declared: null; declared: the number.
  EXPECT_TRUE(j["capabilities"]["dark_beyond_sun_zenith_deg"].is_null());
  d.capabilities.dark_beyond_sun_zenith_deg = 104.5;
  EXPECT_EQ(descriptor_to_json(d)["capabilities"]["dark_beyond_sun_zenith_deg"], 104.5);
}

}  // namespace
}  // namespace clearsky::api
