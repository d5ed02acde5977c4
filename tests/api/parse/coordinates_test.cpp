// Latitude/longitude parsing: decimal and DMS forms, hemispheres, ranges, malformed text.
#include "api/parse/coordinates.h"

#include <gtest/gtest.h>

#include "api/error/api_error.h"

namespace clearsky::api {
namespace {

// The parameter named by the ApiError that parsing text throws, or "" if none.
template <typename Parse>
std::string rejected_parameter(Parse parse, const std::string& text) {
  try {
    parse(text);
  } catch (const ApiError& e) {
    return e.parameter();
  }
  return "";
}

TEST(ParseCoordinates, DecimalDegrees) {
  EXPECT_DOUBLE_EQ(parse_latitude("39.742476"), 39.742476);
  EXPECT_DOUBLE_EQ(parse_longitude("-105.1786"), -105.1786);
  EXPECT_DOUBLE_EQ(parse_longitude(" 180 "), 180.0);
  EXPECT_DOUBLE_EQ(parse_latitude("-90"), -90.0);
}

// The Kider et al. capture site written as DMS (Cornell, Ithaca NY).
TEST(ParseCoordinates, DegreesMinutesSecondsWithHemisphere) {
  EXPECT_NEAR(parse_latitude("42d26'36.4\"N"), 42.0 + 26.0 / 60 + 36.4 / 3600, 1e-12);
  EXPECT_NEAR(parse_longitude("76d28'55.1\"W"), -(76.0 + 28.0 / 60 + 55.1 / 3600), 1e-12);
  EXPECT_NEAR(parse_longitude("76:28:55.1W"), -(76.0 + 28.0 / 60 + 55.1 / 3600), 1e-12);
  EXPECT_NEAR(parse_latitude("S33d52.5"), -(33.0 + 52.5 / 60), 1e-12);
  EXPECT_NEAR(parse_latitude("42\xc2\xb0"
                             "26\xe2\x80\xb2"
                             "36.4\xe2\x80\xb3N"),
              42.0 + 26.0 / 60 + 36.4 / 3600, 1e-12);
}

TEST(ParseCoordinates, HemisphereMustMatchTheCoordinate) {
  EXPECT_EQ(rejected_parameter([](const std::string& t) { return parse_latitude(t, "lat"); },
                               "76d28'55.1\"W"),
            "lat");
  EXPECT_EQ(rejected_parameter([](const std::string& t) { return parse_longitude(t, "lon"); },
                               "42d26'36.4\"N"),
            "lon");
}

TEST(ParseCoordinates, RangeAndMalformedInputNameTheParameter) {
  const auto lat = [](const std::string& t) { return parse_latitude(t, "lat"); };
  const auto lon = [](const std::string& t) { return parse_longitude(t, "lon"); };
  for (const char* bad : {"91", "-90.0001", "nan", "NaN", "inf", "", "abc", "4:60", "12..5",
                          "1.8e2d", "42d26'36.4\"Q"}) {
    EXPECT_EQ(rejected_parameter(lat, bad), "lat") << bad;
  }
  for (const char* bad : {"180.5", "-181", "nan", "200E", "--5"})
    EXPECT_EQ(rejected_parameter(lon, bad), "lon") << bad;
  try {
    parse_latitude("91", "lat");
    ADD_FAILURE();
  } catch (const ApiError& e) {
    EXPECT_EQ(e.status(), 400);
    EXPECT_EQ(std::string(e.what()).rfind("lat: must be in [-90, 90]", 0), 0u) << e.what();
  }
}

// A colon after a seconds component, or a fourth colon, made GeographicLib write past its
// arrays and crash the server (found by fuzz/coordinates_fuzz.cpp): refused before it is read,
// while the colon forms D:M and D:M:S stay accepted.
TEST(ParseCoordinates, ColonAfterSecondsIsRefusedNotCrashing) {
  const auto lat = [](const std::string& t) { return parse_latitude(t, "lat"); };
  for (const char* bad : {"4\"1:1:d", "4\"1:1", "1:2:3:4", "1:2:3:4:5", "1d2:3:4", "1'2:3",
                          "4\xe2\x80\xb3"
                          "1:1"})
    EXPECT_EQ(rejected_parameter(lat, bad), "lat") << bad;
  EXPECT_NEAR(parse_latitude("42:26:36.4N"), 42.0 + 26.0 / 60 + 36.4 / 3600, 1e-12);
  EXPECT_NEAR(parse_latitude("-42:30"), -42.5, 1e-12);
  EXPECT_NEAR(parse_longitude("W76:28"), -(76.0 + 28.0 / 60), 1e-12);
}

// GeographicLib alone reads the 'e' of an exponent as East and its sign as a second term:
// "1e-05" was -4 degrees, and a JSON body's 0.00001 reaches the parser as
// "1.0000000000000001e-05" (found by fuzz/coordinates_fuzz.cpp).
TEST(ParseCoordinates, ExponentsAreNumbersNotHemispheres) {
  EXPECT_DOUBLE_EQ(parse_longitude("1e-05"), 1e-05);
  EXPECT_DOUBLE_EQ(parse_longitude("1.0000000000000001e-05"), 1.0000000000000001e-05);
  EXPECT_DOUBLE_EQ(parse_latitude("2.7777777777777779e-05"), 2.7777777777777779e-05);
  EXPECT_DOUBLE_EQ(parse_latitude(" -1.5E+01 "), -15.0);
  EXPECT_DOUBLE_EQ(parse_longitude("+1e2"), 100.0);
  EXPECT_DOUBLE_EQ(parse_longitude("12E"), 12.0);  // a hemisphere letter still is one
  const auto lon = [](const std::string& t) { return parse_longitude(t, "lon"); };
  for (const char* bad : {"2e-3W", "1e-5d", "1e999", "1.5e+01'"})
    EXPECT_EQ(rejected_parameter(lon, bad), "lon") << bad;
}

}  // namespace
}  // namespace clearsky::api
