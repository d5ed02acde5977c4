// Strict number and boolean parsing of request parameters.
#include "api/parse/number.h"

#include <gtest/gtest.h>

#include "api/parse/invalid_parameter.h"

namespace clearsky::api {
namespace {

TEST(ParseNumber, AcceptsWholeFiniteNumbers) {
  EXPECT_DOUBLE_EQ(parse_number("1830.14", "altitude"), 1830.14);
  EXPECT_DOUBLE_EQ(parse_number(" -7 ", "x"), -7.0);
  EXPECT_DOUBLE_EQ(parse_number("+67", "delta_t"), 67.0);
  EXPECT_DOUBLE_EQ(parse_number("1e3", "x"), 1000.0);
  EXPECT_DOUBLE_EQ(parse_number_in_range("820", "pressure", 0, 5000), 820.0);
}

TEST(ParseNumber, RejectsEverythingElseNamingTheParameter) {
  for (const char* bad : {"", " ", "nan", "NaN", "inf", "-inf", "1e999", "12abc", "1,5", "0x10",
                          "+-1", "--1", "++1"}) {
    try {
      (void)parse_number(bad, "pressure");
      ADD_FAILURE() << "accepted " << bad;
    } catch (const InvalidParameter& e) {
      EXPECT_EQ(e.parameter(), "pressure") << bad;
    }
  }
  EXPECT_THROW((void)parse_number_in_range("5000.5", "pressure", 0, 5000), InvalidParameter);
  EXPECT_THROW((void)parse_number_in_range("-1", "pressure", 0, 5000), InvalidParameter);
}

TEST(ParseBoolean, Words) {
  EXPECT_TRUE(parse_boolean("true", "refraction"));
  EXPECT_TRUE(parse_boolean("YES", "refraction"));
  EXPECT_FALSE(parse_boolean("0", "refraction"));
  EXPECT_FALSE(parse_boolean("False", "refraction"));
  EXPECT_THROW((void)parse_boolean("off-ish", "refraction"), InvalidParameter);
}

}  // namespace
}  // namespace clearsky::api
