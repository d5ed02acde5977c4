// Encoding of per-sample evaluation errors (sample_errors_blob.h).
#include "storage/repositories/sample_errors_blob.h"

#include <bit>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

namespace clearsky::storage {
namespace {

static_assert(std::endian::native == std::endian::little,
              "blob encoding assumes a little-endian host");
static_assert(sizeof(float) == 4 && std::numeric_limits<float>::is_iec559);
static_assert(sizeof(double) == 8 && std::numeric_limits<double>::is_iec559);

constexpr std::size_t kHeaderBytes = 8;
constexpr std::size_t kRecordFixedBytes = 28;

template <typename T>
void put(std::vector<std::byte>& out, std::size_t& at, T value) {
  std::memcpy(out.data() + at, &value, sizeof(T));
  at += sizeof(T);
}

template <typename T>
T take(std::span<const std::byte> in, std::size_t& at) {
  T value;
  std::memcpy(&value, in.data() + at, sizeof(T));
  at += sizeof(T);
  return value;
}

}  // namespace

std::vector<std::byte> encode_sample_errors(const SampleErrorTable& table) {
  const std::size_t n = table.samples.size();
  const std::size_t w = table.wavelength_count;
  if (table.errors.size() != n * w)
    throw std::invalid_argument("sample errors: " + std::to_string(table.errors.size()) +
                                " errors for " + std::to_string(n) + " samples x " +
                                std::to_string(w) + " wavelengths");
  std::vector<std::byte> out(kHeaderBytes + n * (kRecordFixedBytes + 4 * w));
  std::size_t at = 0;
  put(out, at, static_cast<std::uint32_t>(n));
  put(out, at, static_cast<std::uint32_t>(w));
  for (std::size_t s = 0; s < n; ++s) {
    const StoredSampleError& e = table.samples[s];
    put(out, at, e.index);
    put(out, at, e.view_zenith_deg);
    put(out, at, e.view_azimuth_deg);
    put(out, at, e.rmse);
    put(out, at, e.bias);
    if (w > 0) std::memcpy(out.data() + at, table.errors.data() + s * w, 4 * w);
    at += 4 * w;
  }
  return out;
}

SampleErrorTable decode_sample_errors(std::span<const std::byte> bytes) {
  if (bytes.size() < kHeaderBytes)
    throw std::runtime_error("corrupt sample errors blob: " + std::to_string(bytes.size()) +
                             " bytes, no header");
  std::size_t at = 0;
  const std::size_t n = take<std::uint32_t>(bytes, at);
  const std::size_t w = take<std::uint32_t>(bytes, at);
  // Bounds first, so that the size product below cannot overflow.
  if ((n > 0 && (n > bytes.size() / kRecordFixedBytes || w > bytes.size() / 4)) ||
      bytes.size() != kHeaderBytes + n * (kRecordFixedBytes + 4 * w))
    throw std::runtime_error("corrupt sample errors blob: " + std::to_string(bytes.size()) +
                             " bytes for " + std::to_string(n) + " samples x " + std::to_string(w) +
                             " wavelengths");
  SampleErrorTable table;
  table.wavelength_count = static_cast<std::uint32_t>(w);
  table.samples.resize(n);
  table.errors.resize(n * w);
  for (std::size_t s = 0; s < n; ++s) {
    StoredSampleError& e = table.samples[s];
    e.index = take<std::int32_t>(bytes, at);
    e.view_zenith_deg = take<float>(bytes, at);
    e.view_azimuth_deg = take<float>(bytes, at);
    e.rmse = take<double>(bytes, at);
    e.bias = take<double>(bytes, at);
    if (w > 0) std::memcpy(table.errors.data() + s * w, bytes.data() + at, 4 * w);
    at += 4 * w;
  }
  return table;
}

}  // namespace clearsky::storage
