// A stored fit used by the sky endpoints and evaluations (docs/fits.md "Using a fit") through
// the real `clearsky serve` and its real database: a Preetham turbidity fit is POSTed on a
// dataset Preetham made at turbidity 3.4 and followed to `succeeded`; then /v1/radiance with
// fit=ID answers exactly what the explicit turbidity answers and says which fit, every sky
// endpoint takes it (GET and POST alike), fit=latest is not cached, an evaluation with the fit
// records it in its run, and the refusals name the parameter. Timeouts are generous (a loaded
// machine); nothing asserts a duration.
#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <nlohmann/json.hpp>
#include <thread>

#include "storage/repositories/dataset_repository.h"
#include "storage/repositories/fit_repository.h"
#include "tests/server/http/hostile_clients.h"
#include "tests/server/http/watched_serve_process.h"
#include "tests/support/model_made_dataset.h"
#include "tests/support/stored_fit.h"

namespace clearsky::server {
namespace {

using testing::WatchedServeProcess;

const std::string kSky = "&sun_zenith=30&sun_azimuth=135";
const std::string kView = kSky + "&view_zenith=45&view_azimuth=0&wavelengths=450,550,650";
const httplib::Headers kToken = {{"Authorization", "Bearer t0ken"}};

nlohmann::json json_of(const httplib::Result& r) {
  return nlohmann::json::parse(r->body, nullptr, false);
}

class FitUseOverHttp : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    server_ = std::make_unique<WatchedServeProcess>(std::vector<std::string>{
        "--models", "preetham,hosek", "--prebuild-three", "false", "--token", "t0ken"});
    ASSERT_GT(server_->port(), 0) << server_->log();
    ASSERT_TRUE(testing::ready(server_->port(), std::chrono::seconds(300))) << server_->log();
    {
      storage::Database db = storage::Database::open(database());
      ModelConfig truth;
      truth.atmosphere.turbidity = 3.4;
      clearsky::testing::store_model_made_dataset(db, "made", "preetham", truth,
                                                  {{30.0, 120.0}, {45.0, 100.0}});
    }
    auto c = server_->client(120);
    const auto accepted = c.Post("/v1/fits", kToken,
                                 R"({"dataset": "made", "model": "preetham", "free": ["turbidity"],
                                     "bounds": {"turbidity": [2, 6]}, "grid": [9]})",
                                 "application/json");
    ASSERT_TRUE(accepted);
    ASSERT_EQ(accepted->status, 202) << accepted->body;
    const std::string location = accepted->get_header_value("Location");
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(300);
    while (std::chrono::steady_clock::now() < deadline) {
      const auto r = c.Get(location);
      ASSERT_TRUE(r);
      fit_ = json_of(r);
      if (fit_["status"] != "queued" && fit_["status"] != "running") break;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    ASSERT_EQ(fit_["status"], "succeeded") << fit_.dump();
  }
  static void TearDownTestSuite() { server_.reset(); }
  void SetUp() override {
    if (!server_ || fit_.value("status", "") != "succeeded")
      GTEST_SKIP() << "the suite's server or fit did not start (see SetUpTestSuite)";
  }

  static std::filesystem::path database() { return server_->directory() / "db.sqlite"; }
  static httplib::Client client() { return server_->client(120); }
  static std::string id() { return std::to_string(fit_["id"].get<std::int64_t>()); }
  static double turbidity() { return fit_["values"]["turbidity"].get<double>(); }
  // The shortest text of the fitted value (nlohmann's, which round-trips as the server's does).
  static std::string turbidity_text() { return nlohmann::json(turbidity()).dump(); }
  // Whether a Clearsky-Fit header names the fit and its turbidity ("12; turbidity=2.348").
  static bool names_the_fit(const std::string& header) {
    const std::string prefix = id() + "; turbidity=";
    return header.starts_with(prefix) && std::stod(header.substr(prefix.size())) == turbidity();
  }
  // The refusal's code and parameter.
  static std::pair<std::string, std::string> refusal(const httplib::Result& r, int status) {
    EXPECT_TRUE(r);
    if (!r) return {};
    EXPECT_EQ(r->status, status) << r->body;
    const nlohmann::json error = json_of(r)["error"];
    return {error["code"].get<std::string>(), error["parameter"].get<std::string>()};
  }

  static std::unique_ptr<WatchedServeProcess> server_;
  static nlohmann::json fit_;
};

std::unique_ptr<WatchedServeProcess> FitUseOverHttp::server_;
nlohmann::json FitUseOverHttp::fit_;

