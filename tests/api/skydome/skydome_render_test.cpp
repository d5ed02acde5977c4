// Skydome request parsing (api/skydome/skydome_render.h): the image size and its limit.
#include "api/skydome/skydome_render.h"

#include <gtest/gtest.h>

#include "tests/support/synchronous_provider.h"
#include "tests/support/test_sky_model.h"

namespace clearsky::api {
namespace {

ApiRequest skydome_request(NameValues query) {
  ApiRequest request;
  request.path = request.route = "/v1/skydome";
  request.query = {{"model", "testsky"}, {"sun_zenith", "50"}, {"sun_azimuth", "100"}};
  request.query.insert(request.query.end(), query.begin(), query.end());
  return request;
}

// A request without size is 512 pixels wide, or the server's limit when that is lower: the
// default once ran past a lower limit (found by fuzz/api_routes_fuzz.cpp).
TEST(SkydomeRenderSize, DefaultStaysWithinTheLimit) {
  const clearsky::testing::SynchronousProvider provider(clearsky::testing::test_factories());
  const ApiContext wide{provider, Limits{}};
  EXPECT_EQ(prepare_skydome(wide, skydome_request({})).width(), 512);
  const ApiContext narrow{provider, Limits{100, 100, 64}};
  EXPECT_EQ(prepare_skydome(narrow, skydome_request({})).width(), 64);
  const ApiContext odd{provider, Limits{100, 100, 33}};
  EXPECT_EQ(prepare_skydome(odd, skydome_request({{"projection", "latlong"}})).width(), 32);
  EXPECT_EQ(prepare_skydome(narrow, skydome_request({{"size", "16"}})).width(), 16);
  EXPECT_THROW(prepare_skydome(narrow, skydome_request({{"size", "128"}})), ApiError);
}

}  // namespace
}  // namespace clearsky::api
