// Durability of fits started over HTTP (docs/fits.md "Over HTTP", docs/data-api.md
// "Durability") with the real `clearsky serve` binary: two long fits are accepted (one
// running on the single fit worker, one queued), the server is killed with SIGKILL while the
// first runs, and the server restarted on the same database answers both as interrupted; a new
// fit then runs to its end.
#include <gtest/gtest.h>
#include <httplib.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <thread>

#include "storage/schema/migrations.h"
#include "tests/server/durability/background_work_client.h"
#include "tests/server/http/serve_process.h"
#include "tests/support/model_made_dataset.h"
#include "tests/support/temp_dir.h"

namespace clearsky::server {
namespace {

using namespace std::chrono_literals;

std::string post_fit(httplib::Client& c, const std::string& body) {
  const auto accepted = c.Post("/v1/fits", body, "application/json");
  if (!accepted || accepted->status != 202) {
    ADD_FAILURE() << (accepted ? accepted->body : httplib::to_string(accepted.error()));
    return "";
  }
  return accepted->get_header_value("Location");
}

TEST(FitDurability, ServerKilledDuringAFitMarksItInterrupted) {
  clearsky::testing::TempDir dir;
  {
    storage::Database db = storage::open_database(dir.path / "sky.db");
    ModelConfig truth;
    truth.atmosphere.turbidity = 3.4;
    clearsky::testing::store_model_made_dataset(db, "made", "hosek", truth,
                                                {{30.0, 120.0}, {45.0, 100.0}, {22.0, 170.0}});
  }
  // A 101 x 101 grid: thousands of model builds, seconds of work even on an idle machine.
  const std::string long_fit =
      R"({"dataset": "made", "model": "hosek", "free": ["turbidity", "albedo"],
          "grid": [101, 101]})";
  std::string running;
  std::string queued;
  {
    testing::ServeProcess server(dir.path, {"--token", testing::kDurabilityToken}, "hosek");
    ASSERT_GT(server.port(), 0) << server.log();
    auto c = testing::token_client(server);
    running = post_fit(c, long_fit);
    queued = post_fit(c, long_fit);
    ASSERT_FALSE(running.empty());
    ASSERT_FALSE(queued.empty());
    nlohmann::json at_kill;
    const auto deadline = std::chrono::steady_clock::now() + 120s;
    while (std::chrono::steady_clock::now() < deadline) {
      at_kill = testing::get_json(c, running);
      ASSERT_TRUE(at_kill.is_object()) << "no answer from the server";
      if (at_kill["status"] == "running" && at_kill["stage"] == "grid") break;
      ASSERT_TRUE(at_kill["status"] == "queued" || at_kill["status"] == "running")
          << at_kill.dump();
      std::this_thread::sleep_for(5ms);
    }
    ASSERT_EQ(at_kill["stage"], "grid") << at_kill.dump();
    EXPECT_EQ(testing::get_json(c, queued)["status"], "queued");
    EXPECT_EQ(server.kill_now(), SIGKILL);
  }

  testing::ServeProcess server(dir.path, {"--token", testing::kDurabilityToken}, "hosek");
  ASSERT_GT(server.port(), 0) << server.log();
  auto c = testing::token_client(server);
  for (const std::string& location : {running, queued}) {
    const nlohmann::json after = testing::get_json(c, location);
    ASSERT_TRUE(after.is_object()) << "the fit does not answer after the restart";
    EXPECT_EQ(after["status"], "interrupted") << after.dump();
    EXPECT_FALSE(after["finished_utc"].is_null());
    EXPECT_NE(after["error"].get<std::string>().find("interrupted"), std::string::npos);
  }
  const std::string next =
      post_fit(c, R"({"dataset": "made", "model": "hosek", "free": ["turbidity"], "grid": [5]})");
  ASSERT_FALSE(next.empty());
  const nlohmann::json done = testing::await_end(c, next);
  EXPECT_EQ(done["status"], "succeeded") << done.dump();
}

}  // namespace
}  // namespace clearsky::server
