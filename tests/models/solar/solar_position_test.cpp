// Solar position and sunrise/transit/sunset against published values: the SPA report's example
// (Reda and Andreas 2004, appendix A.5) and the Kider et al. 2014 capture site of the study
// (Cornell, Ithaca NY, 2013-05-27; models/evaluation/README.md), plus physical consistency checks,
// polar day and night, and validation.
#include "models/solar/solar_position.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace clearsky {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// 2003-10-17 12:30:30 -07:00, Golden, Colorado: the report's example.
SolarPositionInput spa_example() {
  SolarPositionInput in;
  in.unix_time_utc_s = 1066419030.0;
  in.latitude_deg = 39.742476;
  in.longitude_deg = -105.1786;
  in.elevation_m = 1830.14;
  in.pressure_mbar = 820.0;
  in.temperature_c = 11.0;
  in.delta_t_s = 67.0;
  in.delta_ut1_s = 0.0;
  in.refraction = true;
  in.atmospheric_refraction_at_horizon_deg = 0.5667;
  return in;
}

// The Kider et al. capture site, refraction off as in the study; times in EDT (UTC-4).
SolarPositionInput kider_site(double unix_s) {
  SolarPositionInput in;
  in.unix_time_utc_s = unix_s;
  in.latitude_deg = 42.443449;
  in.longitude_deg = -76.481962;
  in.elevation_m = 0.0;
  in.refraction = false;
  return in;
}

// Local clock time of day in seconds of a unix instant at a UTC offset.
double local_seconds_of_day(double unix_s, double offset_h) {
  const double local = unix_s + offset_h * 3600.0;
  return local - 86400.0 * std::floor(local / 86400.0);
}

constexpr double hms(int h, int m, int s) { return h * 3600.0 + m * 60.0 + s; }

// Angle between two directions given by zenith and azimuth (degrees).
double angular_separation_deg(double zenith1, double azimuth1, double zenith2, double azimuth2) {
  const double d = std::numbers::pi / 180.0;
  const double cosine =
      std::cos(zenith1 * d) * std::cos(zenith2 * d) +
      std::sin(zenith1 * d) * std::sin(zenith2 * d) * std::cos((azimuth1 - azimuth2) * d);
  return std::acos(std::min(1.0, cosine)) / d;
}

TEST(SolarPosition, ReportExampleZenithAndAzimuth) {
  const SolarPosition p = solar_position(spa_example());
  // Published to 5 decimals; the report's stated uncertainty is 0.0003 degrees.
  EXPECT_NEAR(p.zenith_deg, 50.11162, 1e-5);
  EXPECT_NEAR(p.azimuth_deg, 194.34024, 1e-5);
  EXPECT_NEAR(p.refraction_correction_deg, 0.016332, 1e-6);
  EXPECT_NEAR(p.declination_deg, -9.316179, 1e-6);
  EXPECT_NEAR(p.hour_angle_deg, 11.10627, 1e-5);
}

// The report publishes sunrise 06:12:43, transit 11:46:04 and sunset 17:20:19 local (-07:00).
// Its sunset is reduced to the UT day 2003-10-17, i.e. it is the sunset of the evening of
// October 16 local; sun_times gives it for that local date, and for October 17 the sunset of
// that evening, where the sun's centre is at the sunrise/sunset altitude.
TEST(SolarPosition, ReportExampleSunriseTransitSunset) {
  constexpr double kLocalMidnight = 1066374000.0;  // 2003-10-17T00:00:00-07:00
  const SunTimes times = sun_times(spa_example(), -7.0);
  ASSERT_TRUE(times.sunrise_utc_s && times.transit_utc_s && times.sunset_utc_s);
  EXPECT_EQ(times.day_kind, DayKind::normal);
  EXPECT_NEAR(*times.sunrise_utc_s - kLocalMidnight, hms(6, 12, 43), 1.0);
  EXPECT_NEAR(*times.transit_utc_s - kLocalMidnight, hms(11, 46, 4), 1.0);

  SolarPositionInput previous_day = spa_example();
  previous_day.unix_time_utc_s -= 86400.0;
  const SunTimes before = sun_times(previous_day, -7.0);
  ASSERT_TRUE(before.sunset_utc_s);
  EXPECT_NEAR(*before.sunset_utc_s - (kLocalMidnight - 86400.0), hms(17, 20, 19), 1.0);

  // October 17's own sunset, about 1.4 minutes earlier.
  EXPECT_NEAR(*times.sunset_utc_s - kLocalMidnight, hms(17, 18, 55), 30.0);
  SolarPositionInput at_sunset = spa_example();
  at_sunset.refraction = false;
  at_sunset.unix_time_utc_s = *times.sunset_utc_s;
  EXPECT_NEAR(solar_position(at_sunset).zenith_deg, 90.83337, 0.01);
}

