// Parameters: strict numbers (NaN, infinity, trailing text fail), ranges, duplicates, and the
// naming of unused parameters.
#include "api/request/parameters.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "api/error/api_error.h"

namespace clearsky::api {
namespace {

ApiError error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const ApiError& e) {
    return e;
  }
  ADD_FAILURE() << "no ApiError thrown";
  return ApiError(0, "", "", "");
}

TEST(Parameters, ParsesNumbersStrictly) {
  EXPECT_DOUBLE_EQ(number_value("x", "1.5"), 1.5);
  EXPECT_DOUBLE_EQ(number_value("x", " -2e3 "), -2000.0);
  EXPECT_DOUBLE_EQ(number_value("x", "+3"), 3.0);
  for (const char* bad : {"nan", "NaN", "inf", "-inf", "1.5x", "", "1,5", "0x10", "--1"}) {
    const ApiError e = error_of([&] { number_value("view_zenith", bad); });
    EXPECT_EQ(e.status(), 400) << bad;
    EXPECT_EQ(e.parameter(), "view_zenith") << bad;
  }
}

TEST(Parameters, RangesAreInclusiveAndNanFails) {
  Parameters p("GET /x");
  p.add("a", "90");
  p.add("b", "90.0001");
  p.add("c", "nan");
  EXPECT_DOUBLE_EQ(*p.number("a", 0, 90), 90.0);
  EXPECT_EQ(error_of([&] { p.number("b", 0, 90); }).parameter(), "b");
  EXPECT_EQ(error_of([&] { p.number("c", 0, 90); }).parameter(), "c");
  EXPECT_FALSE(p.number("absent", 0, 1).has_value());
  EXPECT_EQ(error_of([&] { p.required_number("absent", 0, 1); }).code(), "missing_parameter");
}

TEST(Parameters, NamesTheFirstUnusedParameter) {
  Parameters p("GET /v1/radiance");
  p.add("model", "x");
  p.add("sun_zenit", "30");
  p.text("model");
  const ApiError e = error_of([&] { p.reject_unused(); });
  EXPECT_EQ(e.status(), 400);
  EXPECT_EQ(e.code(), "unknown_parameter");
  EXPECT_EQ(e.parameter(), "sun_zenit");
}

TEST(Parameters, RejectsDuplicates) {
  Parameters p("GET /x");
  p.add("a", "1");
  EXPECT_EQ(error_of([&] { p.add("a", "2"); }).parameter(), "a");
}

TEST(Parameters, ChoicesAndBooleans) {
  Parameters p("GET /x");
  p.add("format", "xml");
  p.add("spectral", "yes please");
  EXPECT_EQ(error_of([&] { p.choice("format", {"json", "csv"}, "json"); }).parameter(), "format");
  EXPECT_EQ(p.choice("absent", {"json", "csv"}, "json"), "json");
  EXPECT_EQ(error_of([&] { p.boolean_or("spectral", false); }).parameter(), "spectral");
}

TEST(Parameters, FromJsonObjectKeepsFullPrecisionAndRejectsNesting) {
  const auto body = nlohmann::json::parse(
      R"({"sun_zenith": 0.1, "model": "m", "views": [[1, 2]], "flag": true})");
  Parameters p = Parameters::from_json_object("POST /x", body, {"views"});
  EXPECT_EQ(*p.number("sun_zenith", 0, 1), 0.1);
  EXPECT_EQ(*p.text("model"), "m");
  EXPECT_TRUE(p.boolean_or("flag", false));
  EXPECT_FALSE(p.has("views"));
  const auto nested = nlohmann::json::parse(R"({"a": {"b": 1}})");
  EXPECT_EQ(error_of([&] { Parameters::from_json_object("POST /x", nested, {}); }).parameter(),
            "a");
}

// The strict number rules the sun request used to have on its own (whole text, finite, one
// optional '+' before a digit), now those of every parameter.
TEST(Parameters, NumbersAcceptWholeFiniteTextOnly) {
  EXPECT_DOUBLE_EQ(number_value("altitude", "1830.14"), 1830.14);
  EXPECT_DOUBLE_EQ(number_value("x", " -7 "), -7.0);
  EXPECT_DOUBLE_EQ(number_value("delta_t", "+67"), 67.0);
  EXPECT_DOUBLE_EQ(number_value("x", "1e3"), 1000.0);
  for (const char* bad : {"", " ", "nan", "NaN", "inf", "-inf", "1e999", "12abc", "1,5", "0x10",
                          "+-1", "--1", "++1"}) {
    const ApiError e = error_of([&] { number_value("pressure", bad); });
    EXPECT_EQ(e.status(), 400) << bad;
    EXPECT_EQ(e.parameter(), "pressure") << bad;
  }
  Parameters p("GET /x");
  p.add("pressure", "820");
  p.add("above", "5000.5");
  p.add("below", "-1");
  EXPECT_DOUBLE_EQ(*p.number("pressure", 0, 5000), 820.0);
  EXPECT_EQ(error_of([&] { p.number("above", 0, 5000); }).parameter(), "above");
  EXPECT_EQ(error_of([&] { p.number("below", 0, 5000); }).parameter(), "below");
}

TEST(Parameters, BooleanWordsInAnyCase) {
  Parameters p("GET /x");
  p.add("a", "true");
  p.add("b", "YES");
  p.add("c", "0");
  p.add("d", "False");
  p.add("e", "off-ish");
  EXPECT_TRUE(p.boolean_or("a", false));
  EXPECT_TRUE(p.boolean_or("b", false));
  EXPECT_FALSE(p.boolean_or("c", true));
  EXPECT_FALSE(p.boolean_or("d", true));
  EXPECT_EQ(error_of([&] { p.boolean_or("e", true); }).parameter(), "e");
}

TEST(Parameters, ErrorsKeepTheReasonApartFromTheName) {
  Parameters p("GET /x");
  p.add("a", "1");
  const ApiError duplicate = error_of([&] { p.add("a", "2"); });
  EXPECT_STREQ(duplicate.what(), "a: given more than once");
  EXPECT_EQ(duplicate.reason(), "given more than once");
  EXPECT_EQ(duplicate.code(), "duplicate_parameter");
}

}  // namespace
}  // namespace clearsky::api
