// Nishita96's per-sun table sets in the disk table cache (models/nishita96/nishita96_sun_tables_blob.h,
// docs/tables-and-memory.md "Per-sun states"): with sun buckets, a table set computed by one
// model is stored, and a second model on the same cache folder (another server process) answers
// that sun without computing, with the same numbers, near the horizon too (the grazing layouts);
// a truncated file is computed again and replaced; an exact sun is never stored. Cheap 9-node
// tables on 3 wavelengths.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "models/core/numeric.h"
#include "models/nishita96/nishita96.h"
#include "server/cache/file_table_cache.h"
#include "tests/support/temp_dir.h"

namespace clearsky::server {
namespace {

ModelConfig cheap_nishita96(double bucket_deg) {
  ModelConfig config;
  config.wavelengths = WavelengthGrid::points({440.0, 550.0, 680.0});
  config.options["spheres"] = 16;
  config.options["cylinders"] = 16;
  config.options["table_nodes"] = 9;
  config.options["phase_theta_cells"] = 8;
  config.options["sun_zenith_bucket_deg"] = bucket_deg;
  return config;
}

std::vector<double> radiance_at(const SkyModel& model, const SunState& state) {
  const std::vector<ViewDirection> views = {{degrees_to_radians(30.0), degrees_to_radians(10.0)},
                                            {degrees_to_radians(80.0), degrees_to_radians(170.0)}};
  SpectralBatch out;
  model.sky_radiance(state, {}, views, out);
  return out.values;
}

std::size_t files_in(const std::filesystem::path& folder) {
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(folder)) ++files;
  return files;
}

TEST(Nishita96SunTablesCache, ASecondProcessLoadsTheTablesInsteadOfComputingThem) {
  clearsky::testing::TempDir dir;
  const FileTableCache cache(dir.path / "cache");
  PrecomputeContext context;
  context.cache = &cache;
  // 40 degrees: sheared layouts only; 80: the sun's direction in the blend band (both layouts);
  // 89: grazing only.
  const std::vector<SunPosition> suns = {{degrees_to_radians(40.0), degrees_to_radians(120.0)},
                                         {degrees_to_radians(80.0), degrees_to_radians(10.0)},
                                         {degrees_to_radians(89.0), degrees_to_radians(300.0)}};

  const auto first = Nishita96Model::create(cheap_nishita96(2.0));
  std::vector<std::vector<double>> computed;
  for (const SunPosition& sun : suns)
    computed.push_back(radiance_at(*first, *first->prepare_sun(sun, context)));
  EXPECT_EQ(first->sun_states_built(), suns.size());
  EXPECT_EQ(files_in(dir.path / "cache"), suns.size());

  // Another model on the same folder, as a server started later: nothing computed.
  const auto second = Nishita96Model::create(cheap_nishita96(2.0));
  for (std::size_t s = 0; s < suns.size(); ++s)
    EXPECT_EQ(radiance_at(*second, *second->prepare_sun(suns[s], context)), computed[s]) << s;
  EXPECT_EQ(second->sun_states_built(), 0u);

  // Another bucket width is another key: computed.
  const auto other_bucket = Nishita96Model::create(cheap_nishita96(1.0));
  other_bucket->prepare_sun(suns[0], context);
  EXPECT_EQ(other_bucket->sun_states_built(), 1u);

  // A truncated file is a miss: computed again, stored again, then loaded.
  std::size_t damaged = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path / "cache")) {
    std::filesystem::resize_file(entry.path(), std::filesystem::file_size(entry.path()) - 100);
    ++damaged;
  }
  ASSERT_EQ(damaged, suns.size() + 1);
  const auto third = Nishita96Model::create(cheap_nishita96(2.0));
  EXPECT_EQ(radiance_at(*third, *third->prepare_sun(suns[1], context)), computed[1]);
  EXPECT_EQ(third->sun_states_built(), 1u);
  const auto fourth = Nishita96Model::create(cheap_nishita96(2.0));
  EXPECT_EQ(radiance_at(*fourth, *fourth->prepare_sun(suns[1], context)), computed[1]);
  EXPECT_EQ(fourth->sun_states_built(), 0u);
}

TEST(Nishita96SunTablesCache, AnExactSunIsNotStored) {
  clearsky::testing::TempDir dir;
  const FileTableCache cache(dir.path / "cache");
  PrecomputeContext context;
  context.cache = &cache;
  const SunPosition sun{degrees_to_radians(40.0), 0.0};
  Nishita96Model::create(cheap_nishita96(0.0))->prepare_sun(sun, context);
  EXPECT_EQ(files_in(dir.path / "cache"), 0u);
  const auto second = Nishita96Model::create(cheap_nishita96(0.0));
  second->prepare_sun(sun, context);
  EXPECT_EQ(second->sun_states_built(), 1u);
}

}  // namespace
}  // namespace clearsky::server
