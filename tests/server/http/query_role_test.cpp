// A query replica (`clearsky serve --role query`, docs/deploy.md "Roles"), the real process:
// it serves the sky endpoints without a database, opens none (no file appears where the default
// --db would be), answers every data endpoint, writes included, 404 no_database naming the
// role (a sky request naming a stored fit: naming fit), and refuses to start with a --db (a
// usage error).
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <thread>

#include "tests/server/http/watched_serve_process.h"

namespace clearsky::server {
namespace {

using testing::WatchedServeProcess;

nlohmann::json error_of(const httplib::Result& r) {
  return nlohmann::json::parse(r->body)["error"];
}

TEST(QueryRole, ServesTheSkyWithoutADatabaseAndRefusesTheDataEndpointsNamingTheRole) {
  WatchedServeProcess server(
      {"--role", "query", "--models", "preetham", "--prebuild-three", "false", "--token", "t0ken"},
      0, WatchedServeProcess::Database::none);
  ASSERT_GT(server.port(), 0) << server.log();
  EXPECT_NE(server.log().find("role query"), std::string::npos) << server.log();
  auto c = server.client();

  const std::string query =
      "/v1/radiance?model=preetham&sun_zenith=40&sun_azimuth=90&view_zenith=50&view_azimuth=180";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  int status = 0;
  std::string answer;
  while (std::chrono::steady_clock::now() < deadline) {
    const auto r = c.Get(query);
    status = r ? r->status : 0;
    answer = r ? r->body : "";
    if (status != 0 && status != 503) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  EXPECT_EQ(status, 200) << answer;
  const auto ready = c.Get("/readyz");
  ASSERT_TRUE(ready);
  EXPECT_EQ(ready->status, 200) << ready->body;

  for (const char* path : {"/v1/datasets", "/v1/imports", "/v1/evaluations", "/v1/jobs",
                           "/v1/datasets/x", "/v1/jobs/1", "/v1/aerosols", "/v1/aerosols/1"}) {
    const auto r = c.Get(path);
    ASSERT_TRUE(r) << path;
    EXPECT_EQ(r->status, 404) << path;
    EXPECT_EQ(error_of(r)["code"], "no_database") << path;
    EXPECT_EQ(error_of(r)["parameter"], "role") << path;
  }
  // Writes too, with or without the token: a replica has nothing to write to.
  httplib::Headers with_token = {{"Authorization", "Bearer t0ken"}};
  const auto job = c.Post("/v1/jobs", with_token, "{}", "application/json");
  ASSERT_TRUE(job);
  EXPECT_EQ(job->status, 404);
  EXPECT_EQ(error_of(job)["parameter"], "role");
  const auto aerosols = c.Post("/v1/aerosols?name=a", with_token, "x", "text/plain");
  ASSERT_TRUE(aerosols);
  EXPECT_EQ(aerosols->status, 404);
  EXPECT_EQ(error_of(aerosols)["code"], "no_database");
  const auto removal = c.Delete("/v1/datasets/x");
  ASSERT_TRUE(removal);
  EXPECT_EQ(removal->status, 404);
  EXPECT_EQ(error_of(removal)["code"], "no_database");
  // A sky request naming a stored fit needs the database too (docs/fits.md "Using a fit").
  const auto with_fit = c.Get(query + "&fit=1");
  ASSERT_TRUE(with_fit);
  EXPECT_EQ(with_fit->status, 404);
  EXPECT_EQ(error_of(with_fit)["code"], "no_database");
  EXPECT_EQ(error_of(with_fit)["parameter"], "fit");

  EXPECT_TRUE(server.alive());
  EXPECT_FALSE(std::filesystem::exists(server.directory() / "var")) << server.log();
}

TEST(QueryRole, AQueryReplicaWithADatabaseIsAUsageError) {
  WatchedServeProcess server({"--role", "query", "--models", "preetham"});
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (server.alive() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ASSERT_FALSE(server.alive());
  // CLI11's validation error (a usage error: the process never started serving).
  EXPECT_GT(server.exit_status(), 0);
  EXPECT_NE(server.log().find("no database"), std::string::npos) << server.log();
  EXPECT_FALSE(std::filesystem::exists(server.directory() / "db.sqlite"));
}

}  // namespace
}  // namespace clearsky::server
