// F16C and portable float-to-half conversion (api/skydome/half_conversion.h).
#include "api/skydome/half_conversion.h"

#include <cstdint>

#if defined(__x86_64__) && defined(__GNUC__)
#include <cpuid.h>
#include <immintrin.h>
#define CLEARSKY_HALF_F16C 1
#endif

namespace clearsky::api {

namespace {

void floats_to_halves_portable(const float* in, half* out, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) out[i] = half(in[i]);
}

#ifdef CLEARSKY_HALF_F16C
__attribute__((target("avx,f16c"))) void floats_to_halves_f16c(const float* in, half* out,
                                                               std::size_t n) {
  static_assert(sizeof(half) == sizeof(std::uint16_t));
  std::size_t i = 0;
  for (; i + 8 <= n; i += 8) {
    const __m128i h =
        _mm256_cvtps_ph(_mm256_loadu_ps(in + i), _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out + i), h);
  }
  // The tail one float at a time, by the 128-bit form (_cvtss_sh is the same instruction, but
  // clang's macro for it is a compound literal, which -Wc99-extensions refuses).
  for (; i < n; ++i) {
    const __m128i h =
        _mm_cvtps_ph(_mm_set_ss(in[i]), _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
    out[i].setBits(static_cast<std::uint16_t>(_mm_cvtsi128_si32(h)));
  }
}

bool cpu_has_f16c() {
  // F16C from CPUID leaf 1 (ECX bit 29, <cpuid.h>'s bit_F16C), as
  // models/bruneton/spectral_rows.cpp reads it (clang before 16 does not take "f16c" in
  // __builtin_cpu_supports); the 256-bit form needs AVX as well.
  unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
  if (__get_cpuid(1, &eax, &ebx, &ecx, &edx) == 0) return false;
  __builtin_cpu_init();
  return (ecx & bit_F16C) != 0 && __builtin_cpu_supports("avx");
}
#endif

using Conversion = void (*)(const float*, half*, std::size_t);

Conversion conversion() {
  static const Conversion chosen = [] {
#ifdef CLEARSKY_HALF_F16C
    if (cpu_has_f16c()) return &floats_to_halves_f16c;
#endif
    return &floats_to_halves_portable;
  }();
  return chosen;
}

}  // namespace

void floats_to_halves(const float* in, half* out, std::size_t n) { conversion()(in, out, n); }

}  // namespace clearsky::api
