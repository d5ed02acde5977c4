// `clearsky serve` (the built executable) as a child process on a free loopback port, for tests
// that need the real server with its command-line defaults: one analytic model (Preetham), no
// 3-wavelength tables, a temporary database and cache (the database elsewhere when db is given,
// e.g. on a small file system); extra options are appended and `models` replaces Preetham. The
// port is read from the start-up line of its log; the process gets SIGTERM when the object goes
// (kill_now() for SIGKILL).
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace clearsky::server::testing {

class ServeProcess {
 public:
  ServeProcess(const std::filesystem::path& dir, const std::vector<std::string>& extra,
               const std::string& models = "preetham", const std::filesystem::path& db = {}) {
    log_ = dir / "serve.log";
    // A log left by an earlier server in the same folder must not give its port: the child
    // truncates the file only once it runs, after this process starts reading it.
    std::filesystem::remove(log_);
    const std::string binary = std::string(CLEARSKY_BINARY_DIR) + "/clearsky";
    std::vector<std::string> args = {"clearsky",
                                     "serve",
                                     "--host",
                                     "127.0.0.1",
                                     "--port",
                                     "0",
                                     "--db",
                                     (db.empty() ? dir / "sky.db" : db).string(),
                                     "--cache-dir",
                                     (dir / "cache").string(),
                                     "--prebuild-three",
                                     "false",
                                     "--models",
                                     models};
    args.insert(args.end(), extra.begin(), extra.end());
    pid_ = ::fork();
    if (pid_ == 0) {
      const int fd = ::open(log_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      ::dup2(fd, 1);
      ::dup2(fd, 2);
      std::vector<char*> argv;
      for (std::string& a : args) argv.push_back(a.data());
      argv.push_back(nullptr);
      ::execv(binary.c_str(), argv.data());
      ::_exit(127);
    }
    const std::string marker = "serving on http://127.0.0.1:";
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (port_ == 0 && std::chrono::steady_clock::now() < deadline) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
      const std::string text = log();
      const auto at = text.find(marker);
      if (at != std::string::npos) port_ = std::stoi(text.substr(at + marker.size()));
    }
  }
  ~ServeProcess() { stop(); }
  ServeProcess(const ServeProcess&) = delete;
  ServeProcess& operator=(const ServeProcess&) = delete;

  // SIGTERM, then waits for the process to end; returns how long that took.
  std::chrono::duration<double> stop() {
    const auto start = std::chrono::steady_clock::now();
    if (pid_ > 0) {
      ::kill(pid_, SIGTERM);
      ::waitpid(pid_, nullptr, 0);
      pid_ = -1;
    }
    return std::chrono::steady_clock::now() - start;
  }

  // SIGKILL, then waits for the process to end; returns the signal that ended it (0 when none).
  int kill_now() {
    if (pid_ <= 0) return 0;
    ::kill(pid_, SIGKILL);
    int status = 0;
    ::waitpid(pid_, &status, 0);
    pid_ = -1;
    return WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  }

  // 0 when the server did not start within 60 s.
  int port() const { return port_; }
  pid_t pid() const { return pid_; }
  std::string log() const {
    std::ifstream in(log_);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
  }

 private:
  std::filesystem::path log_;
  pid_t pid_ = -1;
  int port_ = 0;
};

}  // namespace clearsky::server::testing
