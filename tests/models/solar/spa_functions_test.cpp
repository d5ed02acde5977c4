// The SPA steps against the intermediate values Reda and Andreas (2004, table A5.1 and the
// report's example output) publish for 2003-10-17 12:30:30 -07:00 at Golden, Colorado, with
// delta-T 67 s; each tolerance is half a unit of the last published digit.
#include "models/solar/spa_functions.h"

#include <gtest/gtest.h>

#include "models/solar/spa_tables.h"

namespace clearsky::spa {
namespace {

// 2003-10-17T19:30:30Z.
constexpr double kExampleUnixS = 1066419030.0;
constexpr double kExampleDeltaTS = 67.0;

TimeScales example_time() { return time_scales((kExampleUnixS - kJ2000UnixSeconds) / 86400.0, kExampleDeltaTS); }

TEST(SpaFunctions, JulianDayOfTheExample) {
  const TimeScales t = example_time();
  EXPECT_NEAR(t.julian_day, 2452930.312847, 5e-7);
  EXPECT_NEAR(t.julian_ephemeris_day - t.julian_day, 67.0 / 86400.0, 1e-9);
  EXPECT_NEAR(t.julian_century, (t.julian_day - 2451545.0) / 36525.0, 1e-12);
  EXPECT_NEAR(t.julian_ephemeris_millennium * 10.0, t.julian_ephemeris_century, 1e-15);
}

TEST(SpaFunctions, JulianDayOfTheUnixEpochAndJ2000) {
  EXPECT_DOUBLE_EQ(time_scales(-kJ2000UnixSeconds / 86400.0, 0).julian_day, 2440587.5);
  EXPECT_DOUBLE_EQ(time_scales(0.0, 0).julian_century, 0.0);
}

TEST(SpaFunctions, EarthHeliocentricPositionOfTheExample) {
  const HeliocentricEarth earth = heliocentric_earth(example_time().julian_ephemeris_millennium);
  EXPECT_NEAR(earth.longitude_deg, 24.0182616917, 5e-10);
  EXPECT_NEAR(earth.latitude_deg, -0.0001011219, 5e-11);
  EXPECT_NEAR(earth.radius_au, 0.9965422974, 5e-11);
}

TEST(SpaFunctions, NutationAndObliquityOfTheExample) {
  const TimeScales t = example_time();
  const Nutation nut = nutation(t.julian_ephemeris_century);
  EXPECT_NEAR(nut.longitude_deg, -0.00399840, 5e-9);
  EXPECT_NEAR(nut.obliquity_deg, 0.00166657, 5e-9);
  EXPECT_NEAR(true_obliquity_deg(t.julian_ephemeris_millennium, nut.obliquity_deg), 23.440465, 5e-7);
}

TEST(SpaFunctions, GeocentricSunOfTheExample) {
  const GeocentricSun sun = geocentric_sun(example_time());
  EXPECT_NEAR(sun.longitude_deg, 204.0182616917, 5e-10);
  EXPECT_NEAR(sun.latitude_deg, 0.0001011219, 5e-11);
  EXPECT_NEAR(sun.apparent_longitude_deg, 204.0085519281, 5e-10);
  EXPECT_NEAR(sun.right_ascension_deg, 202.22741, 5e-6);
  EXPECT_NEAR(sun.declination_deg, -9.31434, 5e-6);
}

TEST(SpaFunctions, ObserverHourAngleAndTopocentricSunOfTheExample) {
  const TimeScales t = example_time();
  const GeocentricSun sun = geocentric_sun(t);
  const double nu =
      apparent_sidereal_time_deg(t.julian_day, t.julian_century, sun.nutation_longitude_deg, sun.true_obliquity_deg);
  EXPECT_NEAR(nu, 318.5119, 5e-5);
  const double hour_angle = wrap_degrees_360(nu - 105.1786 - sun.right_ascension_deg);
  EXPECT_NEAR(hour_angle, 11.105902, 5e-6);
  const TopocentricSun topo = topocentric_sun(sun, hour_angle, 39.742476, 1830.14);
  EXPECT_NEAR(topo.right_ascension_deg, 202.22704, 5e-6);
  EXPECT_NEAR(topo.declination_deg, -9.316179, 5e-7);
  EXPECT_NEAR(topo.hour_angle_deg, 11.10627, 5e-6);
  const double e0 = topocentric_elevation_deg(39.742476, topo.declination_deg, topo.hour_angle_deg);
  EXPECT_NEAR(e0, 39.872046, 5e-7);
  EXPECT_NEAR(refraction_correction_deg(e0, 820.0, 11.0), 0.016332, 5e-7);
  EXPECT_NEAR(topocentric_azimuth_deg(39.742476, topo.declination_deg, topo.hour_angle_deg), 194.34024, 5e-6);
}

TEST(SpaFunctions, TablesHaveThePublishedTermCounts) {
  std::size_t longitude = 0;
  for (auto series : earth_longitude_series()) longitude += series.size();
  std::size_t radius = 0;
  for (auto series : earth_radius_series()) radius += series.size();
  EXPECT_EQ(longitude, 64u + 34 + 20 + 7 + 3 + 1);
  EXPECT_EQ(radius, 40u + 10 + 6 + 2 + 1);
  EXPECT_EQ(earth_latitude_series()[0].size() + earth_latitude_series()[1].size(), 7u);
  EXPECT_EQ(nutation_terms().size(), 63u);
}

TEST(SpaFunctions, AngleWrapping) {
  EXPECT_DOUBLE_EQ(wrap_degrees_360(-30.0), 330.0);
  EXPECT_DOUBLE_EQ(wrap_degrees_360(720.5), 0.5);
  EXPECT_DOUBLE_EQ(wrap_degrees_360(-1e-20), 0.0);
  EXPECT_DOUBLE_EQ(wrap_degrees_180(190.0), -170.0);
  EXPECT_DOUBLE_EQ(wrap_degrees_180(-180.0), -180.0);
  EXPECT_DOUBLE_EQ(wrap_degrees_180(180.0), -180.0);
}

// The equation of time peaks near +16.4 minutes in early November and -14.2 minutes in
// mid-February (apparent minus mean solar time).
TEST(SpaFunctions, EquationOfTimeExtremes) {
  const auto eot_at = [](double unix_s) {
    const TimeScales t = time_scales((unix_s - kJ2000UnixSeconds) / 86400.0, 69.0);
    const GeocentricSun sun = geocentric_sun(t);
    return equation_of_time_min(t.julian_ephemeris_millennium, sun.right_ascension_deg, sun.nutation_longitude_deg,
                                sun.true_obliquity_deg);
  };
  EXPECT_NEAR(eot_at(1699012800.0), 16.4, 0.1);   // 2023-11-03T12:00Z
  EXPECT_NEAR(eot_at(1676116800.0), -14.2, 0.1);  // 2023-02-11T12:00Z
}

}  // namespace
}  // namespace clearsky::spa
