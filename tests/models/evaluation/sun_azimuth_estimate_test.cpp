// Tests of the hemispherical interpolation of a measured sky and of the sun-azimuth estimate
// from its mirror symmetry (models/evaluation/sun_azimuth_estimate.h), on synthetic skies.
#include "models/evaluation/sun_azimuth_estimate.h"

#include <gtest/gtest.h>

#include <cmath>

#include "models/evaluation/concentric_sky_interpolant.h"
#include "models/evaluation/sample_repair.h"
#include "tests/models/evaluation/synthetic_sky.h"

namespace clearsky {
namespace {

ConcentricSkyInterpolant<double> interpolant_of(const MeasuredCapture& capture, double nm) {
  const auto rings = arrange_concentric_rings(capture.samples);
  std::array<std::vector<double>, kConcentricRingCount> values;
  for (int k = 0; k < kConcentricRingCount; ++k)
    for (std::size_t s : rings[k]) values[k].push_back(capture.samples[s].radiance.at(nm, OutOfRange::error));
  return ConcentricSkyInterpolant<double>(std::move(values));
}

double bump(const ViewDirection& v, double) {
  return 0.1 + 0.05 * std::cos(v.zenith_rad) + 0.03 * std::sin(v.zenith_rad) * std::cos(v.azimuth_rad - 1.0);
}

TEST(ConcentricSkyInterpolant, ReproducesTheSamplesAndConstants) {
  const MeasuredCapture capture = testing::synthetic_capture(bump);
  const auto sky = interpolant_of(capture, 500);
  for (const MeasuredSample& s : capture.samples) EXPECT_NEAR(sky(s.view), bump(s.view, 500), 1e-12);
  const auto flat = interpolant_of(testing::synthetic_capture([](const ViewDirection&, double) { return 0.25; }), 500);
  for (double zenith_deg : {0.0, 5.0, 30.0, 60.0, 85.0, 90.0})
    for (double azimuth_deg : {-30.0, 0.0, 77.0, 200.0, 359.0, 400.0})
      EXPECT_NEAR(flat({zenith_deg * kDegree, azimuth_deg * kDegree}), 0.25, 1e-12);
}

TEST(ConcentricSkyInterpolant, IsCloseToASmoothSkyBetweenSamples) {
  const auto sky = interpolant_of(testing::synthetic_capture(bump), 500);
  for (double zenith_deg : {3.0, 25.0, 47.0, 70.0, 84.0})
    for (double azimuth_deg : {10.0, 100.0, 190.0, 280.0})
      EXPECT_NEAR(sky({zenith_deg * kDegree, azimuth_deg * kDegree}), bump({zenith_deg * kDegree, azimuth_deg * kDegree}, 500),
                  2e-3);
}

TEST(ConcentricSkyInterpolant, RefusesAnotherLayout) {
  MeasuredCapture capture = testing::synthetic_capture(bump);
  capture.samples[10].view.azimuth_rad += 1.0 * kDegree;
  EXPECT_THROW(arrange_concentric_rings(capture.samples), std::invalid_argument);
  capture = testing::synthetic_capture(bump);
  capture.samples.pop_back();
  EXPECT_THROW(arrange_concentric_rings(capture.samples), std::invalid_argument);
}

// A sky symmetric about the vertical plane of azimuth axis_deg, brighter towards it.
testing::SkyFunction symmetric_sky(double axis_deg) {
  return [axis_deg](const ViewDirection& v, double nm) {
    const double c = std::cos(v.azimuth_rad - axis_deg * kDegree);
    return (0.05 + 0.04 * std::sin(v.zenith_rad) * (c + 0.3 * c * c)) * (1.0 + 1e-3 * (nm - 500));
  };
}

TEST(SunAzimuthEstimate, FindsTheSymmetryAxisOfASymmetricSky) {
  for (double axis_deg : {101.0, 128.4, 215.2}) {
    const MeasuredCapture capture = testing::synthetic_capture(symmetric_sky(axis_deg));
    const SunAzimuthEstimate e = estimate_sun_azimuth(capture, axis_deg + 7.0);
    EXPECT_NEAR(e.azimuth_deg, axis_deg, 0.2 + 1e-9) << axis_deg;
    EXPECT_EQ(e.candidates, 201);
  }
}

TEST(SunAzimuthEstimate, CandidatesAreOnTheStepGridAroundTheComputedAzimuth) {
  // The axis 90 (a symmetry axis of the sample layout, so exactly symmetric once interpolated)
  // is a candidate when searching around 96 (96 - 20 + 70 * 0.2).
  const SunAzimuthEstimate e = estimate_sun_azimuth(testing::synthetic_capture(symmetric_sky(90.0)), 96.0);
  EXPECT_NEAR(e.azimuth_deg, 90.0, 1e-9);
  EXPECT_NEAR(e.symmetry_error, 0.0, 1e-9);
  // Outside the search range the estimate stops at the nearest end.
  EXPECT_NEAR(estimate_sun_azimuth(testing::synthetic_capture(symmetric_sky(100.0)), 130.0).azimuth_deg, 110.0, 1e-9);
}

TEST(SunAzimuthEstimate, WrapsAroundNorth) {
  const SunAzimuthEstimate e = estimate_sun_azimuth(testing::synthetic_capture(symmetric_sky(2.0)), 355.0);
  EXPECT_NEAR(e.azimuth_deg, 2.0, 0.2 + 1e-9);
}

TEST(SampleRepair, ReplacesTheDefectiveSampleByTheMeanOfItsRingNeighbours) {
  MeasuredCapture capture = testing::synthetic_capture(bump);
  // Ring 4 (32 samples) starts at index 1 + 8 + 16 + 24 = 49; its North sample is 49, the
  // neighbours 50 (11.25 deg) and 80 (348.75 deg).
  MeasuredSample& north = capture.samples[49];
  ASSERT_NEAR(north.view.azimuth_rad, 0.0, 1e-12);
  north.radiance = north.radiance.scaled(3.0);
  north.quality_flags |= kSampleKnownDefective;
  EXPECT_EQ(repair_defective_samples(capture), 1);
  const double expected = 0.5 * (capture.samples[50].radiance.at(600, OutOfRange::error) +
                                 capture.samples[80].radiance.at(600, OutOfRange::error));
  EXPECT_NEAR(capture.samples[49].radiance.at(600, OutOfRange::error), expected, 1e-15);
  EXPECT_TRUE(capture.samples[49].quality_flags & kSampleRepaired);
  ASSERT_EQ(capture.processing_steps.size(), 1u);
  EXPECT_NE(capture.processing_steps[0].find("ring neighbours 80 and 50"), std::string::npos)
      << capture.processing_steps[0];
  EXPECT_EQ(capture.samples.size(), 81u);
  // A second call repairs nothing.
  EXPECT_EQ(repair_defective_samples(capture), 0);
}

TEST(MeasuredSky, LocalTimeWithOffset) {
  EXPECT_EQ(local_time_iso8601(1369661400.0, -240), "2013-05-27T09:30:00-04:00");
  EXPECT_EQ(local_time_iso8601(1369661400.0, 0), "2013-05-27T13:30:00+00:00");
  EXPECT_EQ(local_time_iso8601(1369661400.0, 330), "2013-05-27T19:00:00+05:30");
}

}  // namespace
}  // namespace clearsky
