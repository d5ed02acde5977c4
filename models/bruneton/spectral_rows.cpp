// Weighted sums of spectral rows, portable and AVX2/F16C, and binary16 conversions.
#include "models/bruneton/spectral_rows.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <vector>

#if defined(__x86_64__) || defined(__i386__)
#include <cpuid.h>
#include <immintrin.h>
#define CLEARSKY_BRUNETON_X86 1
#endif

namespace clearsky::bruneton {

std::uint16_t float_to_half(float value) {
  const std::uint32_t x = std::bit_cast<std::uint32_t>(value);
  const std::uint32_t sign = (x >> 16) & 0x8000u;
  const std::uint32_t magnitude = x & 0x7fffffffu;
  if (magnitude > 0x7f800000u) return static_cast<std::uint16_t>(sign | 0x7e00u);   // NaN
  if (magnitude >= 0x477ff000u) return static_cast<std::uint16_t>(sign | 0x7bffu);  // saturate
  if (magnitude < 0x38800000u) {
    // Below the smallest normal half (2^-14): a subnormal m * 2^-24, or zero.
    if (magnitude < 0x33000000u) return static_cast<std::uint16_t>(sign);
    const std::uint32_t exponent = magnitude >> 23;
    const std::uint32_t mantissa = (magnitude & 0x7fffffu) | 0x800000u;
    const std::uint32_t shift = 126u - exponent;
    std::uint32_t m = mantissa >> shift;
    const std::uint32_t remainder = mantissa & ((1u << shift) - 1u);
    const std::uint32_t halfway = 1u << (shift - 1u);
    if (remainder > halfway || (remainder == halfway && (m & 1u))) ++m;
    return static_cast<std::uint16_t>(sign | m);
  }
  // Normal: rebias the exponent from 127 to 15 and round the 13 dropped mantissa bits to
  // nearest even (a carry into the exponent is the correct result).
  std::uint32_t h = (magnitude >> 13) - (112u << 10);
  const std::uint32_t remainder = magnitude & 0x1fffu;
  if (remainder > 0x1000u || (remainder == 0x1000u && (h & 1u))) ++h;
  return static_cast<std::uint16_t>(sign | h);
}

float half_to_float(std::uint16_t half) {
  const std::uint32_t sign = static_cast<std::uint32_t>(half & 0x8000u) << 16;
  const std::uint32_t exponent = (half >> 10) & 0x1fu;
  const std::uint32_t mantissa = half & 0x3ffu;
  if (exponent == 0) {
    const float v = static_cast<float>(mantissa) * 0x1p-24f;
    return sign != 0 ? -v : v;
  }
  if (exponent == 31) return std::bit_cast<float>(sign | 0x7f800000u | (mantissa << 13));
  return std::bit_cast<float>(sign | ((exponent + 112u) << 23) | (mantissa << 13));
}

namespace {

// All 65536 half values widened once: the portable path's conversion is a table read.
const std::vector<float>& half_table() {
  static const std::vector<float> table = [] {
    std::vector<float> t(65536);
    for (std::uint32_t i = 0; i < 65536; ++i) t[i] = half_to_float(static_cast<std::uint16_t>(i));
    return t;
  }();
  return table;
}

void sum_rows_f32_portable(const float* const* rows, const float* weights, int count, int stride,
                           float* out) {
  std::fill(out, out + stride, 0.0f);
  for (int k = 0; k < count; ++k) {
    const float w = weights[k];
    const float* row = rows[k];
    for (int i = 0; i < stride; ++i) out[i] += w * row[i];
  }
}

#ifdef CLEARSKY_BRUNETON_X86
__attribute__((target("avx2,fma,f16c"))) void sum_rows_f32_avx2(const float* const* rows,
                                                                const float* weights, int count,
                                                                int stride, float* out) {
  int c = 0;
  for (; c + 32 <= stride; c += 32) {
    __m256 a0 = _mm256_setzero_ps(), a1 = _mm256_setzero_ps(), a2 = _mm256_setzero_ps(),
           a3 = _mm256_setzero_ps();
    for (int k = 0; k < count; ++k) {
      const __m256 w = _mm256_set1_ps(weights[k]);
      const float* row = rows[k] + c;
      a0 = _mm256_fmadd_ps(w, _mm256_loadu_ps(row), a0);
      a1 = _mm256_fmadd_ps(w, _mm256_loadu_ps(row + 8), a1);
      a2 = _mm256_fmadd_ps(w, _mm256_loadu_ps(row + 16), a2);
      a3 = _mm256_fmadd_ps(w, _mm256_loadu_ps(row + 24), a3);
    }
    _mm256_storeu_ps(out + c, a0);
    _mm256_storeu_ps(out + c + 8, a1);
    _mm256_storeu_ps(out + c + 16, a2);
    _mm256_storeu_ps(out + c + 24, a3);
  }
  for (; c < stride; c += 8) {
    __m256 a = _mm256_setzero_ps();
    for (int k = 0; k < count; ++k)
      a = _mm256_fmadd_ps(_mm256_set1_ps(weights[k]), _mm256_loadu_ps(rows[k] + c), a);
    _mm256_storeu_ps(out + c, a);
  }
}

__attribute__((target("avx2,fma,f16c"))) inline __m256 load_halves(const std::uint16_t* p) {
  return _mm256_cvtph_ps(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p)));
}

