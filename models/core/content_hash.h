// A 64-bit FNV-1a hash for cache keys and content checksums (not cryptographic: it detects
// corruption and keys tables by content, it does not resist tampering).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace clearsky {

inline std::uint64_t fnv1a_64(std::string_view bytes,
                              std::uint64_t seed = 14695981039346656037ull) {
  std::uint64_t h = seed;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

// 16 lowercase hex digits.
std::string hex64(std::uint64_t value);

}  // namespace clearsky
