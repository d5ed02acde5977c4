// measured_aerosols with aerosols=ID through the real `clearsky serve` (the writer installs the
// inversion source, server/cli/serve_command.cpp; models/measured_aerosols/README.md "Uploaded
// inversions"): a copy of the shipped Egbert file with its optical depths doubled is uploaded,
// and the radiance of aerosols=ID differs from the shipped file's (aerosols=0 is the shipped
// file's); an id nobody uploaded is a 404 naming aerosols, and so is every id but 0 on a query
// replica.
// Draft tables keep the builds short; the build wait is long so that a loaded machine builds
// instead of answering 503. Nothing asserts a duration.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "models/core/embedded_data.h"
#include "tests/server/http/watched_serve_process.h"

namespace clearsky::server {
namespace {

using testing::WatchedServeProcess;

const std::string kQuery =
    "/v1/radiance?model=measured_aerosols&quality=draft&sun_zenith=40&sun_azimuth=180"
    "&view_zenith=50&view_azimuth=100&wavelengths=450,550,650";

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  for (std::string field; std::getline(in, field, ',');) out.push_back(field);
  return out;
}

// The shipped inversion with every retrieval's tau440(measured) doubled.
std::string egbert_with_doubled_aod() {
  std::stringstream in{std::string(data::embedded_file("aeronet/130527_130527_Egbert.pfn"))};
  std::string out;
  std::size_t column = std::string::npos;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> f = fields(line);
    if (column == std::string::npos) {
      for (std::size_t i = 0; i < f.size(); ++i)
        if (f[i] == "tau440(measured)") column = i;
    } else if (column < f.size()) {
      f[column] = std::to_string(2.0 * std::stod(f[column]));
      line.clear();
      for (std::size_t i = 0; i < f.size(); ++i) line += (i == 0 ? "" : ",") + f[i];
    }
    out += line + "\n";
  }
  EXPECT_NE(column, std::string::npos) << "no tau440(measured) column";
  return out;
}

TEST(AerosolsSelectionServe, AnUploadedInversionIsServedAndAnUnknownIdIsRefusedNamingAerosols) {
  WatchedServeProcess server({"--models", "measured_aerosols", "--prebuild-three", "false",
                              "--prebuild", "measured_aerosols:draft", "--build-wait-ms", "120000",
                              "--builder-threads", "1", "--token", "t0ken"});
  ASSERT_GT(server.port(), 0) << server.log();
  auto c = server.client(600);
  c.set_bearer_token_auth("t0ken");

  const auto created = c.Post("/v1/aerosols?name=doubled", egbert_with_doubled_aod(), "text/plain");
  ASSERT_TRUE(created);
  ASSERT_EQ(created->status, 201) << created->body;
  const std::int64_t id = nlohmann::json::parse(created->body)["id"];

  const auto shipped = c.Get(kQuery);
  ASSERT_TRUE(shipped);
  ASSERT_EQ(shipped->status, 200) << shipped->body << server.log();
  const auto zero = c.Get(kQuery + "&aerosols=0");
  ASSERT_TRUE(zero);
  ASSERT_EQ(zero->status, 200) << zero->body;
  const auto uploaded = c.Get(kQuery + "&aerosols=" + std::to_string(id));
  ASSERT_TRUE(uploaded);
  ASSERT_EQ(uploaded->status, 200) << uploaded->body << server.log();

  const auto radiance = [](const httplib::Result& r) {
    return nlohmann::json::parse(r->body)["samples"][0]["radiance"];
  };
  ASSERT_EQ(radiance(shipped).size(), 3u);
  EXPECT_EQ(radiance(zero), radiance(shipped));
  ASSERT_EQ(radiance(uploaded).size(), 3u);
  for (std::size_t i = 0; i < 3; ++i)
    EXPECT_NE(radiance(uploaded)[i].get<double>(), radiance(shipped)[i].get<double>()) << i;

  const auto unknown = c.Get(kQuery + "&aerosols=999");
  ASSERT_TRUE(unknown);
  EXPECT_EQ(unknown->status, 404) << unknown->body;
  const auto error = nlohmann::json::parse(unknown->body)["error"];
  EXPECT_EQ(error["code"], "unknown_aerosols");
  EXPECT_EQ(error["parameter"], "aerosols");
}

// A query replica has no database, hence no inversion source: every id but 0 is unknown.
TEST(AerosolsSelectionServe, AQueryReplicaAnswersEveryIdButZeroUnknown) {
  WatchedServeProcess server({"--models", "measured_aerosols", "--prebuild-three", "false",
                              "--prebuild", "measured_aerosols:draft", "--build-wait-ms", "120000",
                              "--builder-threads", "1", "--role", "query"},
                             0, WatchedServeProcess::Database::none);
  ASSERT_GT(server.port(), 0) << server.log();
  auto c = server.client(600);
  const auto unknown = c.Get(kQuery + "&aerosols=1");
  ASSERT_TRUE(unknown);
  EXPECT_EQ(unknown->status, 404) << unknown->body;
  const auto error = nlohmann::json::parse(unknown->body)["error"];
  EXPECT_EQ(error["code"], "unknown_aerosols");
  EXPECT_EQ(error["parameter"], "aerosols");
  const auto shipped = c.Get(kQuery + "&aerosols=0");
  ASSERT_TRUE(shipped);
  EXPECT_EQ(shipped->status, 200) << shipped->body;
}

}  // namespace
}  // namespace clearsky::server