TEST_F(FitUseOverHttp, RadianceWithTheFitEqualsTheExplicitValuesAndSaysWhichFit) {
  auto c = client();
  const auto by_fit = c.Get("/v1/radiance?model=preetham&fit=" + id() + kView);
  const auto given = c.Get("/v1/radiance?model=preetham&turbidity=" + turbidity_text() + kView);
  ASSERT_TRUE(by_fit && given);
  ASSERT_EQ(by_fit->status, 200) << by_fit->body;
  ASSERT_EQ(given->status, 200) << given->body;
  nlohmann::json a = json_of(by_fit);
  const nlohmann::json b = json_of(given);
  EXPECT_EQ(a["samples"], b["samples"]);  // to the bit
  EXPECT_EQ(a["fit"], nlohmann::json({{"id", fit_["id"]},
                                      {"model", "preetham"},
                                      {"model_version", fit_["model_version"]},
                                      {"dataset", "made"},
                                      {"parameters", {{"turbidity", turbidity()}}}}));
  EXPECT_FALSE(b.contains("fit"));
  a.erase("fit");
  EXPECT_EQ(a, b);  // nothing else differs
  EXPECT_TRUE(names_the_fit(by_fit->get_header_value("Clearsky-Fit")))
      << by_fit->get_header_value("Clearsky-Fit");
  // A succeeded fit never changes: fit=ID stays cacheable.
  EXPECT_EQ(by_fit->get_header_value("Cache-Control"), given->get_header_value("Cache-Control"));
}

TEST_F(FitUseOverHttp, EverySkyEndpointTakesTheFitInTheQueryOrTheBody) {
  auto c = client();
  for (const std::string& target :
       {"/v1/rgb?model=preetham&fit=" + id() + kSky + "&view_zenith=45&view_azimuth=0",
        "/v1/irradiance?model=preetham&fit=" + id() + kSky,
        "/v1/skypatches?model=preetham&output=luminance&fit=" + id() + kSky,
        "/v1/irradiance/series?model=preetham&fit=" + id() +
            "&lat=42.44&lon=-76.5&start=2013-05-27T10:00:00-04:00&end=2013-05-27T12:00:00-04:00",
        // A sky matrix (one vector per step) carries the fit as the single vector does.
        "/v1/skypatches?model=preetham&output=luminance&fit=" + id() +
            "&lat=42.44&lon=-76.5&start=2013-05-27T10:00:00-04:00&end=2013-05-27T12:00:00-04:00"}) {
    const auto r = c.Get(target);
    ASSERT_TRUE(r) << target;
    ASSERT_EQ(r->status, 200) << target << ": " << r->body;
    EXPECT_EQ(json_of(r)["fit"]["id"], fit_["id"]) << target;
    EXPECT_TRUE(names_the_fit(r->get_header_value("Clearsky-Fit"))) << target;
  }
  const auto image = c.Get("/v1/skydome?model=preetham&size=16&fit=" + id() + kSky);
  ASSERT_TRUE(image);
  ASSERT_EQ(image->status, 200) << image->body.substr(0, 300);
  EXPECT_TRUE(names_the_fit(image->get_header_value("Clearsky-Fit")));
  EXPECT_NE(image->body.find("clearskyFit"), std::string::npos);  // the EXR attribute

  // POST bodies: the same member as a query parameter.
  const std::string batch = R"({"model": "preetham", "fit": )" + id() +
                            R"(, "sun_zenith": 30, "sun_azimuth": 135, "views": [[45, 0]]})";
  for (const char* path : {"/v1/radiance", "/v1/rgb"}) {
    const auto r = c.Post(path, batch, "application/json");
    ASSERT_TRUE(r) << path;
    ASSERT_EQ(r->status, 200) << path << ": " << r->body;
    EXPECT_EQ(json_of(r)["fit"]["parameters"]["turbidity"], turbidity()) << path;
  }
}

TEST_F(FitUseOverHttp, LatestIsTheNewestFitOfTheModelAndIsNotCached) {
  auto c = client();
  for (const std::string latest : {"latest", "latest:made"}) {
    const auto r = c.Get("/v1/radiance?model=preetham&fit=" + latest + kView);
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200) << r->body;
    EXPECT_EQ(json_of(r)["fit"]["id"], fit_["id"]) << latest;
    EXPECT_EQ(r->get_header_value("Cache-Control"), "no-store") << latest;
  }
  EXPECT_EQ(refusal(c.Get("/v1/radiance?model=hosek&fit=latest" + kView), 404),
            std::make_pair(std::string("unknown_fit"), std::string("fit")));
  EXPECT_EQ(refusal(c.Get("/v1/radiance?model=preetham&fit=latest:other" + kView), 404),
            std::make_pair(std::string("unknown_fit"), std::string("fit")));
}

