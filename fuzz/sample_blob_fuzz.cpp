// The sample blobs of the database (storage/): the per-sample errors of an evaluation run
// (storage/repositories/sample_errors_blob.h) and the double arrays of a measured sample's
// spectrum (storage/sqlite/blob.h), read into a TabulatedSpectrum as the capture repository
// does. The first byte of an input chooses: even, the rest is a sample errors blob; odd, the
// rest is the wavelength blob then the value blob, split at its middle (rounded down to 8
// bytes).
//
// Invariants (docs/fuzzing.md): a refusal is a std::runtime_error (blob sizes) or
// std::invalid_argument (a spectrum that is not strictly increasing and finite), nothing else
// escapes, no sanitizer report; a decoded errors blob encodes back to the same bytes; a
// spectrum that constructs is its end values at its ends (to a rounding), and interpolates and integrates
// inside its range without error.
#include <cmath>
#include <cstdint>
#include <span>
#include <string>

#include "fuzz/support/fuzz_check.h"
#include "models/spectral/tabulated_spectrum.h"
#include "storage/repositories/sample_errors_blob.h"
#include "storage/sqlite/blob.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace clearsky;
  using namespace clearsky::fuzz;
  if (size == 0) return 0;
  const std::span<const std::byte> rest(reinterpret_cast<const std::byte*>(data) + 1, size - 1);
  if (data[0] % 2 == 0) {
    storage::SampleErrorTable table;
    try {
      table = storage::decode_sample_errors(rest);
    } catch (const std::runtime_error&) {
      return 0;
    }
    check(table.errors.size() == table.samples.size() * table.wavelength_count,
          "decoded errors of another size than samples x wavelengths");
    const std::vector<std::byte> again = storage::encode_sample_errors(table);
    check(again.size() == rest.size() && std::equal(again.begin(), again.end(), rest.begin()),
          "a decoded blob encodes to other bytes");
    return 0;
  }
  const std::size_t half = rest.size() / 16 * 8;
  std::vector<double> wavelengths, values;
  try {
    wavelengths = storage::decode_doubles(rest.subspan(0, half));
    values = storage::decode_doubles(rest.subspan(half));
  } catch (const std::runtime_error&) {
    return 0;
  }
  try {
    const TabulatedSpectrum spectrum(std::move(wavelengths), std::move(values));
    const double lo = spectrum.min_nm(), hi = spectrum.max_nm();
    // At the last wavelength the interpolation v0 + 1 * (v1 - v0) may differ from v1 by a
    // rounding.
    const std::vector<double>& v = spectrum.values();
    const double last = spectrum.at(hi, OutOfRange::error);
    const double scale = std::abs(v.back()) + std::abs(v[v.size() > 1 ? v.size() - 2 : 0]);
    check(spectrum.at(lo, OutOfRange::error) == v.front(), "the spectrum at its start");
    check(!std::isfinite(scale) || std::abs(last - v.back()) <= 1e-15 * scale,
          "the spectrum at its end is not its end value");
    const double mid = lo + 0.5 * (hi - lo);
    if (std::isfinite(mid)) {
      spectrum.at(mid, OutOfRange::error);
      spectrum.integral(lo, mid, OutOfRange::error);
      spectrum.bin_average(lo, hi, OutOfRange::error);
    }
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
