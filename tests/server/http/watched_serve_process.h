// The built `clearsky serve` executable as a child process on a free loopback port, for tests
// that must see what the real process does with a request (a crash, a connection left open):
// its own temporary database and cache, its log in a file, the port read from the start-up line.
// What a test may look at besides HTTP: whether the process is still alive, its open file
// descriptors, and the TCP connections of its port still in CLOSE-WAIT (/proc/net/tcp).
#pragma once

#include <fcntl.h>
#include <httplib.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "tests/support/temp_dir.h"

namespace clearsky::server::testing {

class WatchedServeProcess {
 public:
  // Whether the process gets its own database (--db), or none (a query replica, --role query).
  enum class Database { own, none };

  // arguments follow `clearsky serve --host 127.0.0.1 --port 0 --db ... --cache-dir ...`;
  // max_open_files > 0 sets the child's RLIMIT_NOFILE (as `ulimit -n`).
  explicit WatchedServeProcess(const std::vector<std::string>& arguments, rlim_t max_open_files = 0,
                               Database database = Database::own) {
    log_ = dir_.path / "serve.log";
    std::vector<std::string> args = {"clearsky", "serve", "--host", "127.0.0.1", "--port", "0"};
    if (database == Database::own) {
      args.push_back("--db");
      args.push_back((dir_.path / "db.sqlite").string());
    }
    args.push_back("--cache-dir");
    args.push_back((dir_.path / "cache").string());
    args.insert(args.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    const std::string binary = std::string(CLEARSKY_BINARY_DIR) + "/clearsky";
    pid_ = ::fork();
    if (pid_ == 0) {
      // In its own folder: a relative path the server opens (a default --db) lands there.
      if (::chdir(dir_.path.c_str()) != 0) ::_exit(126);
      const int fd = ::open(log_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      ::dup2(fd, 1);
      ::dup2(fd, 2);
      if (max_open_files > 0) {
        const rlimit limit{max_open_files, max_open_files};
        ::setrlimit(RLIMIT_NOFILE, &limit);
      }
      ::execv(binary.c_str(), argv.data());
      ::_exit(127);
    }
    const std::string marker = "serving on http://127.0.0.1:";
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (port_ == 0 && alive() && std::chrono::steady_clock::now() < deadline) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
      const std::string text = log();
      const auto at = text.find(marker);
      if (at != std::string::npos) port_ = std::stoi(text.substr(at + marker.size()));
    }
  }
  ~WatchedServeProcess() {
    if (pid_ > 0) {
      ::kill(pid_, SIGTERM);
      ::waitpid(pid_, nullptr, 0);
    }
  }
  WatchedServeProcess(const WatchedServeProcess&) = delete;
  WatchedServeProcess& operator=(const WatchedServeProcess&) = delete;

  int port() const { return port_; }
  pid_t pid() const { return pid_; }
  std::string log() const {
    std::ifstream in(log_);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
  }
  // False once the process has ended (a crash: its signal is in end_signal()).
  bool alive() {
    if (pid_ <= 0) return false;
    int status = 0;
    if (::waitpid(pid_, &status, WNOHANG) == pid_) {
      end_signal_ = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
      exit_status_ = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      pid_ = -1;
      return false;
    }
    return true;
  }
  int end_signal() const { return end_signal_; }
  // The exit status once the process has ended normally (-1: killed by a signal, or alive).
  int exit_status() const { return exit_status_; }
  // Sends a signal to the process (while it runs).
  void signal(int number) const {
    if (pid_ > 0) ::kill(pid_, number);
  }
  // The folder of its database, cache and log.
  const std::filesystem::path& directory() const { return dir_.path; }

  httplib::Client client(int read_timeout_s = 30) const {
    httplib::Client c("127.0.0.1", port_);
    c.set_read_timeout(read_timeout_s, 0);
    c.set_write_timeout(30, 0);
    c.set_connection_timeout(5, 0);
    return c;
  }
  // GET /healthz answers 200 within a second.
  bool healthy_within_1s() const {
    auto c = client();
    c.set_read_timeout(1, 0);
    c.set_connection_timeout(1, 0);
    const auto start = std::chrono::steady_clock::now();
    const auto r = c.Get("/healthz");
    return r && r->status == 200 &&
           std::chrono::steady_clock::now() - start < std::chrono::seconds(1);
  }
  // Open file descriptors of the process.
  std::size_t open_files() const {
    std::size_t n = 0;
    std::error_code error;
    for (auto it =
             std::filesystem::directory_iterator("/proc/" + std::to_string(pid_) + "/fd", error);
         !error && it != std::filesystem::directory_iterator(); it.increment(error))
      ++n;
    return n;
  }
  // Connections to the server's port that the client closed and the server did not
  // (state CLOSE_WAIT, 08, in /proc/net/tcp).
  std::size_t close_wait_connections() const {
    std::size_t n = 0;
    for (const char* table : {"/proc/net/tcp", "/proc/net/tcp6"}) {
      std::ifstream in(table);
      std::string line;
      std::getline(in, line);  // the column names
      while (std::getline(in, line)) {
        std::istringstream fields(line);
        std::string slot, local, remote, state;
        fields >> slot >> local >> remote >> state;
        const auto colon = local.rfind(':');
        if (colon == std::string::npos || state != "08") continue;
        if (std::stoi(local.substr(colon + 1), nullptr, 16) == port_) ++n;
      }
    }
    return n;
  }

 private:
  clearsky::testing::TempDir dir_;
  std::filesystem::path log_;
  pid_t pid_ = -1;
  int port_ = 0;
  int end_signal_ = 0;
  int exit_status_ = -1;
};

}  // namespace clearsky::server::testing