// The study computed these with the PSA algorithm (Blanco-Muriel et al. 2001, stated accuracy
// 0.5 arc minute = 0.0083 degree): 09:30 EDT zenith 48.938, azimuth 98.142; 11:45 EDT zenith
// 26.654, azimuth 136.065. SPA's directions lie within PSA's accuracy of them.
TEST(SolarPosition, KiderSite0930And1145EdtAgreeWithTheStudysPsaValues) {
  struct Case {
    double unix_s, zenith_deg, azimuth_deg;
  };
  for (const Case& c : {Case{1369661400.0, 48.938, 98.142},      // 2013-05-27T13:30:00Z
                        Case{1369669500.0, 26.654, 136.065}}) {  // 2013-05-27T15:45:00Z
    const SolarPosition p = solar_position(kider_site(c.unix_s));
    EXPECT_DOUBLE_EQ(p.refraction_correction_deg, 0.0);
    EXPECT_NEAR(p.zenith_deg, c.zenith_deg, 0.005);
    EXPECT_NEAR(p.azimuth_deg, c.azimuth_deg, 0.015);
    EXPECT_LT(angular_separation_deg(p.zenith_deg, p.azimuth_deg, c.zenith_deg, c.azimuth_deg),
              0.0083);
  }
}

TEST(SolarPosition, RefractionLiftsTheSunOnlyAboveTheHorizonCutOff) {
  SolarPositionInput in = spa_example();
  in.refraction = false;
  const SolarPosition without = solar_position(in);
  EXPECT_NEAR(spa_example().unix_time_utc_s, in.unix_time_utc_s, 0);
  EXPECT_NEAR(solar_position(spa_example()).zenith_deg, without.zenith_deg - 0.016332, 1e-6);
  EXPECT_DOUBLE_EQ(solar_position(spa_example()).azimuth_deg, without.azimuth_deg);
  // At night (03:00 local) refraction must not apply.
  in.unix_time_utc_s = 1066419030.0 - 9.5 * 3600.0;
  in.refraction = true;
  const SolarPosition night = solar_position(in);
  EXPECT_GT(night.zenith_deg, 120.0);
  EXPECT_DOUBLE_EQ(night.refraction_correction_deg, 0.0);
  // Zero pressure means no atmosphere, hence no refraction.
  in = spa_example();
  in.pressure_mbar = 0.0;
  EXPECT_DOUBLE_EQ(solar_position(in).zenith_deg, without.zenith_deg);
}

// At the computed sunrise and sunset the sun's centre is at -(0.26667 + 0.5667) degrees
// (unrefracted), and at the transit it is on the meridian, due south at these latitudes.
TEST(SolarPosition, SunTimesAreConsistentWithThePosition) {
  SolarPositionInput in = kider_site(1369661400.0);
  const SunTimes times = sun_times(in, -4.0);
  ASSERT_TRUE(times.sunrise_utc_s && times.sunset_utc_s && times.transit_utc_s);
  for (double event : {*times.sunrise_utc_s, *times.sunset_utc_s}) {
    in.unix_time_utc_s = event;
    EXPECT_NEAR(solar_position(in).zenith_deg, 90.83337, 0.01);
  }
  in.unix_time_utc_s = *times.transit_utc_s;
  const SolarPosition transit = solar_position(in);
  EXPECT_NEAR(transit.hour_angle_deg, 0.0, 0.01);
  EXPECT_NEAR(transit.azimuth_deg, 180.0, 0.02);
  // The events lie on the local date (2013-05-27 EDT) in order.
  EXPECT_LT(*times.sunrise_utc_s, *times.transit_utc_s);
  EXPECT_LT(*times.transit_utc_s, *times.sunset_utc_s);
  EXPECT_NEAR(local_seconds_of_day(*times.sunrise_utc_s, -4.0), hms(5, 37, 0), 300.0);
  EXPECT_NEAR(local_seconds_of_day(*times.sunset_utc_s, -4.0), hms(20, 32, 0), 300.0);
}

// Transit = 12:00 mean solar time at the longitude, minus the equation of time.
TEST(SolarPosition, TransitFollowsTheEquationOfTime) {
  const SolarPositionInput in = spa_example();
  const SolarPosition p = solar_position(in);
  const SunTimes times = sun_times(in, -7.0);
  const double expected_local_s =
      hms(12, 0, 0) - in.longitude_deg * 240.0 - 7.0 * 3600.0 - p.equation_of_time_min * 60.0;
  EXPECT_NEAR(local_seconds_of_day(*times.transit_utc_s, -7.0), expected_local_s, 5.0);
}

