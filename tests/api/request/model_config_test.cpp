// validate_model_config and from_invalid_argument: every refusal of the models layer becomes a
// 400 naming the request parameter, by the error's type and field, never by its text.
#include <gtest/gtest.h>

#include "api/error/api_error.h"
#include "api/request/sky_request.h"
#include "tests/support/test_sky_model.h"

namespace clearsky::api {
namespace {

std::string refused_parameter(const ModelConfig& config) {
  try {
    validate_model_config(clearsky::testing::test_sky_descriptor(), config);
  } catch (const ApiError& e) {
    EXPECT_EQ(e.status(), 400) << e.what();
    EXPECT_EQ(e.code(), "invalid_parameter") << e.what();
    return e.parameter();
  }
  return "";
}

// Each atmosphere parameter out of AtmosphereParameters' range, by its request name.
TEST(ModelConfigErrors, AtmosphereRefusalsNameTheParameter) {
  const std::pair<const char*, double> cases[] = {
      {"alpha", 5.0},
      {"beta", 3.0},
      {"g", 1.0},
      {"turbidity", 11.0},
      {"albedo", 2.0},
      {"mie_single_scattering_albedo", 1.5},
      {"rayleigh_scale_height_m", 0.0},
      {"mie_scale_height_m", 2e5},
      {"rayleigh_temperature_celsius", 200.0},
      {"earth_radius_m", -1.0},
      {"top_radius_m", 1.0},
  };
  for (const auto& [name, value] : cases) {
    ModelConfig config;
    ASSERT_TRUE(set_atmosphere_parameter(config.atmosphere, name, value)) << name;
    EXPECT_EQ(refused_parameter(config), name);
  }
  EXPECT_EQ(refused_parameter(ModelConfig{}), "");
}

// A model option out of its descriptor's range, not an integer, or unknown to the model is
// named.
TEST(ModelConfigErrors, OptionRefusalsNameTheOption) {
  ModelConfig config;
  config.options["gain"] = 100.0;
  EXPECT_EQ(refused_parameter(config), "gain");
  config.options["gain"] = 2.0;
  config.options["build_ms"] = 0.5;  // an integer option
  EXPECT_EQ(refused_parameter(config), "build_ms");
  config.options.erase("build_ms");
  config.options["sparkle"] = 1.0;  // not an option of the model
  EXPECT_EQ(refused_parameter(config), "sparkle");
}

TEST(ModelConfigErrors, ByTypeNotByText) {
  const ApiError typed =
      from_invalid_argument(InvalidInput("latitude_deg", "must be in [-90, 90]"));
  EXPECT_EQ(typed.parameter(), "lat");
  EXPECT_EQ(typed.reason(), "must be in [-90, 90]");
  EXPECT_EQ(from_invalid_input(InvalidInput("unix_time_utc_s", "out of range")).parameter(),
            "time");
  EXPECT_EQ(from_invalid_input(InvalidInput("alpha", "must be in [0, 4]")).parameter(), "alpha");
  // A plain std::invalid_argument is not decoded, even when its text looks like "field: why".
  const ApiError plain = from_invalid_argument(std::invalid_argument("alpha: must be in [0, 4]"));
  EXPECT_EQ(plain.status(), 400);
  EXPECT_EQ(plain.parameter(), "model");
  EXPECT_STREQ(plain.what(), "alpha: must be in [0, 4]");
}

}  // namespace
}  // namespace clearsky::api
