// A fuzz program's scratch folder under the system's temporary directory, named after the
// process, created empty and removed at exit (libFuzzer runs one input after the other in one
// process, so one folder per process is enough).
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>

namespace clearsky::fuzz {

class ScratchDir {
 public:
  explicit ScratchDir(const std::string& name)
      : path(std::filesystem::temp_directory_path() /
             ("clearsky_fuzz_" + name + "_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  std::filesystem::path path;
};

}  // namespace clearsky::fuzz
