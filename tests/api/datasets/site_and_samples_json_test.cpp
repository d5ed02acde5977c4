// The site-and-samples body of the open formats' JSON (api/datasets/site_and_samples_json.h):
// the file's site or each sample's own, the members a format adds, and the refusals the formats
// give word for word.
#include "api/datasets/site_and_samples_json.h"

#include <gtest/gtest.h>

#include <string>

#include "api/error/api_error.h"
#include "tests/support/api_refusal.h"

namespace clearsky::api {
namespace {

using Refusal = clearsky::testing::ApiRefusal;
using clearsky::testing::refusal_of;

// The refusal of the body, or of its sample 0 when the body is accepted.
Refusal refusal_of_body(const std::string& text) {
  return refusal_of([&] {
    const SiteAndSamplesJson body(text, {"value", "extra"});
    body.sample(0).number("value");
  });
}

TEST(SiteAndSamplesJson, TheFileSiteOrEachSamplesOwn) {
  const SiteAndSamplesJson file_site(
      R"({"site": {"latitude": 10, "longitude": 20, "elevation_m": 30},
          "samples": [{"time": "t0", "value": 1.5, "extra": null}]})",
      {"value", "extra"});
  ASSERT_EQ(file_site.size(), 1u);
  const JsonSample sample = file_site.sample(0);
  EXPECT_EQ(sample.time, "t0");
  EXPECT_EQ(sample.latitude_deg, 10);
  EXPECT_EQ(sample.longitude_deg, 20);
  EXPECT_EQ(sample.elevation_m, 30);
  EXPECT_EQ(sample.number("value"), 1.5);
  EXPECT_FALSE(sample.optional_number("extra"));
  EXPECT_FALSE(sample.optional_number("value_not_given"));

  const SiteAndSamplesJson own_site(
      R"({"samples": [{"time": "t0", "latitude": -1, "longitude": -2, "elevation_m": -3,
                       "extra": 4}]})",
      {"value", "extra"});
  const JsonSample own = own_site.sample(0);
  EXPECT_EQ(own.latitude_deg, -1);
  EXPECT_EQ(own.elevation_m, -3);
  EXPECT_EQ(own.optional_number("extra"), 4);
  EXPECT_EQ(own_site.names().member(3, "extra"), "samples[3].extra");
}

TEST(SiteAndSamplesJson, RefusesTheBodyNamingTheMember) {
  const std::string site = R"("site": {"latitude": 1, "longitude": 2, "elevation_m": 3})";
  Refusal r = refusal_of_body("[1]");
  EXPECT_EQ(r.status, 400);
  EXPECT_EQ(r.parameter, "body");
  EXPECT_EQ(r.message, "body: must be an object with members site and samples");
  r = refusal_of_body(R"({"samples": [], "sites": 1})");
  EXPECT_EQ(r.parameter, "sites");
  EXPECT_EQ(r.message, "sites: unknown member; the members are site and samples");
  r = refusal_of_body(R"({"site": 1, "samples": []})");
  EXPECT_EQ(r.message, "site: must be an object");
  r = refusal_of_body(R"({"site": {"latitude": 1, "height": 2}, "samples": []})");
  EXPECT_EQ(r.message, "site.height: unknown member");
  r = refusal_of_body(R"({"site": {}, "samples": []})");
  EXPECT_EQ(r.message, "site.latitude: missing");
  r = refusal_of_body(R"({"site": {"latitude": 1, "longitude": 2}, "samples": []})");
  EXPECT_EQ(r.message, "site.elevation_m: missing");
  r = refusal_of_body("{" + site + "}");
  EXPECT_EQ(r.message, "samples: missing");
  r = refusal_of_body("{" + site + R"(, "samples": {}})");
  EXPECT_EQ(r.message, "samples: must be an array");
  r = refusal_of_body("{" + site + ", ");
  EXPECT_EQ(r.status, 400);
  EXPECT_EQ(r.parameter, "body");
}

TEST(SiteAndSamplesJson, RefusesASampleNamingItsMember) {
  const std::string site = R"({"site": {"latitude": 1, "longitude": 2, "elevation_m": 3}, )";
  Refusal r = refusal_of_body(site + R"("samples": [3]})");
  EXPECT_EQ(r.parameter, "samples[0]");
  EXPECT_EQ(r.message, "samples[0]: must be an object");
  r = refusal_of_body(site + R"("samples": [{"time": "t", "value": 1, "colour": 2}]})");
  EXPECT_EQ(r.message, "samples[0].colour: unknown member");
  r = refusal_of_body(site + R"("samples": [{"value": 1}]})");
  EXPECT_EQ(r.message, "samples[0].time: missing");
  r = refusal_of_body(site + R"("samples": [{"time": 5, "value": 1}]})");
  EXPECT_EQ(r.message, "samples[0].time: must be an ISO 8601 time with offset (a string)");
  r = refusal_of_body(site + R"("samples": [{"time": "t", "latitude": 1, "longitude": 2,
                                            "elevation_m": 3, "value": 1}]})");
  EXPECT_EQ(r.message,
            "samples[0].latitude: the file gives the site (member site): a sample may not give "
            "another");
  r = refusal_of_body(R"({"samples": [{"time": "t", "value": 1}]})");
  EXPECT_EQ(r.message,
            "samples[0].latitude: missing: give the site in the file (member site) or in each "
            "sample");
  r = refusal_of_body(site + R"("samples": [{"time": "t"}]})");
  EXPECT_EQ(r.message, "samples[0].value: missing");
  r = refusal_of_body(site + R"("samples": [{"time": "t", "value": "1"}]})");
  EXPECT_EQ(r.parameter, "samples[0].value");
  EXPECT_EQ(r.message, "samples[0].value: must be a number");
  r = refusal_of([&] {
    SiteAndSamplesJson(site + R"("samples": [{"time": "t", "extra": true}]})", {"extra"})
        .sample(0)
        .optional_number("extra");
  });
  EXPECT_EQ(r.message, "samples[0].extra: must be a number or null");
}

}  // namespace
}  // namespace clearsky::api
