// POST, GET /v1/aerosols and GET /v1/aerosols/{id} over loopback (api/aerosols/aerosols_api.h,
// docs/data-api.md "Aerosol inversions"): the shipped Egbert inversion and a copy of it with its
// optical depths doubled are stored and described; what the AERONET reader refuses, a missing
// name, another media type, a file above the cap and a missing token are refused naming the
// parameter, and nothing is stored for them.
#include <gtest/gtest.h>

#include <string>

#include "api/aerosols/aerosols_api.h"
#include "models/core/embedded_data.h"
#include "tests/server/http/data_server_fixture.h"

namespace clearsky::server {
namespace {

class AerosolsOverHttp : public testing::DataServerFixture {};

std::string egbert() {
  return std::string(data::embedded_file("aeronet/130527_130527_Egbert.pfn"));
}

TEST_F(AerosolsOverHttp, StoresListsAndDescribesAnInversion) {
  start(std::string("t0ken"));
  auto c = client("t0ken");
  const auto created = c.Post("/v1/aerosols?name=egbert", egbert(), "text/plain");
  ASSERT_TRUE(created);
  ASSERT_EQ(created->status, 201) << created->body;
  const auto j = body(created);
  const std::int64_t id = j["id"];
  EXPECT_EQ(created->get_header_value("Location"), "/v1/aerosols/" + std::to_string(id));
  EXPECT_EQ(j["name"], "egbert");
  EXPECT_EQ(j["site"], "Egbert");
  EXPECT_EQ(j["first_day"], "2013-05-27");
  EXPECT_EQ(j["retrieval_count"], 5);
  EXPECT_EQ(j["content_hash"].get<std::string>().size(), 16u);
  EXPECT_EQ(j["wavelengths_nm"], nlohmann::json({442.0, 674.0, 871.0, 1020.0}));
  ASSERT_EQ(j["retrievals"].size(), 5u);
  EXPECT_EQ(j["retrievals"][0]["time_utc"], "11:19:04");
  EXPECT_DOUBLE_EQ(j["retrievals"][0]["aod_440"].get<double>(), 0.113925);
  EXPECT_EQ(j["retrievals"][0]["aod"].size(), 4u);

  const auto shown = c.Get("/v1/aerosols/" + std::to_string(id));
  ASSERT_TRUE(shown);
  EXPECT_EQ(shown->status, 200);
  EXPECT_EQ(body(shown), j);

  const auto second = c.Post("/v1/aerosols?name=again", egbert(), "application/octet-stream");
  ASSERT_TRUE(second);
  ASSERT_EQ(second->status, 201) << second->body;
  EXPECT_GT(body(second)["id"].get<std::int64_t>(), id);
  const auto page = c.Get("/v1/aerosols?limit=1");
  ASSERT_TRUE(page);
  ASSERT_EQ(page->status, 200);
  ASSERT_EQ(body(page).size(), 1u);
  EXPECT_EQ(body(page)[0]["name"], "again");
  EXPECT_FALSE(body(page)[0].contains("retrievals"));
  EXPECT_NE(page->get_header_value("Link").find("cursor="), std::string::npos);

  const auto unknown = c.Get("/v1/aerosols/999");
  ASSERT_TRUE(unknown);
  EXPECT_EQ(unknown->status, 404);
  EXPECT_EQ(body(unknown)["error"]["code"], "unknown_aerosols");
  EXPECT_EQ(body(unknown)["error"]["parameter"], "id");
}

TEST_F(AerosolsOverHttp, RefusesNamingTheParameterAndStoresNothing) {
  start(std::string("t0ken"));
  auto c = client("t0ken");
  const auto garbage =
      c.Post("/v1/aerosols?name=g", "not,an,inversion\na\nb\nc\nd\n", "text/plain");
  ASSERT_TRUE(garbage);
  EXPECT_EQ(garbage->status, 400);
  EXPECT_EQ(body(garbage)["error"]["code"], "invalid_inversion");
  EXPECT_EQ(body(garbage)["error"]["parameter"], "body");
  EXPECT_NE(body(garbage)["error"]["message"].get<std::string>().find("line 1"), std::string::npos);
  // The message never names a server path.
  EXPECT_EQ(garbage->body.find(dir.path.string()), std::string::npos);

  std::string fill = egbert();
  const std::size_t line5 = fill.find('\n', fill.find("Julian_Day")) + 1;
  const std::size_t third = fill.find(',', fill.find(',', fill.find(',', line5) + 1) + 1) + 1;
  fill.replace(third, fill.find(',', third) - third, "-999.000000");
  const auto missing = c.Post("/v1/aerosols?name=m", fill, "text/plain");
  ASSERT_TRUE(missing);
  EXPECT_EQ(missing->status, 400) << missing->body;
  EXPECT_NE(body(missing)["error"]["message"].get<std::string>().find("-999"), std::string::npos);

  const auto no_name = c.Post("/v1/aerosols", egbert(), "text/plain");
  ASSERT_TRUE(no_name);
  EXPECT_EQ(no_name->status, 400);
  EXPECT_EQ(body(no_name)["error"]["parameter"], "name");

  const auto empty = c.Post("/v1/aerosols?name=e", "", "text/plain");
  ASSERT_TRUE(empty);
  EXPECT_EQ(empty->status, 400);
  EXPECT_EQ(body(empty)["error"]["parameter"], "body");

  const auto media = c.Post("/v1/aerosols?name=j", egbert(), "application/json");
  ASSERT_TRUE(media);
  EXPECT_EQ(media->status, 415);
  EXPECT_EQ(body(media)["error"]["parameter"], "Content-Type");

  const auto big =
      c.Post("/v1/aerosols?name=b", std::string(api::kMaxAerosolFileBytes + 1, 'x'), "text/plain");
  ASSERT_TRUE(big);
  EXPECT_EQ(big->status, 413);
  EXPECT_EQ(body(big)["error"]["parameter"], "body");

  const auto unknown = c.Post("/v1/aerosols?name=u&site=x", egbert(), "text/plain");
  ASSERT_TRUE(unknown);
  EXPECT_EQ(unknown->status, 400);
  EXPECT_EQ(body(unknown)["error"]["parameter"], "site");

  const auto no_token = client().Post("/v1/aerosols?name=t", egbert(), "text/plain");
  ASSERT_TRUE(no_token);
  EXPECT_EQ(no_token->status, 401);

  const auto list = c.Get("/v1/aerosols");
  ASSERT_TRUE(list);
  EXPECT_EQ(body(list), nlohmann::json::array());
}

}  // namespace
}  // namespace clearsky::server
