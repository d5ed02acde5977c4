// WavelengthGrid: the paper's grid, point grids, integration weights, validation.
#include "models/spectral/wavelength_grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace clearsky {
namespace {

TEST(WavelengthGrid, PaperBinsAre40BinsOf11_75NmFrom360) {
  const WavelengthGrid g = WavelengthGrid::paper_bins();
  ASSERT_EQ(g.size(), 40u);
  EXPECT_DOUBLE_EQ(g[0], 360.0);
  EXPECT_DOUBLE_EQ(g[30], 712.5);  // the last wavelength of the RMSE range
  EXPECT_DOUBLE_EQ(g[39], 818.25);
  EXPECT_DOUBLE_EQ(g.integration_weight_nm(7), 11.75);
  EXPECT_DOUBLE_EQ(g.upper_edge_nm(39), 830.0);
  EXPECT_EQ(g.kind(), WavelengthGrid::Kind::bins);
}

TEST(WavelengthGrid, PointGridUsesTrapezoidWeights) {
  const WavelengthGrid g = WavelengthGrid::points({400.0, 410.0, 430.0});
  EXPECT_DOUBLE_EQ(g.integration_weight_nm(0), 5.0);
  EXPECT_DOUBLE_EQ(g.integration_weight_nm(1), 15.0);
  EXPECT_DOUBLE_EQ(g.integration_weight_nm(2), 10.0);
  EXPECT_EQ(g.index_of(410.0), 1u);
  EXPECT_EQ(g.index_of(411.0), 3u);
}

TEST(WavelengthGrid, RejectsInvalidWavelengths) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(WavelengthGrid::points({}), std::invalid_argument);
  EXPECT_THROW(WavelengthGrid::points({500.0, 400.0}), std::invalid_argument);
  EXPECT_THROW(WavelengthGrid::points({500.0, nan}), std::invalid_argument);
  EXPECT_THROW(WavelengthGrid::points({-1.0}), std::invalid_argument);
  EXPECT_THROW(WavelengthGrid::bins(nan, 10.0, 3), std::invalid_argument);
  EXPECT_THROW(WavelengthGrid::bins(360.0, 0.0, 3), std::invalid_argument);
  EXPECT_THROW(WavelengthGrid::bins(360.0, 10.0, 0), std::invalid_argument);
}

TEST(WavelengthGrid, CanonicalStringDistinguishesGrids) {
  EXPECT_EQ(WavelengthGrid::paper_bins().canonical_string(), "bins:360,11.75,40");
  EXPECT_EQ(WavelengthGrid::points({440, 550, 680}).canonical_string(), "points:440,550,680");
  EXPECT_NE(WavelengthGrid::points({440, 550}), WavelengthGrid::points({440, 551}));
}

}  // namespace
}  // namespace clearsky
