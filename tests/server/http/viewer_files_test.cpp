// The browser viewer's files at / (server/http/viewer_files.h, docs/viewer.md): the listed files
// of the viewer folder with their cache and security headers; every other path keeps the API's
// answer (routes, the JSON 404), and nothing outside the folder is served.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/server/http/server_fixture.h"
#include "tests/support/temp_dir.h"

namespace clearsky::server {
namespace {

class ViewerFilesTest : public testing::ServerFixture {
 protected:
  void SetUp() override {
    std::filesystem::create_directories(dir.path / "viewer" / "assets");
    write("viewer/index.html", "<!doctype html><title>viewer</title>");
    write("viewer/assets/main-ABC123.js", "console.log('sky');");
    write("secret.txt", "outside the viewer folder");
    ServerConfig config;
    config.viewer_dir = (dir.path / "viewer").string();
    start(config);
  }
  void write(const std::string& name, const std::string& text) {
    std::ofstream(dir.path / name) << text;
  }
  clearsky::testing::TempDir dir;
};

TEST_F(ViewerFilesTest, IndexIsRevalidatedAndAssetsAreImmutable) {
  auto c = client();
  const auto index = c.Get("/");
  ASSERT_TRUE(index);
  EXPECT_EQ(index->status, 200);
  EXPECT_EQ(index->body, "<!doctype html><title>viewer</title>");
  EXPECT_EQ(index->get_header_value("Content-Type"), "text/html");
  EXPECT_EQ(index->get_header_value("Cache-Control"), "no-cache");
  EXPECT_NE(index->get_header_value("Content-Security-Policy").find("default-src 'self'"),
            std::string::npos);
  EXPECT_EQ(index->get_header_value("X-Content-Type-Options"), "nosniff");
  EXPECT_EQ(c.Get("/index.html")->status, 200);
  const auto head = c.Head("/");
  ASSERT_TRUE(head);
  EXPECT_EQ(head->status, 200);
  EXPECT_EQ(head->get_header_value("Cache-Control"), "no-cache");
  const auto asset = c.Get("/assets/main-ABC123.js");
  ASSERT_TRUE(asset);
  EXPECT_EQ(asset->status, 200);
  EXPECT_EQ(asset->body, "console.log('sky');");
  EXPECT_EQ(asset->get_header_value("Cache-Control"), "public, max-age=31536000, immutable");
}

TEST_F(ViewerFilesTest, OtherPathsKeepTheApiAnswers) {
  auto c = client();
  EXPECT_EQ(c.Get("/v1/models")->status, 200);
  for (const char* path : {"/missing.js", "/assets/", "/../secret.txt", "/assets/../../secret.txt",
                           "/%2e%2e/secret.txt"}) {
    const auto r = c.Get(path);
    ASSERT_TRUE(r) << path;
    EXPECT_EQ(r->status, 404) << path;
    EXPECT_EQ(r->body.find("outside the viewer folder"), std::string::npos) << path;
    const auto body = nlohmann::json::parse(r->body, nullptr, false);
    EXPECT_FALSE(body.is_discarded()) << path << ": " << r->body;
  }
  // Only GET and HEAD read files.
  EXPECT_EQ(c.Post("/index.html", "", "text/plain")->status, 404);
}

TEST(ViewerFiles, NoFolderOrNoIndexMeansNoViewer) {
  clearsky::testing::TempDir dir;
  EXPECT_FALSE(ViewerFiles("").enabled());
  EXPECT_FALSE(ViewerFiles((dir.path / "absent").string()).enabled());
  EXPECT_FALSE(ViewerFiles(dir.path.string()).enabled());  // no index.html
  EXPECT_FALSE(ViewerFiles(dir.path.string()).serves("/"));
}

}  // namespace
}  // namespace clearsky::server
