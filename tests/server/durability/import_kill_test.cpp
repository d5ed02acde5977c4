// Durability of an import (docs/architecture.md "Storage and durability") with the real `clearsky
// serve` binary: the 15 public captures' .7z files packed into one tar are uploaded, the server is
// killed with SIGKILL while the import runs (its progress already above zero), and the server
// restarted on the same database shows no partial dataset, the import failed as interrupted, no
// spool file left behind; then the same upload imports completely.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <httplib.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "tests/storage/importers/tar_writer.h"
#include "tests/support/shared_data.h"
#include "tests/support/temp_dir.h"

namespace clearsky::server {
namespace {

using namespace std::chrono_literals;

const char* kRadiance = "kider2014/2013-05-27/RADIANCE";
const char* kToken = "t0ken";

std::string bytes_of(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

// `clearsky serve` as a child process on a free port, its log in a file; one analytic model,
// so that no table precomputation competes with the import.
class ServeProcess {
 public:
  ServeProcess(const std::filesystem::path& dir, const std::filesystem::path& db) {
    const std::string log = (dir / ("serve-" + std::to_string(++starts_) + ".log")).string();
    const std::string binary = std::string(CLEARSKY_BINARY_DIR) + "/clearsky";
    const std::string cache = (dir / "cache").string();
    pid_ = ::fork();
    if (pid_ == 0) {
      const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      ::dup2(fd, 1);
      ::dup2(fd, 2);
      ::execl(binary.c_str(), "clearsky", "serve", "--host", "127.0.0.1", "--port", "0", "--db",
              db.c_str(), "--cache-dir", cache.c_str(), "--token", kToken, "--prebuild-three",
              "false", "--models", "preetham", static_cast<char*>(nullptr));
      ::_exit(127);
    }
    // The port is in the start-up line of the log.
    const std::string marker = "serving on http://127.0.0.1:";
    const auto deadline = std::chrono::steady_clock::now() + 30s;
    while (port_ == 0 && std::chrono::steady_clock::now() < deadline) {
      std::this_thread::sleep_for(10ms);
      const std::string text = bytes_of(log);
      const auto at = text.find(marker);
      if (at != std::string::npos) port_ = std::stoi(text.substr(at + marker.size()));
    }
  }
  ~ServeProcess() {
    if (pid_ > 0) {
      ::kill(pid_, SIGTERM);
      ::waitpid(pid_, nullptr, 0);
    }
  }
  // SIGKILL; returns the signal that ended the process.
  int kill_now() {
    ::kill(pid_, SIGKILL);
    int status = 0;
    ::waitpid(pid_, &status, 0);
    pid_ = -1;
    return WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  }
  int port() const { return port_; }
  httplib::Client client() const {
    httplib::Client c("127.0.0.1", port_);
    c.set_bearer_token_auth(kToken);
    c.set_read_timeout(30, 0);
    c.set_write_timeout(30, 0);
    return c;
  }

 private:
  static inline int starts_ = 0;
  pid_t pid_ = -1;
  int port_ = 0;
};

nlohmann::json get_json(httplib::Client& c, const std::string& path) {
  const auto r = c.Get(path.c_str());
  if (!r) return nullptr;
  return nlohmann::json::parse(r->body);
}

bool upload_files_left(const std::filesystem::path& uploads) {
  std::error_code error;
  if (!std::filesystem::is_directory(uploads, error)) return false;
  return !std::filesystem::is_empty(uploads, error);
}

TEST(ImportDurability, ServerKilledDuringAnImportRestartsWithNothingPartial) {
  CLEARSKY_REQUIRE_SHARED_DATA(kRadiance);
  clearsky::testing::TempDir dir;
  const auto db = dir.path / "sky.db";
  const auto uploads = dir.path / "uploads";
  std::vector<std::pair<std::string, std::string>> files;
  for (const auto& entry :
       std::filesystem::directory_iterator(clearsky::testing::shared_data_dir() / kRadiance))
    if (entry.path().extension() == ".7z")
      files.emplace_back(entry.path().filename().string(), bytes_of(entry.path()));
  ASSERT_EQ(files.size(), 15u);
  const auto tar = dir.path / "captures.tar";
  storage::testing::write_tar(tar, files);
  const std::string archive = bytes_of(tar);

  std::string location;
  nlohmann::json at_kill;
  {
    ServeProcess server(dir.path, db);
    ASSERT_GT(server.port(), 0) << "the server did not start";
    auto c = server.client();
    const auto accepted =
        c.Post("/v1/datasets?name=public&format=kider", archive, "application/octet-stream");
    ASSERT_TRUE(accepted) << httplib::to_string(accepted.error());
    ASSERT_EQ(accepted->status, 202) << accepted->body;
    location = accepted->get_header_value("Location");
    // Generous deadlines: sanitizer builds and parallel test runs are several times slower.
    const auto deadline = std::chrono::steady_clock::now() + 60s;
    while (std::chrono::steady_clock::now() < deadline) {
      at_kill = get_json(c, location);
      const auto& p = at_kill["progress"];
      if (at_kill["status"] == "running" && p.is_object() &&
          (p["bytes_read"].get<std::int64_t>() > 0 || p["entries_read"].get<std::int64_t>() > 0))
        break;
      ASSERT_NE(at_kill["status"], "succeeded") << "the import ended before it could be killed";
      ASSERT_NE(at_kill["status"], "failed") << at_kill.dump();
      std::this_thread::sleep_for(2ms);
    }
    ASSERT_EQ(at_kill["status"], "running") << at_kill.dump();
    EXPECT_EQ(server.kill_now(), SIGKILL);
  }
  EXPECT_LT(at_kill["progress"]["captures_added"].get<int>(), 15) << at_kill.dump();
  EXPECT_TRUE(upload_files_left(uploads)) << "the kill left no spool file to clean";

  ServeProcess server(dir.path, db);
  ASSERT_GT(server.port(), 0) << "the server did not restart";
  auto c = server.client();
  ASSERT_EQ(get_json(c, "/v1/models")["models"].size(), 1u);  // --models preetham
  EXPECT_EQ(get_json(c, "/v1/datasets"), nlohmann::json::array());
  const nlohmann::json interrupted = get_json(c, location);
  EXPECT_EQ(interrupted["status"], "failed") << interrupted.dump();
  EXPECT_EQ(interrupted["error"]["code"], "interrupted");
  EXPECT_FALSE(interrupted["timings"]["finished"].is_null());
  EXPECT_FALSE(upload_files_left(uploads));

  const auto again =
      c.Post("/v1/datasets?name=public&format=kider", archive, "application/octet-stream");
  ASSERT_TRUE(again);
  ASSERT_EQ(again->status, 202) << again->body;
  nlohmann::json done;
  const auto deadline = std::chrono::steady_clock::now() + 180s;
  while (std::chrono::steady_clock::now() < deadline) {
    done = get_json(c, again->get_header_value("Location"));
    if (done["status"] == "succeeded" || done["status"] == "failed") break;
    std::this_thread::sleep_for(10ms);
  }
  ASSERT_EQ(done["status"], "succeeded") << done.dump();
  EXPECT_EQ(done["report"]["added"].size(), 15u);
  EXPECT_EQ(done["progress"]["files_read"], 15 * 81);
  const nlohmann::json datasets = get_json(c, "/v1/datasets");
  ASSERT_EQ(datasets.size(), 1u);
  EXPECT_EQ(datasets[0]["captures"], 15);
  EXPECT_EQ(datasets[0]["samples"], 15 * 81);
  EXPECT_FALSE(upload_files_left(uploads));
  EXPECT_EQ(get_json(c, "/v1/imports").size(), 2u);
}

}  // namespace
}  // namespace clearsky::server