// Columns [offset, offset + 8 V) of the weighted sum, V vectors of 8 wavelengths in V
// accumulators over one pass through the rows: each lane adds its rows in order k = 0, 1, ...
// by one fused multiply-add each, so the result does not depend on V, and a spectrum of 40
// wavelengths (5 vectors) is one chain of `count` multiply-adds deep instead of two (a block of
// 4 vectors, then one of 1), which is what bounds a lookup's time (each multiply-add waits for
// the previous one of its lane).
template <int V>
__attribute__((target("avx2,fma,f16c"))) inline void sum_rows_f16_block(
    const std::uint16_t* const* rows, const float* weights, int count, int offset, float* out) {
  __m256 a[V];
  for (int v = 0; v < V; ++v) a[v] = _mm256_setzero_ps();
  for (int k = 0; k < count; ++k) {
    const __m256 w = _mm256_set1_ps(weights[k]);
    const std::uint16_t* row = rows[k] + offset;
    for (int v = 0; v < V; ++v) a[v] = _mm256_fmadd_ps(w, load_halves(row + 8 * v), a[v]);
  }
  for (int v = 0; v < V; ++v) _mm256_storeu_ps(out + offset + 8 * v, a[v]);
}

__attribute__((target("avx2,fma,f16c"))) void sum_rows_f16_avx2(const std::uint16_t* const* rows,
                                                                const float* weights, int count,
                                                                int stride, float* out) {
  // Blocks of up to 8 vectors (64 wavelengths): 8 accumulators, the weight and a widened row
  // fit the 16 vector registers.
  for (int c = 0; c < stride; c += 64) {
    switch (std::min(stride - c, 64) / 8) {
      case 1:
        sum_rows_f16_block<1>(rows, weights, count, c, out);
        break;
      case 2:
        sum_rows_f16_block<2>(rows, weights, count, c, out);
        break;
      case 3:
        sum_rows_f16_block<3>(rows, weights, count, c, out);
        break;
      case 4:
        sum_rows_f16_block<4>(rows, weights, count, c, out);
        break;
      case 5:
        sum_rows_f16_block<5>(rows, weights, count, c, out);
        break;
      case 6:
        sum_rows_f16_block<6>(rows, weights, count, c, out);
        break;
      case 7:
        sum_rows_f16_block<7>(rows, weights, count, c, out);
        break;
      default:
        sum_rows_f16_block<8>(rows, weights, count, c, out);
        break;
    }
  }
}

__attribute__((target("avx2,fma,f16c"))) void floats_to_halves_avx2(const float* in, float scale,
                                                                    std::uint16_t* out,
                                                                    std::size_t n) {
  const __m256 s = _mm256_set1_ps(scale);
  std::size_t i = 0;
  for (; i + 8 <= n; i += 8) {
    const __m128i h =
        _mm256_cvtps_ph(_mm256_mul_ps(_mm256_loadu_ps(in + i), s), _MM_FROUND_TO_NEAREST_INT);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out + i), h);
  }
  for (; i < n; ++i) out[i] = float_to_half(in[i] * scale);
}

bool cpu_has_avx2_f16c() {
  __builtin_cpu_init();
  // F16C from CPUID leaf 1 (ECX bit 29, <cpuid.h>'s bit_F16C): clang before 16 does not take
  // "f16c" in __builtin_cpu_supports, and the fuzz build (docs/fuzzing.md) is clang 14's.
  unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
  const bool f16c = __get_cpuid(1, &eax, &ebx, &ecx, &edx) != 0 && (ecx & bit_F16C) != 0;
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") && f16c;
}
#else
bool cpu_has_avx2_f16c() { return false; }
#endif

struct Kernels {
  void (*sum_f32)(const float* const*, const float*, int, int, float*);
  void (*sum_f16)(const std::uint16_t* const*, const float*, int, int, float*);
  void (*to_halves)(const float*, float, std::uint16_t*, std::size_t);
  bool avx2;
};

const Kernels& kernels() {
  static const Kernels k = [] {
#ifdef CLEARSKY_BRUNETON_X86
    if (cpu_has_avx2_f16c())
      return Kernels{sum_rows_f32_avx2, sum_rows_f16_avx2, floats_to_halves_avx2, true};
#endif
    half_table();
    return Kernels{sum_rows_f32_portable, portable::sum_rows, portable::floats_to_halves, false};
  }();
  return k;
}

}  // namespace

namespace portable {

void sum_rows(const std::uint16_t* const* rows, const float* weights, int count, int stride,
              float* out) {
  const float* table = half_table().data();
  std::fill(out, out + stride, 0.0f);
  for (int k = 0; k < count; ++k) {
    const float w = weights[k];
    const std::uint16_t* row = rows[k];
    for (int i = 0; i < stride; ++i) out[i] += w * table[row[i]];
  }
}

void floats_to_halves(const float* in, float scale, std::uint16_t* out, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) out[i] = float_to_half(in[i] * scale);
}

}  // namespace portable

void sum_rows(const float* const* rows, const float* weights, int count, int stride, float* out) {
  kernels().sum_f32(rows, weights, count, stride, out);
}

void sum_rows(const std::uint16_t* const* rows, const float* weights, int count, int stride,
              float* out) {
  kernels().sum_f16(rows, weights, count, stride, out);
}

void floats_to_halves(const float* in, float scale, std::uint16_t* out, std::size_t n) {
  kernels().to_halves(in, scale, out, n);
}

bool using_avx2_kernels() { return kernels().avx2; }

}  // namespace clearsky::bruneton
