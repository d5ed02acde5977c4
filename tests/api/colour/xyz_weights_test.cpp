// XyzWeights::xyz_of_rows (api/colour/xyz_weights.h): the XYZ of many spectra at once, bit for
// bit xyz() of each, on the paper's 40 bins, the draft's interpolating weights on 9 wavelengths
// and grids whose length is no multiple of 4, for batches of every count up to 11 (the AVX2 pass
// takes four spectra at a time and leaves the rest to xyz()).
#include "api/colour/xyz_weights.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace clearsky::api {
namespace {

void expect_rows_as_single(const XyzWeights& weights, std::size_t length) {
  std::mt19937_64 random(length);
  std::uniform_real_distribution<double> value(0.0, 2.0);
  for (std::size_t count = 0; count <= 11; ++count) {
    std::vector<double> spectra(count * length);
    for (double& v : spectra) v = value(random) * std::pow(10.0, value(random) * 3.0 - 3.0);
    // A -0, a 0 and a large value: the sums start from 0 as xyz()'s do.
    if (!spectra.empty()) spectra[0] = -0.0;
    if (spectra.size() > 2) spectra[2] = 0.0;
    if (spectra.size() > 5) spectra[5] = 1e30;
    std::vector<Xyz> rows(count);
    weights.xyz_of_rows(spectra.data(), length, count, rows.data());
    for (std::size_t j = 0; j < count; ++j) {
      const Xyz single = weights.xyz({spectra.data() + j * length, length});
      EXPECT_EQ(std::bit_cast<std::uint64_t>(rows[j].x), std::bit_cast<std::uint64_t>(single.x))
          << "length " << length << ", count " << count << ", spectrum " << j;
      EXPECT_EQ(std::bit_cast<std::uint64_t>(rows[j].y), std::bit_cast<std::uint64_t>(single.y))
          << "length " << length << ", count " << count << ", spectrum " << j;
      EXPECT_EQ(std::bit_cast<std::uint64_t>(rows[j].z), std::bit_cast<std::uint64_t>(single.z))
          << "length " << length << ", count " << count << ", spectrum " << j;
    }
  }
}

TEST(XyzWeights, RowsGiveTheBitsOfEachSpectrumAlone) {
  expect_rows_as_single(XyzWeights(WavelengthGrid::paper_bins()), 40);
  for (std::size_t n : {1u, 3u, 5u, 9u, 13u}) {
    std::vector<double> nm;
    for (std::size_t i = 0; i < n; ++i) nm.push_back(380.0 + 35.0 * static_cast<double>(i));
    const WavelengthGrid grid = WavelengthGrid::points(nm);
    expect_rows_as_single(XyzWeights(grid), n);
    expect_rows_as_single(XyzWeights::interpolating(grid), n);
  }
}

}  // namespace
}  // namespace clearsky::api
