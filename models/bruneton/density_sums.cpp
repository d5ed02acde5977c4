// J's two spectral sums in one pass, AVX2/FMA and through sum_rows().
#include "models/bruneton/density_sums.h"

#include "models/bruneton/spectral_rows.h"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define CLEARSKY_BRUNETON_X86 1
#endif

namespace clearsky::bruneton {

namespace {

#ifdef CLEARSKY_BRUNETON_X86

// Chunks x 8 wavelengths from `offset`: each lane of each sum is sum_rows_f32_avx2's chain
// (from zero, one fused multiply-add per term in order).
template <int Chunks>
__attribute__((target("avx2,fma"))) inline void sum_chunks(const float* const* rows,
                                                           const float* w_r, const float* w_m,
                                                           int count, int offset, float* sum_r,
                                                           float* sum_m) {
  __m256 a_r[Chunks], a_m[Chunks];
  for (int c = 0; c < Chunks; ++c) {
    a_r[c] = _mm256_setzero_ps();
    a_m[c] = _mm256_setzero_ps();
  }
  for (int k = 0; k < count; ++k) {
    const __m256 wr = _mm256_set1_ps(w_r[k]);
    const __m256 wm = _mm256_set1_ps(w_m[k]);
    const float* row = rows[k] + offset;
    for (int c = 0; c < Chunks; ++c) {
      const __m256 x = _mm256_loadu_ps(row + 8 * c);
      a_r[c] = _mm256_fmadd_ps(wr, x, a_r[c]);
      a_m[c] = _mm256_fmadd_ps(wm, x, a_m[c]);
    }
  }
  for (int c = 0; c < Chunks; ++c) {
    _mm256_storeu_ps(sum_r + offset + 8 * c, a_r[c]);
    _mm256_storeu_ps(sum_m + offset + 8 * c, a_m[c]);
  }
}

// Groups of at most 5 chunks: 10 accumulators and the two weights fit the 16 registers.
__attribute__((target("avx2,fma"))) void sum_avx2(const float* const* rows, const float* w_r,
                                                  const float* w_m, int count, int stride,
                                                  float* sum_r, float* sum_m) {
  int offset = 0;
  for (; offset + 40 <= stride; offset += 40)
    sum_chunks<5>(rows, w_r, w_m, count, offset, sum_r, sum_m);
  switch ((stride - offset) / 8) {
    case 4:
      sum_chunks<4>(rows, w_r, w_m, count, offset, sum_r, sum_m);
      break;
    case 3:
      sum_chunks<3>(rows, w_r, w_m, count, offset, sum_r, sum_m);
      break;
    case 2:
      sum_chunks<2>(rows, w_r, w_m, count, offset, sum_r, sum_m);
      break;
    case 1:
      sum_chunks<1>(rows, w_r, w_m, count, offset, sum_r, sum_m);
      break;
    default:
      break;
  }
}

#endif

}  // namespace

void DensityTerms::sum_reference(int stride, float* sum_r, float* sum_m) const {
  sum_rows(rows_.data(), w_r_.data(), count_, stride, sum_r);
  sum_rows(rows_.data(), w_m_.data(), count_, stride, sum_m);
}

void DensityTerms::sum(int stride, float* sum_r, float* sum_m) const {
#ifdef CLEARSKY_BRUNETON_X86
  // The AVX2 kernel reproduces sum_rows_f32_avx2; the portable sum_rows rounds differently.
  if (using_avx2_kernels()) {
    sum_avx2(rows_.data(), w_r_.data(), w_m_.data(), count_, stride, sum_r, sum_m);
    return;
  }
#endif
  sum_reference(stride, sum_r, sum_m);
}

}  // namespace clearsky::bruneton
