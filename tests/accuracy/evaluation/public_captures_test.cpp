// The 15 public captures as the accuracy tests see them (tests/support/public_captures.h):
// complete, repaired, with SPA sun zeniths and estimated azimuths matching the 2016 study's
// (models/evaluation/README.md: 09:30 zenith 48.938, azimuth 91.142 estimated; 11:45
// zenith 26.654, azimuth 122.265 estimated). Prints the estimate of every capture.
#include "tests/support/public_captures.h"

#include <gtest/gtest.h>

#include <cstdio>

#include "tests/support/shared_data.h"

namespace clearsky {
namespace {

const MeasuredCapture& capture_at(const std::string& label) {
  for (const auto& c : testing::public_captures())
    if (c.label == label) return c;
  throw std::out_of_range("no capture " + label);
}

TEST(PublicCaptures, FifteenCompleteRepairedCaptures) {
  CLEARSKY_REQUIRE_SHARED_DATA("kider2014/2013-05-27/RADIANCE");
  const auto& captures = testing::public_captures();
  ASSERT_EQ(captures.size(), 15u);
  for (const auto& c : captures) {
    EXPECT_EQ(c.samples.size(), 81u) << c.label;
    EXPECT_EQ(c.samples[0].quality_flags, kSampleKnownDefective | kSampleRepaired) << c.label;
    EXPECT_EQ(c.processing_steps.size(), 3u) << c.label;
    std::printf("%s  sun zenith %.3f  azimuth computed %.3f  estimated %.3f (%+.1f)\n",
                local_time_iso8601(c).c_str(), c.sun_zenith_computed_deg,
                c.sun_azimuth_computed_deg, c.sun_azimuth_estimated_deg,
                c.sun_azimuth_estimated_deg - c.sun_azimuth_computed_deg);
  }
  EXPECT_EQ(local_time_iso8601(captures.front()), "2013-05-27T09:30:00-04:00");
  EXPECT_EQ(local_time_iso8601(captures.back()), "2013-05-27T13:30:00-04:00");
  // As imported, sample 0 is kept as measured.
  EXPECT_EQ(testing::public_captures_as_imported()[0].samples[0].quality_flags,
            kSampleKnownDefective);
  const auto timing = testing::public_captures_timing();
  std::printf("import %.2f s, preparation %.2f s\n", timing.import_seconds, timing.prepare_seconds);
}

TEST(PublicCaptures, SunPositionsMatchTheStudy) {
  CLEARSKY_REQUIRE_SHARED_DATA("kider2014/2013-05-27/RADIANCE");
  const MeasuredCapture& c0930 = capture_at("2013-05-27___09.30.00");
  EXPECT_NEAR(c0930.sun_zenith_computed_deg, 48.938, 0.005);
  EXPECT_NEAR(c0930.sun_azimuth_computed_deg, 98.142, 0.015);
  EXPECT_NEAR(c0930.sun_azimuth_estimated_deg, 91.142, 0.2);
  const MeasuredCapture& c1145 = capture_at("2013-05-27___11.45.00");
  EXPECT_NEAR(c1145.sun_zenith_computed_deg, 26.654, 0.005);
  EXPECT_NEAR(c1145.sun_azimuth_computed_deg, 136.065, 0.015);
  EXPECT_NEAR(c1145.sun_azimuth_estimated_deg, 122.265, 0.2);
}

}  // namespace
}  // namespace clearsky
