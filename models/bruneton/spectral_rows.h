// Weighted sums of spectral table rows: the inner loop of every Bruneton table lookup.
//
// A lookup in a precomputed table is a weighted sum of a few texels (4 for a 2D bilinear
// lookup, up to 16 for the 4D one), and each texel is a row of `stride` values, one per
// wavelength (padded to a multiple of 8). Vectorising over wavelengths is what makes both
// the precomputation and the queries fast: one pass computes all wavelengths of a texel.
//
// The 4D tables are stored as IEEE 754 binary16 ("half") values with a power-of-two scale per
// row (see bruneton_tables.h): half the memory of float, 2^-11 relative precision, far below
// the model's own error. Rows of half values are widened on the fly.
//
// Two implementations with identical semantics: AVX2+FMA+F16C when the CPU has them (chosen
// once at run time), portable C++ otherwise. Results agree to float rounding (FMA).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace clearsky::bruneton {

// Values per texel are padded to a multiple of this.
inline constexpr int kRowAlignment = 8;
inline constexpr int padded_stride(int wavelengths) {
  return (wavelengths + kRowAlignment - 1) / kRowAlignment * kRowAlignment;
}

// out[i] = sum_k weights[k] * rows[k][i] for i in [0, stride); stride a multiple of 8.
void sum_rows(const float* const* rows, const float* weights, int count, int stride, float* out);
void sum_rows(const std::uint16_t* const* rows, const float* weights, int count, int stride,
              float* out);

// Round-to-nearest-even conversions (values beyond the half range saturate to +-65504; the
// tables choose their scales so that this never happens).
std::uint16_t float_to_half(float value);
float half_to_float(std::uint16_t half);
// out[i] = half(in[i] * scale) for i in [0, n).
void floats_to_halves(const float* in, float scale, std::uint16_t* out, std::size_t n);

// A spectrum-sized float buffer, on the stack for the usual sizes (queries must not allocate).
class ScratchRow {
 public:
  explicit ScratchRow(int n) {
    if (n > static_cast<int>(small_.size())) {
      big_.resize(static_cast<std::size_t>(n));
      data_ = big_.data();
    } else {
      data_ = small_.data();
    }
  }
  ScratchRow(const ScratchRow&) = delete;
  ScratchRow& operator=(const ScratchRow&) = delete;
  float* data() { return data_; }

 private:
  std::array<float, 256> small_;
  std::vector<float> big_;
  float* data_;
};

// Whether the AVX2/F16C implementation is in use (for the benchmarks' report).
bool using_avx2_kernels();

// The portable implementations, exposed so that tests compare them with the fast ones.
namespace portable {
void sum_rows(const std::uint16_t* const* rows, const float* weights, int count, int stride,
              float* out);
void floats_to_halves(const float* in, float scale, std::uint16_t* out, std::size_t n);
}  // namespace portable

}  // namespace clearsky::bruneton
