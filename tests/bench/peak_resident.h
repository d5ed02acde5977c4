// The peak resident memory of this process (VmHWM of /proc/self/status), resettable so that a
// benchmark reports the peak of its own work (Linux: writing 5 to /proc/self/clear_refs resets
// the peak to the current resident set). Elsewhere both are no-ops and the peak reads 0.
#pragma once

#include <cstddef>
#include <fstream>
#include <string>

namespace clearsky::bench {

inline void reset_peak_resident() {
  std::ofstream clear("/proc/self/clear_refs");
  if (clear) clear << "5";
}

// Bytes; 0 where /proc/self/status is missing.
inline std::size_t peak_resident_bytes() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmHWM:", 0) == 0) return std::stoull(line.substr(6)) * 1024;
  }
  return 0;
}

}  // namespace clearsky::bench
