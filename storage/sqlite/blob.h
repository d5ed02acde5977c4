// Arrays of doubles as SQLite blobs: IEEE-754 binary64, little-endian, no header (the column
// says what the array is). Decoding checks the size.
#pragma once

#include <bit>
#include <cstddef>
#include <cstring>
#include <span>
#include <stdexcept>
#include <vector>

namespace clearsky::storage {

static_assert(std::endian::native == std::endian::little, "blob encoding assumes a little-endian host");

inline std::vector<std::byte> encode_doubles(std::span<const double> values) {
  std::vector<std::byte> bytes(values.size() * sizeof(double));
  if (!values.empty()) std::memcpy(bytes.data(), values.data(), bytes.size());
  return bytes;
}

inline std::vector<double> decode_doubles(std::span<const std::byte> bytes) {
  if (bytes.size() % sizeof(double) != 0) throw std::runtime_error("corrupt blob: size is not a multiple of 8 bytes");
  std::vector<double> values(bytes.size() / sizeof(double));
  if (!values.empty()) std::memcpy(values.data(), bytes.data(), bytes.size());
  return values;
}

}  // namespace clearsky::storage
