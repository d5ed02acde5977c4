// The quality parameter on the sky handlers (api/request/quality.h, docs/quality-levels.md),
// on O'Neal (a registered model whose level is its sample count, cheap to build): the level's
// options are applied, standard is the answer without quality, explicit options win, every
// answer states the quality, and another value is a 400 naming quality.
#include <gtest/gtest.h>

#include "api/handlers/handlers.h"
#include "api/request/quality.h"
#include "api/skydome/skydome_render.h"
#include "models/registry.h"
#include "tests/support/synchronous_provider.h"

namespace clearsky::api {
namespace {

class QualityParameter : public ::testing::Test {
 protected:
  using Q = std::vector<std::pair<std::string, std::string>>;
  ApiResponse call(ApiResponse (*handler)(const ApiContext&, const ApiRequest&), Q extra,
                   QualityLevel default_level = QualityLevel::standard) {
    Q query{{"model", "oneal"}, {"sun_zenith", "40"}, {"sun_azimuth", "180"}};
    query.insert(query.end(), extra.begin(), extra.end());
    ApiRequest r{"GET", "/v1/x", std::move(query), ""};
    ApiContext context{provider, limits};
    context.default_quality = default_level;
    try {
      return handler(context, r);
    } catch (const ApiError& e) {
      return error_response(e);
    }
  }
  static nlohmann::json json_of(const ApiResponse& r) { return nlohmann::json::parse(r.body); }
  static nlohmann::json radiance_of(const ApiResponse& r) {
    return json_of(r)["samples"][0]["radiance"];
  }
  clearsky::testing::SynchronousProvider provider{
      std::vector<ModelFactory>(registered_models().begin(), registered_models().end())};
  Limits limits{100, 500, 1024};
  const Q view{{"view_zenith", "50"}, {"view_azimuth", "100"}, {"wavelengths", "450,550,650"}};
  Q with(Q extra) const {
    Q q = view;
    q.insert(q.end(), extra.begin(), extra.end());
    return q;
  }
};

TEST_F(QualityParameter, StandardIsTheAnswerWithoutQuality) {
  const ApiResponse plain = call(radiance, view);
  const ApiResponse standard = call(radiance, with({{"quality", "standard"}}));
  ASSERT_EQ(plain.status, 200) << plain.body;
  ASSERT_EQ(standard.status, 200) << standard.body;
  EXPECT_EQ(radiance_of(plain), radiance_of(standard));
  const auto j = json_of(standard);
  EXPECT_EQ(j["quality"], "standard");
  EXPECT_EQ(j["served_quality"], "standard");
  EXPECT_EQ(j["quality_setting"], nlohmann::json({{"samples", 4.0}}));
  EXPECT_EQ(j["quality_error"]["against"], "reference");
  EXPECT_GT(j["quality_error"]["p95_relative"].get<double>(), 0.0);
  EXPECT_FALSE(j.contains("quality_overridden"));
  EXPECT_EQ(json_of(plain)["quality"], "standard");
  EXPECT_EQ(standard.header("Clearsky-Quality"), "standard");
  EXPECT_EQ(standard.header("Clearsky-Served-Quality"), "standard");
}

TEST_F(QualityParameter, DraftAndReferenceApplyTheirOptions) {
  for (const auto& [level, samples] : {std::pair{"draft", "64"}, std::pair{"reference", "512"}}) {
    const ApiResponse leveled = call(radiance, with({{"quality", level}}));
    const ApiResponse explicit_options = call(radiance, with({{"samples", samples}}));
    ASSERT_EQ(leveled.status, 200) << leveled.body;
    ASSERT_EQ(explicit_options.status, 200) << explicit_options.body;
    EXPECT_EQ(radiance_of(leveled), radiance_of(explicit_options)) << level;
    EXPECT_NE(radiance_of(leveled), radiance_of(call(radiance, view))) << level;
    const auto j = json_of(leveled);
    EXPECT_EQ(j["quality"], level);
    EXPECT_EQ(j["quality_setting"]["samples"], std::stod(samples));
    EXPECT_EQ(leveled.header("Clearsky-Quality"), level);
  }
  // The reference's figures are its difference to a finer setting (docs/quality-levels.md).
  const auto reference_error =
      json_of(call(radiance, with({{"quality", "reference"}})))["quality_error"];
  EXPECT_EQ(reference_error["against"], "finer_setting");
  EXPECT_GT(reference_error["max_relative"].get<double>(), 0.0);
  EXPECT_LT(reference_error["max_relative"].get<double>(), 0.02);
}

TEST_F(QualityParameter, TheServersDefaultLevelAppliesWithoutQuality) {
  const ApiResponse r = call(radiance, view, QualityLevel::draft);
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(json_of(r)["quality"], "draft");
  EXPECT_EQ(radiance_of(r), radiance_of(call(radiance, with({{"quality", "draft"}}))));
  // A request's own quality wins over the server's default.
  EXPECT_EQ(
      json_of(call(radiance, with({{"quality", "standard"}}), QualityLevel::draft))["quality"],
      "standard");
}

TEST_F(QualityParameter, ExplicitOptionsOverrideTheLevelAndDropItsFigures) {
  const ApiResponse r = call(radiance, with({{"quality", "draft"}, {"samples", "8"}}));
  ASSERT_EQ(r.status, 200) << r.body;
  const auto j = json_of(r);
  EXPECT_EQ(j["quality"], "draft");
  EXPECT_EQ(j["quality_setting"]["samples"], 8.0);
  EXPECT_EQ(j["quality_overridden"], nlohmann::json({"samples"}));
  EXPECT_TRUE(j["quality_error"].is_null());
  EXPECT_EQ(radiance_of(r), radiance_of(call(radiance, with({{"samples", "8"}}))));
}

TEST_F(QualityParameter, AnotherValueIsA400NamingQuality) {
  for (const char* value : {"best", "", "Draft", "1"}) {
    const ApiResponse r = call(radiance, with({{"quality", value}}));
    EXPECT_EQ(r.status, 400) << value;
    EXPECT_EQ(json_of(r)["error"]["parameter"], "quality") << value;
  }
}

TEST_F(QualityParameter, EverySkyEndpointStatesItsQuality) {
  const ApiResponse answers[] = {
      call(rgb, {{"view_zenith", "50"}, {"view_azimuth", "100"}, {"quality", "draft"}}),
      call(irradiance, {{"quality", "draft"}, {"component", "diffuse"}}),
      call(skypatches, {{"quality", "draft"}, {"output", "luminance"}}),
  };
  for (const ApiResponse& r : answers) {
    ASSERT_EQ(r.status, 200) << r.body;
    EXPECT_EQ(json_of(r)["quality"], "draft") << r.body;
    EXPECT_EQ(json_of(r)["served_quality"], "draft");
    EXPECT_EQ(r.header("Clearsky-Quality"), "draft");
  }
  // CSV answers state it in their headers.
  const ApiResponse csv = call(radiance, with({{"quality", "draft"}, {"format", "csv"}}));
  ASSERT_EQ(csv.status, 200) << csv.body;
  EXPECT_EQ(csv.header("Clearsky-Quality"), "draft");
  EXPECT_NE(csv.header("Clearsky-Quality-Detail")->find("samples=64"), std::string_view::npos);
}

TEST_F(QualityParameter, TheSkydomeStatesItsQualityInTheExrHeader) {
  ApiRequest r{"GET",
               "/v1/skydome",
               {{"model", "oneal"},
                {"sun_zenith", "40"},
                {"sun_azimuth", "180"},
                {"size", "8"},
                {"quality", "draft"}},
               ""};
  const ApiContext context{provider, limits};
  const SkydomeRender render = prepare_skydome(context, r);
  std::string bytes;
  ASSERT_TRUE(render.write([&](const char* data, std::size_t size) {
    bytes.append(data, size);
    return true;
  }));
  EXPECT_NE(bytes.find("clearskyQuality"), std::string::npos);
  EXPECT_NE(bytes.find("clearskyServedQuality"), std::string::npos);
  EXPECT_NE(bytes.find("draft"), std::string::npos);
  std::vector<std::pair<std::string, std::string>> headers;
  render.add_quality_headers(headers);
  ASSERT_FALSE(headers.empty());
  EXPECT_EQ(headers[0], std::make_pair(std::string("Clearsky-Quality"), std::string("draft")));
}

}  // namespace
}  // namespace clearsky::api
