// The data endpoints over loopback HTTP on an ephemeral port (api/routes/route_table.h):
// bearer-token rules (reads open, writes 403 without a configured token, 401 without the right
// one), an archive upload imported as a background job (202, Location, /v1/imports), dataset
// show/delete, an evaluation started over HTTP and read back, the job lifecycle, and the
// server's error format. Preetham on one public capture.
#include <gtest/gtest.h>
#include <httplib.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>

#include "storage/schema/migrations.h"
#include "tests/server/http/data_server_fixture.h"
#include "tests/support/shared_data.h"

namespace clearsky::server {
namespace {

const char* kArchive = "kider2014/2013-05-27/RADIANCE/2013-05-27___12.00.00.7z";

std::string bytes_of(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

class DataRoutes : public testing::DataServerFixture {};

TEST_F(DataRoutes, WithoutATokenReadsAreOpenAndWritesDisabled) {
  start(std::nullopt);
  auto c = client("anything");
  const auto list = c.Get("/v1/datasets");
  ASSERT_TRUE(list);
  EXPECT_EQ(list->status, 200);
  EXPECT_EQ(list->body, "[]");
  const auto post = c.Post("/v1/jobs", "{}", "application/json");
  ASSERT_TRUE(post);
  EXPECT_EQ(post->status, 403);
  EXPECT_EQ(body(post)["error"]["code"], "writes_disabled");
  EXPECT_EQ(c.Delete("/v1/datasets/x")->status, 403);
}

TEST_F(DataRoutes, WritesNeedTheBearerToken) {
  start(std::string("t0ken"));
  const auto none = client().Post("/v1/evaluations", "{}", "application/json");
  ASSERT_TRUE(none);
  EXPECT_EQ(none->status, 401);
  EXPECT_EQ(none->get_header_value("WWW-Authenticate"), "Bearer");
  EXPECT_EQ(body(none)["error"]["code"], "unauthorized");
  EXPECT_EQ(client("wrong").Delete("/v1/jobs/1")->status, 401);
  // The right token reaches the handler (which finds no job 1).
  const auto right = client("t0ken").Delete("/v1/jobs/1");
  EXPECT_EQ(right->status, 404);
  EXPECT_EQ(body(right)["error"]["code"], "unknown_job");
}

TEST_F(DataRoutes, UploadShowEvaluateAndDelete) {
  CLEARSKY_REQUIRE_SHARED_DATA(kArchive);
  start(std::string("t0ken"));
  auto c = client("t0ken");
  const std::string archive = bytes_of(clearsky::testing::shared_data_dir() / kArchive);
  const auto imported =
      c.Post("/v1/datasets?name=noon&format=kider", archive, "application/octet-stream");
  ASSERT_TRUE(imported);
  ASSERT_EQ(imported->status, 202) << imported->body;
  const std::string import_path = imported->get_header_value("Location");
  EXPECT_EQ(import_path, body(imported)["location"]);
  EXPECT_EQ(import_path.rfind("/v1/imports/", 0), 0u);
  EXPECT_EQ(body(imported)["source"], "upload");
  EXPECT_EQ(body(imported)["upload_bytes"], archive.size());
  const nlohmann::json done = finished_import(imported);
  ASSERT_EQ(done["status"], "succeeded") << done.dump();
  EXPECT_EQ(done["report"]["added"][0], "2013-05-27___12.00.00");
  EXPECT_EQ(done["progress"]["captures_added"], 1);
  EXPECT_EQ(body(c.Get("/v1/imports")).size(), 1u);
  EXPECT_EQ(c.Get("/v1/imports/99")->status, 404);
  EXPECT_EQ(c.Get("/v1/imports/x")->status, 400);
  EXPECT_TRUE(std::filesystem::is_empty(dir.path / "uploads"));
  EXPECT_EQ(body(c.Get("/v1/datasets"))[0]["captures"], 1);
  const auto shown = body(c.Get("/v1/datasets/noon?samples=true"));
  EXPECT_EQ(shown["captures"][0]["time"], "2013-05-27T12:00:00-04:00");
  EXPECT_EQ(shown["captures"][0]["samples"].size(), 81u);
  EXPECT_EQ(c.Get("/v1/datasets/noon?colour=1")->status, 400);
  const auto missing = c.Get("/v1/datasets/none");
  EXPECT_EQ(missing->status, 404);
  EXPECT_EQ(body(missing)["error"]["parameter"], "dataset");

  const auto started = c.Post("/v1/evaluations", R"({"models": ["preetham"], "dataset": "noon"})",
                              "application/json");
  ASSERT_EQ(started->status, 202) << started->body;
  const std::string location = body(started)["location"];
  nlohmann::json ticket;
  for (int i = 0; i < 600; ++i) {
    ticket = body(c.Get(location.c_str()));
    if (ticket["status"] == "succeeded" || ticket["status"] == "failed") break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ASSERT_EQ(ticket["status"], "succeeded") << ticket.dump();
  const std::string run_path = "/v1/evaluations/" + std::to_string(ticket["runs"][0].get<int>());
  const auto run = body(c.Get(run_path.c_str()));
  EXPECT_EQ(run["model"], "preetham");
  EXPECT_EQ(run["software_version"], "test");
  EXPECT_GT(run["rmse"].get<double>(), 1.0);
  EXPECT_EQ(run["captures"].size(), 1u);
  EXPECT_FALSE(run["captures"][0].contains("samples"));
  const auto samples =
      body(c.Get((run_path + "?samples=true&capture=2013-05-27___12.00.00").c_str()));
  ASSERT_EQ(samples["captures"][0]["samples"].size(), 81u);
  EXPECT_EQ(c.Get((run_path + "?samples=maybe").c_str())->status, 400);
  EXPECT_EQ(c.Get((run_path + "?capture=none").c_str())->status, 404);
  EXPECT_EQ(body(c.Get("/v1/evaluations?model=preetham&dataset=noon")).size(), 1u);
  EXPECT_EQ(c.Get("/v1/evaluations?since=never")->status, 400);

  EXPECT_EQ(c.Delete("/v1/datasets/noon")->status, 200);
  EXPECT_EQ(c.Get("/v1/datasets")->body, "[]");
  EXPECT_EQ(c.Get(run_path.c_str())->status, 404);  // runs go with their dataset
}

TEST_F(DataRoutes, ImportFromAServerSidePath) {
  CLEARSKY_REQUIRE_SHARED_DATA(kArchive);
  import_roots = {(clearsky::testing::shared_data_dir() / "kider2014").string()};
  start(std::string("t0ken"));
  const std::string archive = (clearsky::testing::shared_data_dir() / kArchive).string();
  const httplib::Params params{{"name", "local"}, {"path", archive}};
  auto c = client("t0ken");
  const auto r = c.Post(("/v1/datasets?" + httplib::detail::params_to_query_str(params)).c_str(),
                        "", "application/octet-stream");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 202) << r->body;
  EXPECT_EQ(body(r)["path"], archive);
  const nlohmann::json done = finished_import(r);
  ASSERT_EQ(done["status"], "succeeded") << done.dump();
  EXPECT_EQ(done["report"]["added"].size(), 1u);
  // Both a path and a body: refused; a missing path: 404 and nothing created.
  EXPECT_EQ(c.Post(("/v1/datasets?" + httplib::detail::params_to_query_str(params)).c_str(), "x",
                   "application/octet-stream")
                ->status,
            400);
  EXPECT_EQ(c.Post("/v1/datasets?name=gone&path=/nonexistent/x.7z", "", "application/octet-stream")
                ->status,
            404);
  EXPECT_EQ(body(c.Get("/v1/datasets")).size(), 1u);
}

TEST_F(DataRoutes, UploadAboveTheLimitIs413AndLeavesNothing) {
  start(std::string("t0ken"), 4096, 4096);
  const auto r = client("t0ken").Post("/v1/datasets?name=big", std::string(100000, 'x'),
                                      "application/octet-stream");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 413);
  EXPECT_EQ(body(r)["error"]["code"], "too_large");
  EXPECT_EQ(client().Get("/v1/datasets")->body, "[]");
  EXPECT_EQ(client().Get("/v1/imports")->body, "[]");
}

TEST_F(DataRoutes, JobLifecycle) {
  start(std::string("t0ken"));
  {
    storage::Database db = storage::open_database(db_path);
    db.execute("INSERT INTO datasets (name, format, created_utc) VALUES ('d', 'kider2014', 'x')");
  }
  auto c = client("t0ken");
  const auto created =
      c.Post("/v1/jobs",
             R"({"name": "nightly", "schedule": "0 3 * * *", "dataset": "d", "models": "all"})",
             "application/json");
  ASSERT_EQ(created->status, 201) << created->body;
  const std::string id = std::to_string(body(created)["id"].get<int>());
  EXPECT_EQ(body(created)["next_run"].get<std::string>().substr(11), "03:00:00Z");
  EXPECT_EQ(body(c.Get("/v1/jobs")).size(), 1u);
  EXPECT_EQ(body(c.Post(("/v1/jobs/" + id + "/pause").c_str(), "", "application/json"))["paused"],
            true);
  EXPECT_EQ(body(c.Post(("/v1/jobs/" + id + "/resume").c_str(), "", "application/json"))["paused"],
            false);
  const auto bad = c.Post("/v1/jobs", R"({"name": "x", "schedule": "0 3 * *", "dataset": "d"})",
                          "application/json");
  EXPECT_EQ(bad->status, 400);
  EXPECT_EQ(body(bad)["error"]["parameter"], "schedule");
  // A JSON body sent form-encoded (curl -d) is read as JSON all the same.
  const auto form =
      c.Post("/v1/jobs", R"({"name": "form", "schedule": "0 4 * * *", "dataset": "d"})",
             "application/x-www-form-urlencoded");
  EXPECT_EQ(form->status, 201) << form->body;
  EXPECT_EQ(c.Delete(("/v1/jobs/" + id).c_str())->status, 200);
  EXPECT_EQ(c.Get(("/v1/jobs/" + id).c_str())->status, 404);
}

}  // namespace
}  // namespace clearsky::server
