// The byte form of a Nishita96 per-sun table set (models/nishita96/nishita96_sun_tables_blob.h):
// it reads back bit for bit, and bytes of another sun, node count or length are refused, never
// read as tables.
#include "models/nishita96/nishita96_sun_tables_blob.h"

#include <gtest/gtest.h>

#include "models/core/numeric.h"
#include "models/nishita96/nishita96.h"

namespace clearsky::nishita96 {
namespace {

TEST(Nishita96SunTablesBlob, ReadsBackBitForBitAndRefusesAnythingElse) {
  ModelConfig config;
  config.wavelengths = WavelengthGrid::points({440.0, 550.0, 680.0});
  config.options["spheres"] = 16;
  config.options["cylinders"] = 16;
  const auto model = Nishita96Model::create(config);
  const double zenith = degrees_to_radians(80.0);  // the sun's direction in the blend band
  const int nodes = 9;
  const auto tables =
      build_sun_tables(model->optical_lengths(), model->atmosphere(), zenith, nodes, 8, {});
  const std::string bytes = sun_tables_to_bytes(*tables);

  const auto loaded = sun_tables_from_bytes(bytes, model->atmosphere(), zenith, nodes, 8);
  ASSERT_NE(loaded, nullptr);
  for (int k = 0; k < kSamplingDirections; ++k) {
    const auto& a = tables->table(k);
    const auto& b = loaded->table(k);
    EXPECT_EQ(b.angle_rad(), a.angle_rad()) << k;
    EXPECT_TRUE(std::equal(a.sheared_values().begin(), a.sheared_values().end(),
                           b.sheared_values().begin(), b.sheared_values().end()))
        << k;
    EXPECT_TRUE(std::equal(a.grazing_values().begin(), a.grazing_values().end(),
                           b.grazing_values().begin(), b.grazing_values().end()))
        << k;
  }
  bool blended = false;
  for (int k = 0; k < kSamplingDirections; ++k)
    blended = blended || (tables->table(k).has_grazing() && tables->table(k).has_sheared());
  EXPECT_TRUE(blended);

  const auto& atmosphere = model->atmosphere();
  EXPECT_EQ(sun_tables_from_bytes(bytes.substr(0, bytes.size() - 4), atmosphere, zenith, nodes, 8),
            nullptr);
  EXPECT_EQ(sun_tables_from_bytes(bytes + "x", atmosphere, zenith, nodes, 8), nullptr);
  EXPECT_EQ(sun_tables_from_bytes(bytes, atmosphere, zenith + 1e-9, nodes, 8), nullptr);
  EXPECT_EQ(sun_tables_from_bytes(bytes, atmosphere, zenith, 11, 8), nullptr);
  EXPECT_EQ(sun_tables_from_bytes("", atmosphere, zenith, nodes, 8), nullptr);
}

}  // namespace
}  // namespace clearsky::nishita96
