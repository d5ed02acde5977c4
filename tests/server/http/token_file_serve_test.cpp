// `clearsky serve --token-file` (server/auth/token_file.h), the real process: writes take the
// file's token (its final newline dropped) and refuse another; a file that cannot be a token
// stops the server at start rather than leaving writes silently disabled.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <thread>

#include "tests/server/http/watched_serve_process.h"
#include "tests/support/temp_dir.h"

namespace clearsky::server {
namespace {

using testing::WatchedServeProcess;

TEST(TokenFileServe, WritesTakeTheTokenOfTheFile) {
  clearsky::testing::TempDir temp;
  const auto token = temp.path / "token";
  std::ofstream(token) << "f1le-T0ken\n";
  WatchedServeProcess server(
      {"--models", "preetham", "--prebuild-three", "false", "--token-file", token.string()});
  ASSERT_GT(server.port(), 0) << server.log();
  auto c = server.client();
  const auto wrong =
      c.Post("/v1/jobs", {{"Authorization", "Bearer other"}}, "{}", "application/json");
  ASSERT_TRUE(wrong);
  EXPECT_EQ(wrong->status, 401);
  // The right token reaches the handler, which refuses the empty job (400), not the token.
  const auto right =
      c.Post("/v1/jobs", {{"Authorization", "Bearer f1le-T0ken"}}, "{}", "application/json");
  ASSERT_TRUE(right);
  EXPECT_EQ(right->status, 400) << right->body;
  EXPECT_EQ(server.log().find("f1le-T0ken"), std::string::npos) << "the token was logged";
}

TEST(TokenFileServe, AnEmptyTokenFileStopsTheServerAtStart) {
  clearsky::testing::TempDir temp;
  const auto token = temp.path / "token";
  std::ofstream(token) << "\n";
  WatchedServeProcess server({"--models", "preetham", "--token-file", token.string()});
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (server.alive() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ASSERT_FALSE(server.alive());
  EXPECT_EQ(server.exit_status(), 1);
  EXPECT_NE(server.log().find("--token-file"), std::string::npos) << server.log();
}

}  // namespace
}  // namespace clearsky::server
