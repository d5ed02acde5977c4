// The list endpoints' pages and the Location of created resources over loopback HTTP
// (server/http/data_routes.cpp, api/paging/list_page.h): a bare JSON array per page, the next
// page in a Link header (RFC 8288) that is absent on the last page, limits checked; POST
// /v1/jobs answers 201 with the job's Location.
#include <gtest/gtest.h>
#include <httplib.h>

#include <regex>

#include "storage/repositories/dataset_repository.h"
#include "tests/server/http/data_server_fixture.h"

namespace clearsky::server {
namespace {

class DataPagination : public testing::DataServerFixture {};

// The target of a Link header's rel="next".
std::string next_target(const std::string& link) {
  std::smatch match;
  if (!std::regex_match(link, match, std::regex(R"(<([^>]+)>; rel="next")"))) return "";
  return match[1];
}

TEST_F(DataPagination, JobsAreCreatedAtTheirLocationAndListedPageByPage) {
  start(std::string("t"));
  {
    storage::Database db = storage::open_database(db_path);
    for (const char* name : {"b", "a", "c"})
      storage::DatasetRepository(db).find_or_create(name, "kider2014");
  }
  auto c = client("t");
  std::vector<std::string> locations;
  for (const char* name : {"weekly", "hourly", "nightly"}) {
    const auto created =
        c.Post("/v1/jobs",
               std::string(R"({"name": ")") + name +
                   R"(", "schedule": "0 3 * * *", "dataset": "a", "models": ["preetham"]})",
               "application/json");
    ASSERT_TRUE(created);
    ASSERT_EQ(created->status, 201) << created->body;
    const std::string location = created->get_header_value("Location");
    EXPECT_EQ(location, "/v1/jobs/" + std::to_string(body(created)["id"].get<int>()));
    const auto shown = c.Get(location.c_str());
    EXPECT_EQ(body(shown)["name"], name);
    locations.push_back(location);
  }
  // Jobs by name, two a page.
  const auto first = c.Get("/v1/jobs?limit=2");
  ASSERT_EQ(first->status, 200);
  const auto first_items = body(first);
  ASSERT_TRUE(first_items.is_array());
  ASSERT_EQ(first_items.size(), 2u);
  EXPECT_EQ(first_items[0]["name"], "hourly");
  EXPECT_EQ(first_items[1]["name"], "nightly");
  const std::string next = next_target(first->get_header_value("Link"));
  ASSERT_EQ(next.rfind("/v1/jobs?limit=2&cursor=", 0), 0u) << first->get_header_value("Link");
  const auto last = c.Get(next.c_str());
  ASSERT_EQ(last->status, 200);
  ASSERT_EQ(body(last).size(), 1u);
  EXPECT_EQ(body(last)[0]["name"], "weekly");
  EXPECT_FALSE(last->has_header("Link"));
  EXPECT_FALSE(c.Get("/v1/jobs")->has_header("Link"));  // all on the first page

  // Datasets likewise; a filter is kept in the next page's link.
  const auto datasets = c.Get("/v1/datasets?limit=1");
  EXPECT_EQ(body(datasets)[0]["name"], "a");
  EXPECT_NE(datasets->get_header_value("Link").find("limit=1&cursor="), std::string::npos);
  const auto runs = c.Get("/v1/evaluations?model=preetham&limit=5");
  ASSERT_EQ(runs->status, 200);
  EXPECT_EQ(runs->body, "[]");
  EXPECT_FALSE(runs->has_header("Link"));
  for (const char* bad : {"/v1/jobs?limit=0", "/v1/datasets?limit=1001", "/v1/imports?limit=x",
                          "/v1/evaluations?cursor=zz"}) {
    const auto refused = c.Get(bad);
    EXPECT_EQ(refused->status, 400) << bad;
  }
  EXPECT_EQ(body(c.Get("/v1/jobs?cursor=zz"))["error"]["parameter"], "cursor");
}

}  // namespace
}  // namespace clearsky::server
