// Elek 2010 as a variant of Bruneton 2008: identical on the paper's 40-wavelength grid, its
// own descriptor, and its original RGB output from 15 wavelengths close to the 40-wavelength
// colour.
#include "models/elek/elek.h"

#include <gtest/gtest.h>

#include "models/registry.h"
#include "tests/models/bruneton/bruneton_test_support.h"

namespace clearsky {
namespace {

ModelConfig reduced(WavelengthGrid grid) {
  ModelConfig c = testing::small_bruneton_config();
  c.wavelengths = std::move(grid);
  return c;
}

TEST(Elek, IdenticalToBrunetonOnThePaperGrid) {
  // Identity holds at any resolution: the smallest tables keep the test fast.
  ModelConfig config = reduced(WavelengthGrid::paper_bins());
  config.options["table_r_size"] = 4;
  config.options["table_mu_size"] = 8;
  config.options["table_mu_s_size"] = 4;
  const ModelFactory* elek = find_model("elek");
  const ModelFactory* bruneton = find_model("bruneton");
  ASSERT_NE(elek, nullptr);
  ASSERT_NE(bruneton, nullptr);
  const auto e = elek->create(config, {});
  const auto b = bruneton->create(config, {});
  EXPECT_EQ(e->descriptor().id, "elek");
  EXPECT_EQ(b->descriptor().id, "bruneton");
  const std::vector<ViewDirection> views = {{0.0, 0.0},
                                            {degrees_to_radians(45.0), 1.0},
                                            {degrees_to_radians(89.0), 4.0},
                                            {degrees_to_radians(120.0), 2.0}};
  for (double sun_zenith : {10.0, 60.0, 95.0}) {
    const auto sun_e = e->prepare_sun({degrees_to_radians(sun_zenith), 0.3});
    const auto sun_b = b->prepare_sun({degrees_to_radians(sun_zenith), 0.3});
    SpectralBatch le, lb;
    e->sky_radiance(*sun_e, {250.0}, views, le);
    b->sky_radiance(*sun_b, {250.0}, views, lb);
    EXPECT_EQ(le.values, lb.values) << sun_zenith;
    EXPECT_EQ(le.status, lb.status);
    EXPECT_EQ(e->sun_irradiance(*sun_e, {250.0}).value, b->sun_irradiance(*sun_b, {250.0}).value);
    EXPECT_EQ(e->sky_irradiance(*sun_e, {250.0}).value, b->sky_irradiance(*sun_b, {250.0}).value);
  }
  // Same tables, shared through the cache: an Elek model loads what Bruneton stored (the live
  // models above would otherwise lend theirs: BrunetonTablesInMemory).
  testing::MemoryTableCache cache;
  PrecomputeContext with_cache;
  with_cache.cache = &cache;
  with_cache.reuse_live_tables = false;
  BrunetonModel::create(bruneton_descriptor(), config, with_cache);
  const auto shared = BrunetonModel::create(elek_descriptor(), config, with_cache);
  EXPECT_TRUE(shared->loaded_from_cache());
}

// The extended sun range is an option of Elek too: the same tables as Bruneton with it (one
// precomputation through the cache), the same answers with the sun below 101.39 degrees, and
// the instance's capabilities follow the option while the registry's keep the default.
TEST(Elek, ExtendedSunRangeLikeBruneton) {
  ModelConfig config = reduced(WavelengthGrid::points({450.0, 600.0}));
  config.options["table_r_size"] = 4;
  config.options["table_mu_size"] = 8;
  config.options["table_mu_s_size"] = 8;
  config.options["max_sun_zenith_deg"] = 115.0;
  testing::MemoryTableCache cache;
  PrecomputeContext with_cache;
  with_cache.cache = &cache;
  const auto b = find_model("bruneton")->create(config, with_cache);
  const auto e = find_model("elek")->create(config, with_cache);
  EXPECT_EQ(cache.stores, 1);
  EXPECT_EQ(e->descriptor().id, "elek");
  EXPECT_DOUBLE_EQ(e->descriptor().capabilities.max_sun_zenith_deg, 115.0);
  EXPECT_NEAR(elek_descriptor().capabilities.max_sun_zenith_deg, 101.39, 0.01);
  const std::vector<ViewDirection> views = {{0.0, 0.0}, {degrees_to_radians(89.0), 0.2}};
  for (double sun_zenith : {104.0, 115.0}) {
    const auto sun_e = e->prepare_sun({degrees_to_radians(sun_zenith), 0.0});
    const auto sun_b = b->prepare_sun({degrees_to_radians(sun_zenith), 0.0});
    SpectralBatch le, lb;
    e->sky_radiance(*sun_e, {0.0}, views, le);
    b->sky_radiance(*sun_b, {0.0}, views, lb);
    EXPECT_EQ(le.status[0], SampleStatus::ok);
    EXPECT_EQ(le.values, lb.values) << sun_zenith;
  }
  EXPECT_EQ(e->check_sun({degrees_to_radians(116.0), 0.0}),
            SampleStatus::sun_below_horizon_unsupported);
}

TEST(Elek, DescriptorHasFifteenNativeWavelengths) {
  const ModelDescriptor& d = elek_descriptor();
  ASSERT_EQ(d.native_wavelengths_nm.size(), 15u);
  EXPECT_DOUBLE_EQ(d.native_wavelengths_nm.front(), 360.0);
  EXPECT_DOUBLE_EQ(d.native_wavelengths_nm.back(), 696.0);
  EXPECT_EQ(d.capabilities.max_sun_zenith_deg,
            bruneton_descriptor().capabilities.max_sun_zenith_deg);
  EXPECT_TRUE(d.capabilities.view_from_space);
  EXPECT_TRUE(d.capabilities.aerial_perspective);
  EXPECT_NE(d.citation, bruneton_descriptor().citation);
  EXPECT_THROW(elek_original_rgb(Spectrum(40, 1.0)), std::invalid_argument);
}

// The original RGB output (15 wavelengths converted at the end) against the colour of the
// same sky computed on the paper's 40 wavelengths: the paper finds no significant difference
// between 40 and 15 wavelengths; here each channel agrees within 3%.
TEST(Elek, OriginalRgbFromFifteenWavelengthsMatchesFortyWavelengthColour) {
  const ModelFactory* elek = find_model("elek");
  const auto native = elek->create(reduced(elek_native_grid()), {});
  const auto spectral = elek->create(reduced(WavelengthGrid::paper_bins()), {});
  const std::vector<ViewDirection> views = {
      {0.0, 0.0}, {degrees_to_radians(60.0), 2.5}, {degrees_to_radians(80.0), 0.5}};
  const auto sun_native = native->prepare_sun({degrees_to_radians(40.0), 0.0});
  const auto sun_spectral = spectral->prepare_sun({degrees_to_radians(40.0), 0.0});
  SpectralBatch l15, l40;
  native->sky_radiance(*sun_native, {0.0}, views, l15);
  spectral->sky_radiance(*sun_spectral, {0.0}, views, l40);
  for (std::size_t i = 0; i < views.size(); ++i) {
    const auto s15 = l15.spectrum(i);
    const auto s40 = l40.spectrum(i);
    const LinearSrgb original =
        elek_original_rgb(Spectrum(std::vector<double>(s15.begin(), s15.end())));
    const LinearSrgb reference = spectrum_to_linear_srgb(
        Spectrum(std::vector<double>(s40.begin(), s40.end())), WavelengthGrid::paper_bins());
    EXPECT_NEAR(original.r / reference.r, 1.0, 0.03) << i;
    EXPECT_NEAR(original.g / reference.g, 1.0, 0.03) << i;
    EXPECT_NEAR(original.b / reference.b, 1.0, 0.03) << i;
  }
}

}  // namespace
}  // namespace clearsky
