// The open sky-radiance format (docs/measurement-formats.md) and the site and clock of archive
// imports (docs/data-api.md), against `clearsky serve` with its SQLite database:
// - a CSV and a JSON file that Preetham made with its default parameters, at a site and times
//   of their own, round trip through import and evaluation with an RMSE of Preetham of ~0; a
//   direction measured over too narrow a range is excluded and counted;
// - malformed uploads are refused before 202 naming the column or member and the row, an
//   unsupported media type is 415, a CSV sent as a Kider archive is refused up front;
// - no answer names a server path.
#include <gtest/gtest.h>
#include <httplib.h>

#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "api/parse/iso8601_time.h"
#include "models/core/numeric.h"
#include "models/evaluation/capture_preparation.h"
#include "models/registry.h"
#include "tests/server/durability/background_work_client.h"
#include "tests/server/http/hostile_clients.h"
#include "tests/server/http/serve_process.h"
#include "tests/support/temp_dir.h"

namespace clearsky::server {
namespace {

nlohmann::json json_of(const httplib::Result& r) { return nlohmann::json::parse(r->body); }

// The final state of the work at location (an import, an evaluation ticket).
nlohmann::json finished(httplib::Client& c, const std::string& location) {
  return testing::await_end(c, location, std::chrono::seconds(300));
}

// A started server, ready, and a client of it with the write token.
struct Served {
  clearsky::testing::TempDir dir;
  testing::ServeProcess serve{dir.path, {"--token", testing::kDurabilityToken}};
  httplib::Client client = testing::token_client(serve);
  bool ready() const { return testing::ready(serve.port(), std::chrono::seconds(120)); }
};

// One measured value of the made sky.
struct Row {
  std::string time;
  double view_zenith = 0, view_azimuth = 0, wavelength_nm = 0, radiance = 0;
};

constexpr double kLatitude = 48.8566;
constexpr double kLongitude = 2.3522;
constexpr double kElevation = 35.0;

// What Preetham (default parameters) answers at two instants in Paris (UTC+02:00), for 12
// directions on the model's grid wavelengths (those the evaluation compares), plus values
// outside the compared range (not compared) and a 13th direction measured only over
// 500..600 nm (excluded: it does not reach every compared wavelength). The sun is the
// evaluation's own (capture_preparation.h: SPA from the time and the site).
std::vector<Row> preetham_made_rows() {
  const ModelFactory* factory = find_model("preetham");
  const std::shared_ptr<const SkyModel> model = factory->create(ModelConfig{}, {});
  const std::vector<double>& grid = model->wavelengths().nanometres();
  std::vector<Row> rows;
  for (const std::string time : {"2024-06-21T10:00:00+02:00", "2024-06-21T11:30:00+02:00"}) {
    MeasuredCapture capture;
    capture.unix_time_utc_s = api::parse_iso8601_time(time).unix_time_utc_s;
    capture.site = {kLatitude, kLongitude, kElevation};
    compute_sun_position(capture);
    const auto sun = model->prepare_sun(
        {capture.sun_zenith_computed_deg * kDegree, capture.sun_azimuth_computed_deg * kDegree});
    std::vector<ViewDirection> views;
    for (double zenith : {20.0, 50.0, 75.0})
      for (double azimuth : {0.0, 90.0, 180.0, 270.0}) views.push_back({zenith, azimuth});
    views.push_back({35.0, 45.0});
    std::vector<ViewDirection> radians;
    for (const ViewDirection& v : views)
      radians.push_back({v.zenith_rad * kDegree, v.azimuth_rad * kDegree});
    SpectralBatch batch;
    model->sky_radiance(*sun, Viewpoint{}, radians, batch);
    for (std::size_t v = 0; v < views.size(); ++v) {
      const bool narrow = v + 1 == views.size();
      for (std::size_t i = 0; i < grid.size(); ++i) {
        if (narrow && (grid[i] < 500 || grid[i] > 600)) continue;
        rows.push_back(
            {time, views[v].zenith_rad, views[v].azimuth_rad, grid[i], batch.spectrum(v)[i]});
      }
    }
  }
  return rows;
}

std::string number(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

std::string csv_of(const std::vector<Row>& rows) {
  std::string csv =
      "time,latitude,longitude,elevation_m,view_zenith,view_azimuth,wavelength_nm,radiance\n";
  for (const Row& r : rows)
    csv += r.time + "," + number(kLatitude) + "," + number(kLongitude) + "," + number(kElevation) +
           "," + number(r.view_zenith) + "," + number(r.view_azimuth) + "," +
           number(r.wavelength_nm) + "," + number(r.radiance) + "\n";
  return csv;
}

std::string json_text_of(const std::vector<Row>& rows) {
  nlohmann::json samples = nlohmann::json::array();
  for (const Row& r : rows)
    samples.push_back({{"time", r.time},
                       {"view_zenith", r.view_zenith},
                       {"view_azimuth", r.view_azimuth},
                       {"wavelength_nm", r.wavelength_nm},
                       {"radiance", r.radiance}});
  return nlohmann::json{
      {"site", {{"latitude", kLatitude}, {"longitude", kLongitude}, {"elevation_m", kElevation}}},
      {"samples", std::move(samples)}}
      .dump();
}

// Imports body into dataset name and evaluates Preetham on it; returns the run.
nlohmann::json import_and_evaluate(httplib::Client& c, const std::string& name,
                                   const std::string& body, const std::string& content_type) {
  const auto accepted = c.Post(("/v1/datasets?name=" + name).c_str(), body, content_type.c_str());
  EXPECT_TRUE(accepted);
  if (!accepted) return {};
  EXPECT_EQ(accepted->status, 202) << accepted->body;
  const nlohmann::json import = finished(c, accepted->get_header_value("Location"));
  EXPECT_EQ(import["status"], "succeeded") << import.dump();
  const auto ticket =
      c.Post("/v1/evaluations", nlohmann::json{{"dataset", name}, {"models", {"preetham"}}}.dump(),
             "application/json");
  EXPECT_TRUE(ticket);
  if (!ticket) return {};
  EXPECT_EQ(ticket->status, 202) << ticket->body;
  const nlohmann::json done = finished(c, ticket->get_header_value("Location"));
  EXPECT_EQ(done["status"], "succeeded") << done.dump();
  const auto run = c.Get(("/v1/evaluations/" + std::to_string(done["runs"][0].get<int>())).c_str());
  EXPECT_TRUE(run && run->status == 200);
  return run ? json_of(run) : nlohmann::json{};
}

void expect_preetham_finds_its_own_sky(const nlohmann::json& run) {
  ASSERT_EQ(run["status"], "succeeded") << run.dump();
  // The model's own values at its own wavelengths: 0 up to the rounding of 17 digits.
  EXPECT_LT(run["rmse"].get<double>(), 1e-9) << run.dump();
  EXPECT_EQ(run["samples_compared"], 24);
  EXPECT_EQ(run["samples_excluded"], 2);
  ASSERT_EQ(run["captures"].size(), 2u);
  for (const nlohmann::json& capture : run["captures"]) {
    EXPECT_EQ(capture["samples_compared"], 12);
    ASSERT_EQ(capture["excluded"].size(), 1u) << capture.dump();
    EXPECT_EQ(capture["excluded"][0]["reason"], "wavelength_out_of_range") << capture.dump();
    EXPECT_EQ(capture["excluded"][0]["samples"], nlohmann::json::array({12})) << capture.dump();
  }
  EXPECT_EQ(run["captures"][0]["label"], "2024-06-21T10:00:00+02:00");
}

TEST(SkyRadianceImport, AModelMadeCsvAndJsonRoundTripWithAnRmseOfZero) {
  Served s;
  ASSERT_TRUE(s.ready()) << s.serve.log();
  httplib::Client& c = s.client;
  const std::vector<Row> rows = preetham_made_rows();
  expect_preetham_finds_its_own_sky(import_and_evaluate(c, "made-csv", csv_of(rows), "text/csv"));
  expect_preetham_finds_its_own_sky(
      import_and_evaluate(c, "made-json", json_text_of(rows), "application/json"));
  // The dataset keeps each capture's site and clock, and its sun from them.
  const nlohmann::json dataset = json_of(c.Get("/v1/datasets/made-csv"));
  EXPECT_EQ(dataset["format"], "sky-radiance");
  EXPECT_EQ(dataset["captures"][0]["time"], "2024-06-21T10:00:00+02:00");
  EXPECT_EQ(dataset["captures"][0]["place"]["latitude"], kLatitude);
  EXPECT_EQ(dataset["captures"][0]["samples"], 13);
}

// Every answer of the refusals below, to check that none names a server path.
struct Answer {
  int status = 0;
  nlohmann::json error;
  std::string body;
};

Answer post(httplib::Client& c, const std::string& target, const std::string& body,
            const std::string& content_type) {
  const auto r = c.Post(target.c_str(), body, content_type.c_str());
  if (!r) return {};
  Answer a{r->status, nullptr, r->body};
  const nlohmann::json j = nlohmann::json::parse(r->body, nullptr, false);
  if (j.is_object() && j.contains("error")) a.error = j["error"];
  return a;
}

TEST(SkyRadianceImport, MalformedUploadsAreRefusedBeforeTheyAreAcceptedNamingColumnAndRow) {
  Served s;
  ASSERT_TRUE(s.ready()) << s.serve.log();
  httplib::Client& c = s.client;
  const std::string header =
      "time,latitude,longitude,elevation_m,view_zenith,view_azimuth,wavelength_nm,radiance\n";
  const std::string good = "2024-06-21T10:00:00+02:00,48.85,2.35,35,30,90,550,0.05\n";
  struct Case {
    std::string what, body, content_type;
    int status;
    std::string parameter, in_message;
  };
  const std::vector<Case> cases = {
      {"a bad number", header + good + good.substr(0, good.size() - 5) + "x.05\n", "text/csv", 400,
       "radiance", "row 2 (line 3)"},
      {"a negative radiance", header + good + std::string(good).replace(good.size() - 5, 4, "-1.0"),
       "text/csv", 400, "radiance", "row 2"},
      {"a time without offset", header + "2024-06-21T10:00:00,48.85,2.35,35,30,90,550,0.05\n",
       "text/csv", 400, "time", "row 1"},
      {"a missing column", "time,latitude\n", "text/csv", 400, "longitude", "line 1"},
      {"an unknown column", header.substr(0, header.size() - 1) + ",colour\n", "text/csv", 400,
       "colour", "line 1"},
      {"a short row", header + "2024-06-21T10:00:00+02:00,48.85\n", "text/csv", 400, "body",
       "row 1"},
      {"an azimuth of 360", header + "2024-06-21T10:00:00+02:00,48.85,2.35,35,30,360,550,0.05\n",
       "text/csv", 400, "view_azimuth", "row 1"},
      {"a wavelength twice", header + good + good, "text/csv", 400, "wavelength_nm", "row 2"},
      {"a JSON string for a number",
       R"({"site": {"latitude": 1, "longitude": 2, "elevation_m": 3}, "samples": [{"time": "2024-06-21T10:00:00Z", "view_zenith": 1, "view_azimuth": 2, "wavelength_nm": 500, "radiance": 0.1}, {"time": "2024-06-21T10:00:00Z", "view_zenith": 1, "view_azimuth": 2, "wavelength_nm": 510, "radiance": "0.1"}]})",
       "application/json", 400, "samples[1].radiance", "samples[1]"},
      {"a JSON sample without a site",
       R"({"samples": [{"time": "2024-06-21T10:00:00Z", "view_zenith": 1, "view_azimuth": 2, "wavelength_nm": 500, "radiance": 0.1}]})",
       "application/json", 400, "samples[0].latitude", "site"},
      {"broken JSON", "{\"samples\": [", "application/json", 400, "samples", "not valid JSON"},
      {"an unsupported media type", header + good, "image/png", 415, "Content-Type", "image/png"},
      {"a CSV sent as a Kider archive", header + good, "application/octet-stream", 400, "body",
       "not an archive"},
  };
  for (const Case& k : cases) {
    const Answer a = post(c, "/v1/datasets?name=refused", k.body, k.content_type);
    EXPECT_EQ(a.status, k.status) << k.what << ": " << a.body;
    EXPECT_EQ(a.error["parameter"], k.parameter) << k.what << ": " << a.body;
    EXPECT_NE(a.error["message"].get<std::string>().find(k.in_message), std::string::npos)
        << k.what << ": " << a.body;
    EXPECT_EQ(a.body.find(s.dir.path.string()), std::string::npos) << k.what << ": " << a.body;
    EXPECT_EQ(a.body.find("/tmp"), std::string::npos) << k.what << ": " << a.body;
  }
  // The format against the media type, and what only archives take.
  EXPECT_EQ(post(c, "/v1/datasets?name=r&format=kider", header + good, "text/csv").status, 415);
  const Answer site = post(c, "/v1/datasets?name=r&lat=10", header + good, "text/csv");
  EXPECT_EQ(site.status, 400);
  EXPECT_EQ(site.error["parameter"], "lat");
  // A CSV named as such with format= and no media type of its own is read as CSV.
  const Answer named = post(c, "/v1/datasets?name=named&format=sky-radiance-csv", header + good,
                            "application/x-www-form-urlencoded");
  EXPECT_EQ(named.status, 202) << named.body;
  // Nothing refused was recorded: no import but the accepted one, no dataset but its own.
  const nlohmann::json imports = json_of(c.Get("/v1/imports"));
  EXPECT_EQ(imports.size(), 1u) << imports.dump();
  const nlohmann::json import =
      finished(c, "/v1/imports/" + std::to_string(imports[0]["id"].get<int>()));
  EXPECT_EQ(import["status"], "succeeded") << import.dump();
  EXPECT_EQ(import.dump().find(s.dir.path.string()), std::string::npos) << import.dump();
}

}  // namespace
}  // namespace clearsky::server
