// The per-sample errors of one capture in one evaluation run, as stored in
// evaluation_sample_errors.data: one compact little-endian blob rather than one SQL row per
// value, so that a run of a model over 15 captures stays a few hundred kilobytes at most.
// Layout (little-endian, no padding):
//   uint32 N (samples), uint32 W (wavelengths: the run's evaluation_runs.wavelengths_nm),
//   then N records of: int32 scan index, float32 view zenith (deg), float32 view azimuth (deg,
//   clockwise from North), float64 RMSE over the W wavelengths, float64 bias (mean signed
//   error), W x float32 signed error (model - measured); errors in mW/(m2.sr.nm).
// Size: 8 + N (28 + 4 W) bytes; 12,320 bytes for the 81 Kider directions and 31 wavelengths.
// float32 keeps 7 significant digits, far below the measurement's own uncertainty; the RMSE
// and bias stay float64 so that the stored samples recompute the capture's RMSE to 1e-15.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace clearsky::storage {

struct StoredSampleError {
  std::int32_t index = 0;
  float view_zenith_deg = 0;
  float view_azimuth_deg = 0;
  double rmse = 0;  // mW/(m2.sr.nm)
  double bias = 0;  // mW/(m2.sr.nm), model - measured
  bool operator==(const StoredSampleError&) const = default;
};

struct SampleErrorTable {
  std::uint32_t wavelength_count = 0;
  std::vector<StoredSampleError> samples;
  std::vector<float> errors;  // samples.size() rows of wavelength_count, model - measured
  std::span<const float> errors_of(std::size_t sample) const {
    return std::span<const float>(errors).subspan(sample * wavelength_count, wavelength_count);
  }
  bool operator==(const SampleErrorTable&) const = default;
};

// Throws std::invalid_argument when errors.size() != samples.size() * wavelength_count.
std::vector<std::byte> encode_sample_errors(const SampleErrorTable& table);
// Throws std::runtime_error for a blob whose size does not match its header.
SampleErrorTable decode_sample_errors(std::span<const std::byte> bytes);

}  // namespace clearsky::storage