TEST_F(FitUseOverHttp, RefusalsNameTheParameter) {
  auto c = client();
  using Refusal = std::pair<std::string, std::string>;
  EXPECT_EQ(refusal(c.Get("/v1/radiance?model=preetham&fit=" + id() + "&turbidity=3" + kView), 400),
            Refusal("conflicting_parameters", "turbidity"));
  EXPECT_EQ(refusal(c.Get("/v1/radiance?model=preetham&fit=first" + kView), 400),
            Refusal("invalid_parameter", "fit"));
  EXPECT_EQ(refusal(c.Get("/v1/radiance?model=preetham&fit=9999" + kView), 404),
            Refusal("unknown_fit", "fit"));
  EXPECT_EQ(refusal(c.Get("/v1/radiance?model=hosek&fit=" + id() + kView), 409),
            Refusal("fit_model_mismatch", "fit"));
  // A fit still running (written into the server's database as the fit worker would).
  std::int64_t running = 0;
  {
    storage::Database db = storage::Database::open(database());
    const auto made = storage::DatasetRepository(db).find("made");
    ASSERT_TRUE(made.has_value());
    running =
        clearsky::testing::store_fit(db, made->id, "preetham", {{"turbidity", 3.0}}, "running");
  }
  EXPECT_EQ(
      refusal(c.Get("/v1/radiance?model=preetham&fit=" + std::to_string(running) + kView), 409),
      Refusal("fit_not_succeeded", "fit"));
  {
    storage::Database db = storage::Database::open(database());
    storage::FitRepository(db).fail(running, "test: stopped");
  }
}

TEST_F(FitUseOverHttp, AnEvaluationWithTheFitRecordsItInItsRun) {
  auto c = client();
  const std::string body =
      R"({"dataset": "made", "models": ["preetham", "hosek"], "parameters": {"fit": )" + id() +
      "}}";
  const auto accepted = c.Post("/v1/evaluations", kToken, body, "application/json");
  ASSERT_TRUE(accepted);
  ASSERT_EQ(accepted->status, 202) << accepted->body;
  const std::string location = accepted->get_header_value("Location");
  nlohmann::json ticket;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(300);
  while (std::chrono::steady_clock::now() < deadline) {
    ticket = json_of(c.Get(location));
    if (ticket["status"] != "queued" && ticket["status"] != "running") break;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ASSERT_EQ(ticket["status"], "succeeded") << ticket.dump();
  ASSERT_EQ(ticket["runs"].size(), 2u);
  for (const auto& model : ticket["models"]) {
    const auto run = c.Get("/v1/evaluations/" + model["run"].dump());
    ASSERT_TRUE(run);
    ASSERT_EQ(run->status, 200) << run->body;
    const nlohmann::json parameters = json_of(run)["parameters"];
    if (model["model"] == "preetham") {
      // The fit's id and the values it set, as stored with the run.
      EXPECT_EQ(parameters, nlohmann::json({{"fit", fit_["id"]}, {"turbidity", turbidity()}}));
      EXPECT_NEAR(json_of(run)["rmse"].get<double>(), fit_["rmse_after"].get<double>(),
                  1e-6 * fit_["rmse_after"].get<double>());
    } else {
      EXPECT_EQ(parameters, nlohmann::json::object());  // a fit of Preetham leaves Hosek alone
    }
  }

  using Refusal = std::pair<std::string, std::string>;
  EXPECT_EQ(refusal(c.Post("/v1/evaluations", kToken,
                           R"({"dataset": "made", "models": ["hosek"], "parameters": {"fit": )" +
                               id() + "}}",
                           "application/json"),
                    409),
            Refusal("fit_model_mismatch", "fit"));
  EXPECT_EQ(refusal(c.Post("/v1/evaluations", kToken,
                           R"({"dataset": "made", "models": ["preetham"], "parameters": {"fit": )" +
                               id() + R"(, "turbidity": 3}})",
                           "application/json"),
                    400),
            Refusal("conflicting_parameters", "turbidity"));
  // A job checks its fit when it is created, as an evaluation does.
  EXPECT_EQ(refusal(c.Post("/v1/jobs", kToken,
                           R"({"name": "refit", "schedule": "0 3 * * *", "dataset": "made",
                               "models": ["hosek"], "parameters": {"fit": "latest"}})",
                           "application/json"),
                    404),
            Refusal("unknown_fit", "fit"));
  const auto job = c.Post("/v1/jobs", kToken,
                          R"({"name": "refit", "schedule": "0 3 * * *", "dataset": "made",
                              "models": ["preetham"], "parameters": {"fit": "latest"}})",
                          "application/json");
  ASSERT_TRUE(job);
  EXPECT_EQ(job->status, 201) << job->body;
  EXPECT_EQ(json_of(job)["parameters"], nlohmann::json({{"fit", "latest"}}));
}

}  // namespace
}  // namespace clearsky::server
