// TabulatedSpectrum: interpolation, exact bin averages, out-of-range policies, table reader.
#include "models/spectral/tabulated_spectrum.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace clearsky {
namespace {

const TabulatedSpectrum kRamp({400.0, 500.0, 600.0}, {1.0, 3.0, 2.0});

TEST(TabulatedSpectrum, InterpolatesLinearly) {
  EXPECT_DOUBLE_EQ(kRamp.at(450.0, OutOfRange::error), 2.0);
  EXPECT_DOUBLE_EQ(kRamp.at(400.0, OutOfRange::error), 1.0);
  EXPECT_DOUBLE_EQ(kRamp.at(600.0, OutOfRange::error), 2.0);
  EXPECT_DOUBLE_EQ(kRamp.at(575.0, OutOfRange::error), 2.25);
}

// Values near the largest double of opposite signs: their difference overflows, and the
// interpolation must still give each node's value and a finite value between them.
TEST(TabulatedSpectrum, InterpolatesValuesWhoseDifferenceOverflows) {
  const double big = std::numeric_limits<double>::max();
  const TabulatedSpectrum extreme({0.0, 1.0, 2.0}, {big, -0.5 * big, 1.0});
  EXPECT_EQ(extreme.at(0.0, OutOfRange::error), big);
  EXPECT_EQ(extreme.at(1.0, OutOfRange::error), -0.5 * big);
  const double between = extreme.at(0.5, OutOfRange::error);
  EXPECT_TRUE(std::isfinite(between));
  EXPECT_DOUBLE_EQ(between, 0.25 * big);
}

// Wavelengths near the largest double of opposite signs (a forged blob; fuzz/corpus/sample_blob/
// overflowing-span): their span overflows, and the interpolation must still give each node's
// value at the node and the midpoint's value halfway.
TEST(TabulatedSpectrum, InterpolatesOverWavelengthsWhoseSpanOverflows) {
  const double big = std::numeric_limits<double>::max();
  const TabulatedSpectrum wide({-0.75 * big, 0.75 * big}, {2.0, 4.0});
  EXPECT_EQ(wide.at(-0.75 * big, OutOfRange::error), 2.0);
  EXPECT_EQ(wide.at(0.75 * big, OutOfRange::error), 4.0);
  EXPECT_DOUBLE_EQ(wide.at(0.0, OutOfRange::error), 3.0);
}

TEST(TabulatedSpectrum, OutOfRangePolicyIsExplicit) {
  EXPECT_DOUBLE_EQ(kRamp.at(300.0, OutOfRange::hold_end_values), 1.0);
  EXPECT_DOUBLE_EQ(kRamp.at(700.0, OutOfRange::hold_end_values), 2.0);
  EXPECT_DOUBLE_EQ(kRamp.at(700.0, OutOfRange::zero), 0.0);
  EXPECT_THROW(kRamp.at(700.0, OutOfRange::error), std::out_of_range);
  EXPECT_THROW(kRamp.bin_average(550.0, 650.0, OutOfRange::error), std::out_of_range);
}

TEST(TabulatedSpectrum, BinAverageIsTheExactMeanOfThePiecewiseLinearFunction) {
  // Over [450, 550]: trapezoids (2+3)/2*50 + (3+2.5)/2*50 = 262.5, mean 2.625.
  EXPECT_DOUBLE_EQ(kRamp.bin_average(450.0, 550.0, OutOfRange::error), 2.625);
  EXPECT_DOUBLE_EQ(kRamp.integral(400.0, 600.0, OutOfRange::error), 450.0);
  // Held beyond the end: [600, 700] at 2 adds 200.
  EXPECT_DOUBLE_EQ(kRamp.integral(400.0, 700.0, OutOfRange::hold_end_values), 650.0);
  EXPECT_DOUBLE_EQ(kRamp.integral(400.0, 700.0, OutOfRange::zero), 450.0);
}

TEST(TabulatedSpectrum, ResamplesPointOrBinAverage) {
  const WavelengthGrid bins = WavelengthGrid::bins(400.0, 100.0, 2);
  const Spectrum averages = kRamp.resample(bins, Resampling::bin_average, OutOfRange::error);
  EXPECT_DOUBLE_EQ(averages[0], 2.0);
  EXPECT_DOUBLE_EQ(averages[1], 2.5);
  const Spectrum points = kRamp.resample(bins, Resampling::point, OutOfRange::error);
  EXPECT_DOUBLE_EQ(points[0], 1.0);
  EXPECT_DOUBLE_EQ(points[1], 3.0);
}

TEST(NumericTable, ReadsCommentsHeaderAndRows) {
  std::istringstream in("# comment\nwavelength_nm,value\n400,1\n500, 2\n");
  const NumericTable t = read_numeric_table(in, "test.csv");
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.column_index("value"), 1u);
  EXPECT_DOUBLE_EQ(t.spectrum(0, 1).at(450.0, OutOfRange::error), 1.5);
}

TEST(NumericTable, ReportsMalformedRowsWithTheirLine) {
  std::istringstream in("wavelength_nm,value\n400,1\n500,abc\n");
  try {
    read_numeric_table(in, "bad.csv");
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("bad.csv:3"), std::string::npos) << e.what();
  }
  std::istringstream short_row("a,b\n400,1\n500\n");
  EXPECT_THROW(read_numeric_table(short_row, "short.csv"), std::runtime_error);
}

}  // namespace
}  // namespace clearsky
