// The memory estimate of a batch answer (batch_answer_bytes.h).
#include "api/http/batch_answer_bytes.h"

namespace clearsky::api {

namespace {

constexpr std::size_t kSpectrumBytesPerWavelength = sizeof(double);
constexpr std::size_t kStatusBytesPerView = 8;
constexpr std::size_t kValueBytes = 32;  // a JSON value (16 bytes) in an array grown by doubling
constexpr std::size_t kTextBytes = 64;   // its text in the body (a CSV row per value: 4 numbers)
constexpr std::size_t kSampleObjectBytes = 640;
constexpr std::size_t kFixedBytes = std::size_t{16} << 10;

}  // namespace

std::size_t batch_answer_bytes(std::size_t views, std::size_t grid_wavelengths,
                               std::size_t numbers_per_view) {
  const std::size_t per_view = grid_wavelengths * kSpectrumBytesPerWavelength +
                               kStatusBytesPerView + numbers_per_view * (kValueBytes + kTextBytes) +
                               kSampleObjectBytes;
  return kFixedBytes + views * per_view;
}

}  // namespace clearsky::api
