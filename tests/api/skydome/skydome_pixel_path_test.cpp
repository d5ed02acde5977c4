// The skydome's fast pixel path (SkydomePixelPath::fast, api/skydome/skydome_render.h) against
// its per-pixel reference: the same bytes, whatever the model, ground, disc, channels, format,
// projection and compression, including a sun on the horizon whose disc reaches the rows below
// it (which the fast path must then compute pixel by pixel).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "api/skydome/skydome_render.h"
#include "models/registry.h"
#include "tests/support/synchronous_provider.h"

namespace clearsky::api {
namespace {

std::string rendered(const SkydomeRender& render, SkydomePixelPath path, std::size_t& unanswered) {
  std::string bytes;
  EXPECT_TRUE(render.write(
      [&bytes](const char* data, std::size_t size) {
        bytes.append(data, size);
        return true;
      },
      0, &unanswered, path));
  return bytes;
}

TEST(SkydomePixelPath, FastGivesTheBytesOfThePerPixelReference) {
  const clearsky::testing::SynchronousProvider provider(
      std::vector<ModelFactory>(registered_models().begin(), registered_models().end()));
  const ApiContext context{provider, Limits{}};
  const std::vector<NameValues> cases = {
      {{"model", "preetham"}, {"projection", "latlong"}, {"ground", "albedo"}},
      {{"model", "preetham"}, {"projection", "latlong"}, {"ground", "none"}},
      {{"model", "hosek"}, {"projection", "latlong"}, {"ground", "albedo"}, {"quality", "draft"}},
      {{"model", "hosek"},
       {"projection", "latlong"},
       {"ground", "albedo"},
       {"sun", "disc"},
       {"sun_zenith", "90"}},
      {{"model", "preetham"}, {"projection", "latlong"}, {"channels", "luminance"}},
      {{"model", "preetham"}, {"projection", "latlong"}, {"channels", "spectral"}},
      {{"model", "preetham"}, {"projection", "latlong"}, {"method", "three"}},
      {{"model", "preetham"},
       {"projection", "latlong"},
       {"ground", "albedo"},
       {"compression", "zip"}},
      {{"model", "preetham"}, {"projection", "latlong"}, {"format", "png"}},
      {{"model", "preetham"}, {"projection", "fisheye"}, {"ground", "albedo"}},
      // The fast path's XYZ of a whole piece (XyzWeights::xyz_of_rows): RGB, luminance, the
      // disc's pixels (computed one by one among the others) and a second model.
      {{"model", "preetham"}, {"projection", "fisheye"}, {"channels", "luminance"}},
      {{"model", "preetham"}, {"projection", "fisheye"}, {"sun", "disc"}},
      {{"model", "hosek"}, {"projection", "fisheye"}, {"ground", "albedo"}},
      {{"model", "oneal"}, {"projection", "latlong"}, {"ground", "model"}},
  };
  for (const NameValues& query : cases) {
    ApiRequest request;
    request.path = request.route = "/v1/skydome";
    request.query = {{"sun_azimuth", "135"}, {"size", "64"}};
    if (std::none_of(query.begin(), query.end(),
                     [](const auto& p) { return p.first == "sun_zenith"; }))
      request.query.emplace_back("sun_zenith", "40");
    request.query.insert(request.query.end(), query.begin(), query.end());
    const SkydomeRender render = prepare_skydome(context, request);
    std::size_t fast_unanswered = 0, reference_unanswered = 0;
    const std::string fast = rendered(render, SkydomePixelPath::fast, fast_unanswered);
    const std::string reference =
        rendered(render, SkydomePixelPath::per_pixel, reference_unanswered);
    std::string name;
    for (const auto& [key, value] : query) name += key + "=" + value + " ";
    EXPECT_GT(fast.size(), 1000u) << name;
    EXPECT_TRUE(fast == reference) << name;
    EXPECT_EQ(fast_unanswered, reference_unanswered) << name;
  }
}

}  // namespace
}  // namespace clearsky::api
