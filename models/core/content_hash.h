// A 64-bit FNV-1a hash of short strings whose value is stored or shown and so must never
// change: table-cache keys (the Bruneton key "bruneton-<hash of the configuration>" and the
// cache file names) and the content hashes kept in the database (Kider captures, evaluation
// sample errors). Not cryptographic. Bulk payloads are checksummed with XXH3 instead
// (server/cache/table_checksum.h): FNV-1a reads one byte per multiply.
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
