// The renderer options of GET /v1/skydome (api/skydome/skydome_options.h): values outside the
// table, ground=model without a ground, units without rgb and half with the disc or photometric
// values are 400s naming the parameter; the defaults keep the answer of earlier requests; the
// OpenAPI document lists each option with the table's values.
#include "api/skydome/skydome_options.h"

#include <gtest/gtest.h>

#include "api/openapi/openapi_document.h"
#include "api/skydome/skydome_render.h"
#include "tests/support/synchronous_provider.h"
#include "tests/support/test_sky_model.h"

namespace clearsky::api {
namespace {

ApiRequest skydome_request(NameValues query) {
  ApiRequest request;
  request.path = request.route = "/v1/skydome";
  request.query = {
      {"model", "testsky"}, {"sun_zenith", "50"}, {"sun_azimuth", "100"}, {"size", "16"}};
  request.query.insert(request.query.end(), query.begin(), query.end());
  return request;
}

class SkydomeOptionsTest : public ::testing::Test {
 protected:
  // The parameter a refused request names ("" when it is accepted).
  std::string refused(NameValues query) {
    try {
      prepare_skydome(context, skydome_request(std::move(query)));
    } catch (const ApiError& e) {
      EXPECT_EQ(e.status(), 400) << e.what();
      return e.parameter();
    }
    return "";
  }
  const clearsky::testing::SynchronousProvider provider{clearsky::testing::test_factories()};
  const ApiContext context{provider, Limits{}};
};

TEST_F(SkydomeOptionsTest, ValuesOutsideTheTableAreRefusedByName) {
  EXPECT_EQ(refused({{"sun", "bright"}}), "sun");
  EXPECT_EQ(refused({{"ground", "grass"}}), "ground");
  EXPECT_EQ(refused({{"units", "lux"}}), "units");
  EXPECT_EQ(refused({{"compression", "lzma"}}), "compression");
  EXPECT_EQ(refused({{"sun", "disc"},
                     {"ground", "albedo"},
                     {"units", "photometric"},
                     {"compression", "piz"}}),
            "");
}

TEST_F(SkydomeOptionsTest, ConflictsAreRefusedByName) {
  // The test sky answers no view below the horizon: it has no ground of its own.
  EXPECT_EQ(refused({{"ground", "model"}}), "ground");
  // units is an option of RGB images only.
  EXPECT_EQ(refused({{"channels", "luminance"}, {"units", "photometric"}}), "units");
  EXPECT_EQ(refused({{"sun", "disc"}, {"pixel_type", "half"}}), "pixel_type");
  EXPECT_EQ(refused({{"units", "photometric"}, {"pixel_type", "half"}}), "pixel_type");
  EXPECT_EQ(refused({{"pixel_type", "half"}}), "");
}

TEST_F(SkydomeOptionsTest, DefaultsKeepEarlierAnswers) {
  Parameters p("/v1/skydome");
  const SkydomeOptions o = parse_skydome_options(p, true, clearsky::testing::test_sky_descriptor());
  EXPECT_EQ(o.sun, SunDisc::none);
  EXPECT_EQ(o.ground, Ground::none);
  EXPECT_EQ(o.units, PixelUnits::radiometric);
  EXPECT_EQ(o.compression, ExrCompression::none);
  ModelDescriptor with_ground = clearsky::testing::test_sky_descriptor();
  with_ground.capabilities.view_below_horizon = true;
  EXPECT_EQ(parse_skydome_options(p, true, with_ground).ground, Ground::model);
}

TEST_F(SkydomeOptionsTest, OpenApiListsTheTable) {
  const auto& document = openapi_document();
  const auto& parameters = document["paths"]["/v1/skydome"]["get"]["parameters"];
  for (const SkydomeOptionSpec& option : skydome_option_table()) {
    bool found = false;
    for (const auto& p : parameters) {
      if (!p.contains("name") || p["name"].get<std::string>() != option.name) continue;
      found = true;
      ASSERT_EQ(p["schema"]["enum"].size(), option.values.size());
      for (std::size_t i = 0; i < option.values.size(); ++i)
        EXPECT_EQ(p["schema"]["enum"][i].get<std::string>(), option.values[i]);
    }
    EXPECT_TRUE(found) << option.name;
  }
}

}  // namespace
}  // namespace clearsky::api
