// Durability of evaluation tickets (docs/data-api.md "Evaluation tickets" and "Durability") with
// the real `clearsky serve` binary: a three-model evaluation is accepted, the server is killed
// with SIGKILL while the first model's run is running (the two others still queued), and the
// server restarted on the same database answers the ticket: interrupted, the running model with
// its run (failed as interrupted), the queued ones listed without a run and interrupted; a new
// ticket gets the next id, never the old one.
#include <gtest/gtest.h>
#include <httplib.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <thread>

#include "storage/repositories/capture_repository.h"
#include "storage/repositories/dataset_repository.h"
#include "storage/schema/migrations.h"
#include "tests/models/evaluation/function_model.h"
#include "tests/server/durability/background_work_client.h"
#include "tests/server/http/serve_process.h"
#include "tests/support/temp_dir.h"

namespace clearsky::server {
namespace {

using namespace std::chrono_literals;

double sky(const ViewDirection&, double) { return 0.05; }

void add_synthetic_dataset(const std::filesystem::path& path) {
  storage::Database db = storage::open_database(path);
  storage::Transaction t(db);
  const auto dataset = storage::DatasetRepository(db).find_or_create("synthetic", "kider2014");
  for (int i = 0; i < 2; ++i) {
    MeasuredCapture c = clearsky::testing::synthetic_capture(sky, 40.0 + 5.0 * i, 125.0);
    c.label = "capture " + std::to_string(i);
    c.unix_time_utc_s += 900.0 * i;
    storage::CaptureRepository(db).insert(dataset, c, "hash" + std::to_string(i), "test");
  }
  t.commit();
}

TEST(TicketDurability, ServerKilledDuringAMultiModelEvaluationKeepsTheTicket) {
  clearsky::testing::TempDir dir;
  add_synthetic_dataset(dir.path / "sky.db");
  const std::string body =
      R"({"dataset": "synthetic", "models": ["bruneton", "preetham", "hosek"]})";

  std::string location;
  std::int64_t ticket_id = 0;
  nlohmann::json at_kill;
  {
    // Bruneton first: its table precomputation keeps its run running long enough to be killed
    // with the two analytic models still queued.
    testing::ServeProcess server(dir.path, {"--token", testing::kDurabilityToken},
                                 "bruneton,preetham,hosek");
    ASSERT_GT(server.port(), 0) << server.log();
    auto c = testing::token_client(server);
    const auto accepted = c.Post("/v1/evaluations", body, "application/json");
    ASSERT_TRUE(accepted) << httplib::to_string(accepted.error());
    ASSERT_EQ(accepted->status, 202) << accepted->body;
    location = accepted->get_header_value("Location");
    const nlohmann::json queued = nlohmann::json::parse(accepted->body);
    ticket_id = queued["ticket"].get<std::int64_t>();
    ASSERT_EQ(queued["models"].size(), 3u) << queued.dump();
    EXPECT_EQ(queued["models"][2]["model"], "hosek");
    EXPECT_TRUE(queued["models"][2]["run"].is_null());
    // Generous deadline: a loaded machine or a sanitizer build is several times slower.
    const auto deadline = std::chrono::steady_clock::now() + 120s;
    while (std::chrono::steady_clock::now() < deadline) {
      at_kill = testing::get_json(c, location);
      ASSERT_TRUE(at_kill.is_object()) << "no answer from the server";
      if (at_kill["models"][0]["status"] == "running") break;
      ASSERT_TRUE(at_kill["status"] == "queued" || at_kill["status"] == "running")
          << at_kill.dump();
      std::this_thread::sleep_for(5ms);
    }
    ASSERT_EQ(at_kill["models"][0]["status"], "running") << at_kill.dump();
    EXPECT_EQ(server.kill_now(), SIGKILL);
  }
  ASSERT_EQ(at_kill["models"][1]["status"], "queued") << at_kill.dump();
  const std::int64_t run_id = at_kill["models"][0]["run"].get<std::int64_t>();

  testing::ServeProcess server(dir.path, {"--token", testing::kDurabilityToken}, "preetham");
  ASSERT_GT(server.port(), 0) << server.log();
  auto c = testing::token_client(server);
  const nlohmann::json after = testing::get_json(c, location);
  ASSERT_TRUE(after.is_object()) << "the ticket does not answer after the restart";
  EXPECT_EQ(after["ticket"], ticket_id);
  EXPECT_EQ(after["status"], "interrupted") << after.dump();
  EXPECT_FALSE(after["finished"].is_null());
  EXPECT_NE(after["error"].get<std::string>().find("interrupted"), std::string::npos);
  ASSERT_EQ(after["models"].size(), 3u) << after.dump();
  EXPECT_EQ(after["models"][0]["model"], "bruneton");
  EXPECT_EQ(after["models"][0]["run"], run_id);
  EXPECT_EQ(after["models"][0]["status"], "interrupted");
  for (int i = 1; i < 3; ++i) {
    EXPECT_EQ(after["models"][i]["status"], "interrupted") << after.dump();
    EXPECT_TRUE(after["models"][i]["run"].is_null()) << after.dump();
    EXPECT_NE(after["models"][i]["error"].get<std::string>().find("before"), std::string::npos);
  }
  EXPECT_EQ(after["runs"], nlohmann::json::array({run_id}));
  const nlohmann::json run = testing::get_json(c, "/v1/evaluations/" + std::to_string(run_id));
  EXPECT_EQ(run["status"], "failed") << run.dump();
  EXPECT_NE(run["error"].get<std::string>().find("interrupted"), std::string::npos);

  // The next ticket gets the next id: an old ticket's id never names a new evaluation.
  const auto again = c.Post(
      "/v1/evaluations", R"({"dataset": "synthetic", "models": ["preetham"]})", "application/json");
  ASSERT_TRUE(again);
  ASSERT_EQ(again->status, 202) << again->body;
  EXPECT_EQ(nlohmann::json::parse(again->body)["ticket"], ticket_id + 1);
  const nlohmann::json done = testing::await_end(c, again->get_header_value("Location"));
  EXPECT_EQ(done["status"], "succeeded") << done.dump();
  EXPECT_EQ(testing::get_json(c, location)["status"], "interrupted");
}

}  // namespace
}  // namespace clearsky::server
