// Tests of the preparation of measured captures (models/evaluation/capture_preparation.h): the
// sun azimuth is estimated from the mirror symmetry on Kider's 81-direction layout only.
#include "models/evaluation/capture_preparation.h"

#include <gtest/gtest.h>

#include <cmath>

#include "models/evaluation/concentric_sky_interpolant.h"
#include "tests/models/evaluation/synthetic_sky.h"

namespace clearsky {
namespace {

// A sky symmetric about the vertical plane of azimuth 120 degrees.
double symmetric_sky(const ViewDirection& view, double nm) {
  return 0.05 + 0.02 * std::cos(view.azimuth_rad - 120.0 * kDegree) * std::sin(view.zenith_rad) +
         1e-5 * (nm - 500);
}

TEST(PrepareCapture, EstimatesTheSunAzimuthOnTheConcentricLayoutOnly) {
  MeasuredCapture kider = testing::synthetic_capture(symmetric_sky, 40.0, 125.0);
  kider.sun_azimuth_estimated_deg = kNotComputed;
  ASSERT_TRUE(is_concentric_layout(kider.samples));
  prepare_capture(kider);
  EXPECT_NEAR(kider.sun_azimuth_estimated_deg, 120.0, 0.2);

  // The same sky without its last ring sample: another layout, the computed azimuth stays.
  MeasuredCapture other = testing::synthetic_capture(symmetric_sky, 40.0, 125.0);
  other.sun_azimuth_estimated_deg = kNotComputed;
  other.samples.pop_back();
  EXPECT_FALSE(is_concentric_layout(other.samples));
  prepare_capture(other);
  EXPECT_TRUE(std::isnan(other.sun_azimuth_estimated_deg));
  EXPECT_DOUBLE_EQ(other.sun_azimuth_computed_deg, 125.0);
  ASSERT_FALSE(other.processing_steps.empty());
  EXPECT_NE(other.processing_steps.back().find("sun azimuth not estimated"), std::string::npos)
      << other.processing_steps.back();
}

}  // namespace
}  // namespace clearsky