TEST(SolarPosition, PolarDayAndNightHaveNoSunriseOrSunset) {
  SolarPositionInput in;
  in.unix_time_utc_s = 1687348800.0;  // 2023-06-21T12:00Z
  in.latitude_deg = 80.0;
  in.longitude_deg = 15.0;
  SunTimes times = sun_times(in, 1.0);
  EXPECT_EQ(times.day_kind, DayKind::polar_day);
  EXPECT_FALSE(times.sunrise_utc_s.has_value());
  EXPECT_FALSE(times.sunset_utc_s.has_value());
  ASSERT_TRUE(times.transit_utc_s.has_value());
  in.unix_time_utc_s = *times.transit_utc_s;
  EXPECT_NEAR(solar_position(in).zenith_deg, 80.0 - 23.44, 0.1);

  in.latitude_deg = -80.0;
  times = sun_times(in, 1.0);
  EXPECT_EQ(times.day_kind, DayKind::polar_night);
  EXPECT_FALSE(times.sunrise_utc_s.has_value());
  EXPECT_FALSE(times.sunset_utc_s.has_value());

  // At the poles themselves: the sun circles at constant altitude.
  in.latitude_deg = 90.0;
  times = sun_times(in, 0.0);
  EXPECT_EQ(times.day_kind, DayKind::polar_day);
  EXPECT_FALSE(times.sunrise_utc_s.has_value());
  const SolarPosition pole = solar_position(in);
  EXPECT_TRUE(std::isfinite(pole.azimuth_deg));
  EXPECT_NEAR(pole.zenith_deg, 90.0 - 23.44, 0.05);
  in.latitude_deg = -90.0;
  EXPECT_EQ(sun_times(in, 0.0).day_kind, DayKind::polar_night);
  EXPECT_NEAR(solar_position(in).zenith_deg, 90.0 + 23.44, 0.05);
}

TEST(SolarPosition, OutputsStayInRangeOverADayAndTheYears) {
  SolarPositionInput in = kider_site(0.0);
  for (double unix_s :
       {-125000000000.0, -2208988800.0, 0.0, 1369661400.0, 4102444800.0, 127000000000.0}) {
    for (int hour = 0; hour < 24; hour += 3) {
      in.unix_time_utc_s = unix_s + hour * 3600.0;
      const SolarPosition p = solar_position(in);
      EXPECT_GE(p.zenith_deg, 0.0);
      EXPECT_LE(p.zenith_deg, 180.0);
      EXPECT_GE(p.azimuth_deg, 0.0);
      EXPECT_LT(p.azimuth_deg, 360.0);
      EXPECT_LE(std::abs(p.equation_of_time_min), 20.0);
    }
  }
}

void expect_invalid(SolarPositionInput in, const std::string& name, double offset_h = 0.0) {
  try {
    (void)sun_times(in, offset_h);
    ADD_FAILURE() << "accepted an invalid " << name;
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind(name + ":", 0), 0u) << e.what();
  }
  if (name != "timezone_offset_h") {
    EXPECT_THROW((void)solar_position(in), std::invalid_argument);
  }
}

TEST(SolarPosition, InvalidInputsThrowNamingTheArgument) {
  SolarPositionInput in = spa_example();
  in.latitude_deg = kNaN;
  expect_invalid(in, "latitude_deg");
  in.latitude_deg = 91.0;
  expect_invalid(in, "latitude_deg");
  in = spa_example();
  in.longitude_deg = -180.5;
  expect_invalid(in, "longitude_deg");
  in = spa_example();
  in.unix_time_utc_s = kNaN;
  expect_invalid(in, "unix_time_utc_s");
  in.unix_time_utc_s = 2e11;  // year 8307
  expect_invalid(in, "unix_time_utc_s");
  in = spa_example();
  in.elevation_m = std::numeric_limits<double>::infinity();
  expect_invalid(in, "elevation_m");
  in = spa_example();
  in.pressure_mbar = kNaN;
  expect_invalid(in, "pressure_mbar");
  in = spa_example();
  in.temperature_c = -273.0;
  expect_invalid(in, "temperature_c");
  in = spa_example();
  in.delta_t_s = kNaN;
  expect_invalid(in, "delta_t_s");
  in = spa_example();
  in.delta_ut1_s = 1.0;
  expect_invalid(in, "delta_ut1_s");
  in = spa_example();
  in.atmospheric_refraction_at_horizon_deg = kNaN;
  expect_invalid(in, "atmospheric_refraction_at_horizon_deg");
  expect_invalid(spa_example(), "timezone_offset_h", kNaN);
  expect_invalid(spa_example(), "timezone_offset_h", 19.0);
}

}  // namespace
}  // namespace clearsky
