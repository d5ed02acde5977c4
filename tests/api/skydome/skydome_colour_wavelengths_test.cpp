// The colour grid of an RGB skydome per quality level (api/colour/colour_wavelengths.h, used by
// api/skydome/skydome_render.cpp): at standard every pixel is, bit for bit, the colour of the
// model's 40-wavelength spectrum through the grid's XYZ weights (the computation of earlier
// releases) and the header has no colour-grid attribute; at draft the model is built on the
// short grid, the header names it and the error, and every pixel is within the stated Delta E
// 2000 of the standard pixel.
#include <gtest/gtest.h>

#include <algorithm>

#include "api/colour/colour_wavelengths.h"
#include "api/colour/srgb_gamut.h"
#include "api/colour/xyz_weights.h"
#include "api/skydome/skydome_render.h"
#include "models/colour/delta_e_2000.h"
#include "models/registry.h"
#include "tests/server/http/decoded_exr.h"
#include "tests/support/synchronous_provider.h"

namespace clearsky::api {
namespace {

using clearsky::server::testing::DecodedExr;

constexpr int kWidth = 48;  // latlong: 48 x 24 pixels

DecodedExr render(const ApiContext& context, const std::string& quality) {
  ApiRequest request;
  request.path = request.route = "/v1/skydome";
  request.query = {{"model", "preetham"},
                   {"sun_zenith", "40"},
                   {"sun_azimuth", "135"},
                   {"projection", "latlong"},
                   {"size", std::to_string(kWidth)},
                   {"pixel_type", "float"},
                   {"ground", "none"},
                   {"quality", quality}};
  const SkydomeRender render = prepare_skydome(context, request);
  std::string bytes;
  EXPECT_TRUE(render.write([&bytes](const char* data, std::size_t size) {
    bytes.append(data, size);
    return true;
  }));
  return clearsky::server::testing::decode(bytes);
}

class SkydomeColourWavelengths : public ::testing::Test {
 protected:
  SkydomeColourWavelengths()
      : provider_(
            std::vector<ModelFactory>(registered_models().begin(), registered_models().end())),
        context_{provider_, Limits{}} {}
  clearsky::testing::SynchronousProvider provider_;
  ApiContext context_;
};

TEST_F(SkydomeColourWavelengths, StandardIsTheFortyWavelengthColourBitForBit) {
  const DecodedExr image = render(context_, "standard");
  EXPECT_FALSE(image.strings.contains("clearskyColourWavelengthsNm"));
  const auto model = find_model("preetham")->create(ModelConfig{}, {});
  ASSERT_EQ(model->wavelengths().size(), 40u);
  const XyzWeights weights(model->wavelengths());
  const auto sun = model->prepare_sun({degrees_to_radians(40.0), degrees_to_radians(135.0)});
  const SkydomeProjection projection(Projection::latlong, kWidth);
  int compared = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      SkyDirection d;
      if (!projection.direction(x, y, d) || d.zenith_rad > 0.5 * kPi) continue;
      SpectralBatch batch;
      model->sky_radiance(*sun, {}, std::vector<ViewDirection>{d}, batch);
      if (batch.status[0] != SampleStatus::ok) continue;
      const LinearSrgb c = clip_to_srgb_gamut(xyz_to_linear_srgb(weights.xyz(batch.values))).rgb;
      const std::size_t i = static_cast<std::size_t>(y) * kWidth + static_cast<std::size_t>(x);
      EXPECT_EQ(image.channels.at("R")[i], static_cast<float>(c.r)) << x << "," << y;
      EXPECT_EQ(image.channels.at("G")[i], static_cast<float>(c.g)) << x << "," << y;
      EXPECT_EQ(image.channels.at("B")[i], static_cast<float>(c.b)) << x << "," << y;
      ++compared;
    }
  }
  EXPECT_GT(compared, kWidth * kWidth / 8);
}

TEST_F(SkydomeColourWavelengths, DraftIsWithinItsStatedDeltaE) {
  const DecodedExr standard = render(context_, "standard");
  const DecodedExr draft = render(context_, "draft");
  EXPECT_EQ(draft.strings.at("clearskyColourWavelengthsNm"),
            wavelength_list_text(kDraftColourWavelengthsNm));
  const std::optional<ColourError> stated = draft_colour_error("preetham");
  ASSERT_TRUE(stated);
  EXPECT_EQ(draft.strings.at("clearskyColourError"), colour_error_text(stated));
  // CIELAB relative to the brightest standard pixel, D65 (as the measurement of the figures).
  const auto xyz = [](const DecodedExr& e, std::size_t i) {
    return linear_srgb_to_xyz(
        {e.channels.at("R")[i], e.channels.at("G")[i], e.channels.at("B")[i]});
  };
  const std::size_t n = standard.channels.at("R").size();
  double brightest = 0.0;
  for (std::size_t i = 0; i < n; ++i) brightest = std::max(brightest, xyz(standard, i).y);
  const Xyz white = xyy_to_xyz({0.3127, 0.3290, brightest});
  double largest = 0.0;
  bool differs = false;
  for (std::size_t i = 0; i < n; ++i) {
    if (standard.channels.at("A")[i] == 0.0f) continue;
    largest = std::max(largest, delta_e_2000(xyz_to_lab(xyz(standard, i), white),
                                             xyz_to_lab(xyz(draft, i), white)));
    differs = differs || standard.channels.at("R")[i] != draft.channels.at("R")[i];
  }
  EXPECT_TRUE(differs) << "the draft was computed on the 40 wavelengths";
  // The sRGB gamut clip can only bring the two colours closer where both are clipped; the
  // stated maximum is of the unclipped colours over more suns.
  EXPECT_LE(largest, stated->max);
}

}  // namespace
}  // namespace clearsky::api
