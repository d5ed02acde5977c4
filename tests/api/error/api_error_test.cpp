// The typed errors of api/error/api_error.h: what they name.
#include "api/error/api_error.h"

#include <gtest/gtest.h>

#include "api/http/api_types.h"

namespace clearsky::api {
namespace {

TEST(UnknownParameter, NamesTheParameter) {
  const ApiError e = unknown_parameter("colour", "GET /v1/sun");
  EXPECT_EQ(e.status(), 400);
  EXPECT_EQ(e.code(), "unknown_parameter");
  EXPECT_EQ(e.parameter(), "colour");
}

// A JSON body member named "" was refused naming no parameter ("parameter": null; found by
// fuzz/api_routes_fuzz.cpp on POST /v1/jobs): it is named as the body.
TEST(UnknownParameter, AMemberWithoutANameIsTheBodys) {
  const ApiError e = unknown_parameter("", "POST /v1/jobs");
  EXPECT_EQ(e.status(), 400);
  EXPECT_EQ(e.parameter(), "body");
  const nlohmann::json body = nlohmann::json::parse(error_response(e).body);
  EXPECT_EQ(body["error"]["parameter"], "body");
  EXPECT_EQ(body["error"]["code"], "unknown_parameter");
}

// The same member with an object for its value: refused as invalid, naming the body.
TEST(InvalidParameter, AMemberWithoutANameIsTheBodys) {
  EXPECT_EQ(invalid_parameter("lat", "out of range").parameter(), "lat");
  const ApiError e = invalid_parameter("", "must be a string, a number or a boolean");
  EXPECT_EQ(e.parameter(), "body");
  const nlohmann::json body = nlohmann::json::parse(error_response(e).body);
  EXPECT_EQ(body["error"]["parameter"], "body");
}

}  // namespace
}  // namespace clearsky::api
