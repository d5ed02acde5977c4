// The single-scattering rows that the second order reads (models/bruneton/second_order_rows.h):
// every row that a lookup of J's or the irradiance's profiles touches (found by gather_4d, the
// lookup the precomputation runs) is marked, and at the paper's resolution the first pass
// computes fewer than a quarter of the rows (749 of 4,096).
#include "models/bruneton/second_order_rows.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "models/bruneton/bruneton_tables.h"

namespace clearsky::bruneton {
namespace {

// The rows that gather_4d reads at radius r and the zenith cosines cos_t, any sun cosine and nu
// slice: each pointer of the lookup's list mapped back to its (r, mu) row.
void expect_marked(const HalfTable4D& table, const Resolution& res, const ShellGeometry& g,
                   double r, const std::vector<double>& cos_t, const std::vector<char>& marked,
                   int& lookups) {
  const std::size_t row_size = table.row_texels() * static_cast<std::size_t>(table.stride);
  for (const double mu : cos_t) {
    for (int ms = 0; ms < res.mu_s; ++ms) {
      Coord4 c = coordinates_4d(r, mu, texel_mu_s(ms, res.mu_s, res.sun), 0.0, res, g);
      for (int k = 0; k < res.nu; ++k) {
        c.nu = Axis{k, k, 0.0};
        RowList<std::uint16_t> list;
        gather_4d(table, c, 1.0, list);
        for (const std::uint16_t* row : list.rows) {
          const auto index = static_cast<std::size_t>(row - table.values.data()) / row_size;
          ASSERT_LT(index, marked.size());
          EXPECT_EQ(marked[index], 1) << "r " << r << " mu " << mu << " row " << index;
          ++lookups;
        }
      }
    }
  }
}

void check(const Resolution& res) {
  const ShellGeometry g;
  const std::vector<char> marked = rows_read_by_second_order(res, g);
  ASSERT_EQ(marked.size(), static_cast<std::size_t>(res.r) * res.mu);
  HalfTable4D table;
  table.allocate(res, 8);
  std::fill(table.row_scale.begin(), table.row_scale.end(), 1.0f);
  int lookups = 0;
  // J's profiles: at each layer's radius (clamped to the shell), the sphere's zeniths.
  const std::vector<double> sphere = zenith_cosines(res.sphere_samples, res.sphere_samples);
  for (int layer = 0; layer < res.r; ++layer) {
    const double r = std::clamp(layer_geometry(layer, res.r, g).r, g.bottom_m, g.top_m);
    expect_marked(table, res, g, r, sphere, marked, lookups);
  }
  // The irradiance's profiles: at its table's radii, the upper hemisphere's zeniths.
  const std::vector<double> hemisphere =
      zenith_cosines(res.irradiance_samples / 2, res.irradiance_samples);
  for (int j = 0; j < res.irradiance_r; ++j)
    expect_marked(table, res, g, irradiance_texel_r(j, res.irradiance_r, g), hemisphere, marked,
                  lookups);
  EXPECT_GT(lookups, 0);
}

TEST(SecondOrderRows, EveryRowTheSecondOrderReadsIsMarked) {
  Resolution small;
  small.r = 8;
  small.mu = 32;
  small.mu_s = 8;
  small.nu = 4;
  check(small);
  Resolution twilight = small;
  twilight.sun = SunRange::up_to(110.0 * kPi / 180.0);
  check(twilight);
  Resolution medium;
  medium.r = 16;
  medium.mu = 64;
  medium.mu_s = 4;
  medium.nu = 2;
  check(medium);
  Resolution paper;
  paper.mu_s = 2;  // the axes of r and mu are those of the paper; fewer sun cosines to try
  paper.nu = 2;
  check(paper);
}

TEST(SecondOrderRows, FewerThanAQuarterOfThePaperRows) {
  const Resolution paper;
  const std::vector<char> marked = rows_read_by_second_order(paper, ShellGeometry{});
  const auto count = std::count(marked.begin(), marked.end(), 1);
  // At most 16 zeniths x 2 mu rows per layer for J (fewer: zeniths share rows), and the
  // irradiance's 16 upper zeniths at radii between two layers: 749 of 4,096 rows.
  EXPECT_GT(count, 0);
  EXPECT_LT(count, static_cast<long>(marked.size()) / 4) << count << " of " << marked.size();
  RecordProperty("rows", static_cast<int>(count));
}

TEST(SecondOrderRows, ZenithCosinesAreTheMidpointsOfEqualAngles) {
  const std::vector<double> cos_t = zenith_cosines(8, 16);
  ASSERT_EQ(cos_t.size(), 8u);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(cos_t[i], std::cos((i + 0.5) * (kPi / 16)));
}

}  // namespace
}  // namespace clearsky::bruneton
