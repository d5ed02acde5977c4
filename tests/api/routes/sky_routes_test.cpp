// GET /v1/skydome's reservation in the answer memory budget (api/routes/sky_routes.cpp,
// api/http/answer_memory_budget.h): an image reserves its band while its answer exists, another
// image that does not fit is refused with 503 + Retry-After naming answer_memory, the bytes come
// back when the answer is destroyed (sent or cut), and a band above the whole budget is a 413.
#include <gtest/gtest.h>

#include "api/http/answer_memory_budget.h"
#include "api/routes/route_handlers.h"
#include "api/skydome/skydome_render.h"
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

const NameValues kSpectral64 = {{"size", "64"}, {"channels", "spectral"}};

TEST(SkydomeBandBytes, GrowWithWidthAndChannels) {
  const clearsky::testing::SynchronousProvider provider(clearsky::testing::test_factories());
  const ApiContext context{provider, Limits{}};
  const SkydomeRender spectral = prepare_skydome(context, skydome_request(kSpectral64));
  const SkydomeRender wide =
      prepare_skydome(context, skydome_request({{"size", "128"}, {"channels", "spectral"}}));
  const SkydomeRender luminance =
      prepare_skydome(context, skydome_request({{"size", "64"}, {"channels", "luminance"}}));
  // At least one row of float samples with its alpha channel.
  EXPECT_GE(luminance.band_bytes(), 64u * 2 * sizeof(float));
  EXPECT_GT(spectral.band_bytes(), luminance.band_bytes());
  EXPECT_GT(wide.band_bytes(), spectral.band_bytes());
}

TEST(SkydomeAnswerMemory, AnImageThatDoesNotFitIsRefusedUntilAnotherEnds) {
  const clearsky::testing::SynchronousProvider provider(clearsky::testing::test_factories());
  const ApiContext plain{provider, Limits{}};
  const std::size_t band = prepare_skydome(plain, skydome_request(kSpectral64)).band_bytes();
  // Room for two bands, not three.
  AnswerMemoryBudget budget(band * 5 / 2);
  ApiContext context{provider, Limits{}};
  context.retry_after_s = 7;
  context.answer_memory = &budget;

  std::optional<ApiResponse> first = get_skydome(context, skydome_request(kSpectral64));
  ApiResponse second = get_skydome(context, skydome_request(kSpectral64));
  EXPECT_EQ(budget.reserved_bytes(), 2 * band);
  try {
    get_skydome(context, skydome_request(kSpectral64));
    FAIL() << "a third image was accepted";
  } catch (const ApiError& e) {
    EXPECT_EQ(e.status(), 503);
    EXPECT_EQ(e.code(), "busy");
    EXPECT_EQ(e.parameter(), "answer_memory");
    EXPECT_EQ(e.retry_after_s(), 7);
    EXPECT_NE(std::string(e.what()).find("answer_memory"), std::string::npos) << e.what();
  }
  EXPECT_EQ(budget.reserved_bytes(), 2 * band);

  // The first answer is sent whole and destroyed: its band is given back.
  std::string image;
  EXPECT_TRUE(first->stream([&image](const char* data, std::size_t size) {
    image.append(data, size);
    return true;
  }));
  EXPECT_GT(image.size(), 64u * 64 * 4);
  first.reset();
  EXPECT_EQ(budget.reserved_bytes(), band);

  // A client that leaves: the stream stops, and its band comes back with the answer.
  ApiResponse third = get_skydome(context, skydome_request(kSpectral64));
  EXPECT_FALSE(third.stream([](const char*, std::size_t) { return false; }));
  third = ApiResponse{};
  EXPECT_EQ(budget.reserved_bytes(), band);
}

TEST(SkydomeAnswerMemory, ABandAboveTheWholeBudgetIsTooLarge) {
  const clearsky::testing::SynchronousProvider provider(clearsky::testing::test_factories());
  const ApiContext plain{provider, Limits{}};
  const std::size_t band = prepare_skydome(plain, skydome_request(kSpectral64)).band_bytes();
  AnswerMemoryBudget budget(band - 1);
  ApiContext context{provider, Limits{}};
  context.answer_memory = &budget;
  try {
    get_skydome(context, skydome_request(kSpectral64));
    FAIL() << "an image above the budget was accepted";
  } catch (const ApiError& e) {
    EXPECT_EQ(e.status(), 413);
    EXPECT_EQ(e.parameter(), "answer_memory");
  }
  EXPECT_EQ(budget.reserved_bytes(), 0u);
  EXPECT_NO_THROW(
      get_skydome(context, skydome_request({{"size", "8"}, {"channels", "luminance"}})));
}

}  // namespace
}  // namespace clearsky::api
