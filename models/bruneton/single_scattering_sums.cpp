// Single scattering's sums along a view ray, AVX2/FMA and through sum_rows().
#include "models/bruneton/single_scattering_sums.h"

#include <cstddef>

#include "models/bruneton/spectral_rows.h"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define CLEARSKY_BRUNETON_X86 1
#endif

namespace clearsky::bruneton {

namespace {

#ifdef CLEARSKY_BRUNETON_X86

// Chunks x 8 wavelengths from `offset`, all samples: the sun's transmittance is
// sum_rows_f32_avx2's chain (from zero, one fused multiply-add per row), the rest the scalar
// code's products and sums, each rounded: the empty asm keeps the compiler from fusing a
// product into the following addition (GCC contracts them by default when FMA is enabled).
template <int Chunks>
__attribute__((target("avx2,fma"))) inline void add_chunks(const SunlitSample* samples, int count,
                                                           int offset, float* sum_r, float* sum_m) {
  __m256 acc_r[Chunks], acc_m[Chunks];
  for (int c = 0; c < Chunks; ++c) {
    acc_r[c] = _mm256_loadu_ps(sum_r + offset + 8 * c);
    acc_m[c] = _mm256_loadu_ps(sum_m + offset + 8 * c);
  }
  for (int i = 0; i < count; ++i) {
    const SunlitSample& s = samples[i];
    __m256 sun[Chunks];
    for (int c = 0; c < Chunks; ++c) sun[c] = _mm256_setzero_ps();
    for (int k = 0; k < s.count; ++k) {
      const __m256 w = _mm256_set1_ps(s.weights[k]);
      const float* row = s.rows[k] + offset;
      for (int c = 0; c < Chunks; ++c)
        sun[c] = _mm256_fmadd_ps(w, _mm256_loadu_ps(row + 8 * c), sun[c]);
    }
    const __m256 wr = _mm256_set1_ps(s.weight_r);
    const __m256 wm = _mm256_set1_ps(s.weight_m);
    for (int c = 0; c < Chunks; ++c) {
      __m256 ti = _mm256_mul_ps(_mm256_loadu_ps(s.view + offset + 8 * c), sun[c]);
      __m256 term_r = _mm256_mul_ps(wr, ti);
      __m256 term_m = _mm256_mul_ps(wm, ti);
      __asm__("" : "+x"(term_r), "+x"(term_m));
      acc_r[c] = _mm256_add_ps(acc_r[c], term_r);
      acc_m[c] = _mm256_add_ps(acc_m[c], term_m);
    }
  }
  for (int c = 0; c < Chunks; ++c) {
    _mm256_storeu_ps(sum_r + offset + 8 * c, acc_r[c]);
    _mm256_storeu_ps(sum_m + offset + 8 * c, acc_m[c]);
  }
}

// Groups of at most 3 chunks: 6 running sums, 3 of the sun and the weights fit the registers.
__attribute__((target("avx2,fma"))) void add_avx2(const SunlitSample* samples, int count,
                                                  int stride, float* sum_r, float* sum_m) {
  int offset = 0;
  for (; offset + 24 <= stride; offset += 24) add_chunks<3>(samples, count, offset, sum_r, sum_m);
  if (stride - offset == 16) add_chunks<2>(samples, count, offset, sum_r, sum_m);
  if (stride - offset == 8) add_chunks<1>(samples, count, offset, sum_r, sum_m);
}

#endif

}  // namespace

void add_sunlit_samples_reference(const SunlitSample* samples, int count, int stride, float* sum_r,
                                  float* sum_m) {
  ScratchRow sun(stride);
  for (int i = 0; i < count; ++i) {
    const SunlitSample& s = samples[i];
    sum_rows(s.rows, s.weights, s.count, stride, sun.data());
    for (int w = 0; w < stride; ++w) {
      const float ti = s.view[w] * sun.data()[w];
      sum_r[w] += s.weight_r * ti;
      sum_m[w] += s.weight_m * ti;
    }
  }
}

void add_sunlit_samples(const SunlitSample* samples, int count, int stride, float* sum_r,
                        float* sum_m) {
#ifdef CLEARSKY_BRUNETON_X86
  // The AVX2 kernel reproduces sum_rows_f32_avx2; the portable sum_rows rounds differently.
  if (using_avx2_kernels()) {
    add_avx2(samples, count, stride, sum_r, sum_m);
    return;
  }
#endif
  add_sunlit_samples_reference(samples, count, stride, sum_r, sum_m);
}

}  // namespace clearsky::bruneton
