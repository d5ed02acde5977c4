// Haber's per-sun domes in the disk table cache (models/haber/haber_dome_blob.h,
// docs/tables-and-memory.md "Per-sun states"): a dome computed by one model is stored, and a
// second model on the same cache folder (another server process) answers that sun without
// computing, with the same numbers; a damaged file is computed again and replaced. Cheap
// 24-sector grid on 3 wavelengths.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "models/core/numeric.h"
#include "models/haber/haber.h"
#include "server/cache/file_table_cache.h"
#include "tests/support/temp_dir.h"

namespace clearsky::server {
namespace {

ModelConfig cheap_haber() {
  ModelConfig config;
  config.wavelengths = WavelengthGrid::points({440.0, 550.0, 680.0});
  config.options["azimuth_sectors"] = 24;
  return config;
}

std::vector<double> radiance_at(const SkyModel& model, const SunState& state) {
  const std::vector<ViewDirection> views = {{degrees_to_radians(30.0), degrees_to_radians(10.0)},
                                            {degrees_to_radians(80.0), degrees_to_radians(170.0)}};
  SpectralBatch out;
  model.sky_radiance(state, {}, views, out);
  return out.values;
}

TEST(HaberDomeCache, ASecondProcessLoadsTheDomeInsteadOfComputingIt) {
  clearsky::testing::TempDir dir;
  const FileTableCache cache(dir.path / "cache");
  PrecomputeContext context;
  context.cache = &cache;
  const SunPosition sun{degrees_to_radians(40.0), degrees_to_radians(120.0)};

  const auto first = haber::HaberModel::create(cheap_haber());
  const auto computed = first->prepare_sun(sun, context);
  EXPECT_EQ(first->sun_states_built(), 1u);

  // Another model on the same folder, as a server started later: nothing computed.
  const auto second = haber::HaberModel::create(cheap_haber());
  const auto loaded = second->prepare_sun(sun, context);
  EXPECT_EQ(second->sun_states_built(), 0u);
  EXPECT_EQ(radiance_at(*second, *loaded), radiance_at(*first, *computed));

  // Without the cache a model computes, whatever the folder holds.
  const auto uncached = haber::HaberModel::create(cheap_haber());
  uncached->prepare_sun(sun);
  EXPECT_EQ(uncached->sun_states_built(), 1u);

  // A damaged file (truncated) is a miss: computed again, stored again, then loaded.
  std::size_t damaged = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path / "cache")) {
    const auto size = std::filesystem::file_size(entry.path());
    std::filesystem::resize_file(entry.path(), size - 100);
    ++damaged;
  }
  ASSERT_EQ(damaged, 1u);
  const auto third = haber::HaberModel::create(cheap_haber());
  const auto recomputed = third->prepare_sun(sun, context);
  EXPECT_EQ(third->sun_states_built(), 1u);
  EXPECT_EQ(radiance_at(*third, *recomputed), radiance_at(*first, *computed));
  const auto fourth = haber::HaberModel::create(cheap_haber());
  fourth->prepare_sun(sun, context);
  EXPECT_EQ(fourth->sun_states_built(), 0u);
}

}  // namespace
}  // namespace clearsky::server
