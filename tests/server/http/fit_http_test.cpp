// Fits over HTTP end to end (docs/fits.md "Over HTTP") on a real server (data_server_fixture.h):
// a Preetham turbidity fit POSTed on a dataset Preetham made at turbidity 3.4 answers 202 with
// its Location, is followed until it succeeded, finds 3.4 back, and its stored fields agree
// with the request; a POST without the token is a 401; unknown fits and datasets are 404s.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "storage/repositories/fit_repository.h"
#include "tests/server/http/data_server_fixture.h"
#include "tests/support/model_made_dataset.h"

namespace clearsky::server {
namespace {

class FitOverHttp : public testing::DataServerFixture {
 protected:
  void SetUp() override {
    start(std::string("t0ken"));
    storage::Database db = storage::Database::open(db_path);
    ModelConfig truth;
    truth.atmosphere.turbidity = 3.4;
    clearsky::testing::store_model_made_dataset(db, "made", "preetham", truth,
                                                {{30.0, 120.0}, {45.0, 100.0}, {22.0, 170.0}});
  }
  // Polls the fit at location until it is no longer queued or running (at most 120 s: the
  // machine may be loaded), checking that progress never goes back.
  nlohmann::json finished_fit(const std::string& location) const {
    nlohmann::json state;
    double progress = 0;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (std::chrono::steady_clock::now() < deadline) {
      const auto r = client().Get(location.c_str());
      if (!r || r->status != 200) return nullptr;
      state = body(r);
      EXPECT_GE(state["progress"].get<double>(), progress);
      progress = state["progress"].get<double>();
      if (state["status"] != "queued" && state["status"] != "running") break;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return state;
  }
};

constexpr const char* kFit =
    R"({"dataset": "made", "model": "preetham", "free": ["turbidity"],
        "bounds": {"turbidity": [2, 6]}, "per_capture": true, "cross_validate": true})";

TEST_F(FitOverHttp, PostedFitRunsAndFindsTheTurbidityBack) {
  const auto accepted = client("t0ken").Post("/v1/fits", kFit, "application/json");
  ASSERT_TRUE(accepted);
  ASSERT_EQ(accepted->status, 202) << accepted->body;
  const std::string location = accepted->get_header_value("Location");
  const nlohmann::json queued = body(accepted);
  EXPECT_EQ(location, "/v1/fits/" + std::to_string(queued["id"].get<int>()));
  EXPECT_TRUE(queued["status"] == "queued" || queued["status"] == "running") << queued;

  const nlohmann::json fit = finished_fit(location);
  ASSERT_EQ(fit["status"], "succeeded") << fit.dump();
  EXPECT_NEAR(fit["values"]["turbidity"].get<double>(), 3.4, 0.05);
  EXPECT_LT(fit["rmse_after"].get<double>(), 0.1 * fit["rmse_before"].get<double>());
  EXPECT_LT(fit["cross_validated_rmse"].get<double>(), 0.1 * fit["rmse_before"].get<double>());
  EXPECT_EQ(fit["dataset"], "made");
  EXPECT_EQ(fit["model"], "preetham");
  EXPECT_EQ(fit["progress"], 1.0);
  EXPECT_EQ(fit["free_parameters"][0]["min"], 2.0);
  EXPECT_EQ(fit["free_parameters"][0]["max"], 6.0);
  EXPECT_EQ(fit["settings"]["per_capture"], true);
  EXPECT_EQ(fit["settings"]["cross_validate"], true);
  ASSERT_EQ(fit["captures_fitted"].size(), 3u);
  for (const auto& capture : fit["captures_fitted"])
    EXPECT_NEAR(capture["own_values"]["turbidity"].get<double>(), 3.4, 0.1) << capture;
  EXPECT_FALSE(fit["finished_utc"].is_null());

  // The row behind the answer holds the same.
  storage::Database db = storage::Database::open(db_path);
  const auto stored = storage::FitRepository(db).get(fit["id"].get<std::int64_t>());
  ASSERT_TRUE(stored.has_value());
  EXPECT_EQ(stored->fit.status, "succeeded");
  ASSERT_TRUE(stored->outcome.has_value());
  EXPECT_DOUBLE_EQ(stored->outcome->rmse_after, fit["rmse_after"].get<double>());
  EXPECT_EQ(stored->fit.software_version, "test");

  const auto list = client().Get("/v1/fits");
  ASSERT_TRUE(list);
  ASSERT_EQ(list->status, 200);
  ASSERT_EQ(body(list).size(), 1u);
  EXPECT_EQ(body(list)[0]["values"], fit["values"]);
}

TEST_F(FitOverHttp, TokenAndUnknownsAreRefused) {
  const auto unauthorized = client().Post("/v1/fits", kFit, "application/json");
  ASSERT_TRUE(unauthorized);
  EXPECT_EQ(unauthorized->status, 401);
  const auto unknown_dataset = client("t0ken").Post(
      "/v1/fits", R"({"dataset": "none", "model": "preetham"})", "application/json");
  ASSERT_TRUE(unknown_dataset);
  EXPECT_EQ(unknown_dataset->status, 404);
  EXPECT_EQ(body(unknown_dataset)["error"]["code"], "unknown_dataset");
  const auto unknown_fit = client().Get("/v1/fits/42");
  ASSERT_TRUE(unknown_fit);
  EXPECT_EQ(unknown_fit->status, 404);
  EXPECT_EQ(body(unknown_fit)["error"]["code"], "unknown_fit");
  const auto list = client().Get("/v1/fits");
  ASSERT_TRUE(list);
  EXPECT_EQ(list->body, "[]");
}

}  // namespace
}  // namespace clearsky::server
