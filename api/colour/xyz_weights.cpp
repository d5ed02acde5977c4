// XYZ weights from unit spectra.
#include "api/colour/xyz_weights.h"

#include <algorithm>

#include "models/spectral/reference_spectra.h"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define CLEARSKY_XYZ_AVX2 1
#endif

namespace clearsky::api {

namespace {

#ifdef CLEARSKY_XYZ_AVX2
// c += w[i] * v, for the three weights of wavelength i and the values v of four spectra: the
// products and sums of xyz() in each lane (mul then add, never fused: the target has no FMA).
__attribute__((target("avx2"))) inline void add_wavelength(const double* wx, const double* wy,
                                                           const double* wz, std::size_t i,
                                                           __m256d v, __m256d& cx, __m256d& cy,
                                                           __m256d& cz) {
  cx = _mm256_add_pd(cx, _mm256_mul_pd(_mm256_broadcast_sd(wx + i), v));
  cy = _mm256_add_pd(cy, _mm256_mul_pd(_mm256_broadcast_sd(wy + i), v));
  cz = _mm256_add_pd(cz, _mm256_mul_pd(_mm256_broadcast_sd(wz + i), v));
}

// Four spectra at a time: their values at four wavelengths are loaded as four rows and
// transposed into four columns (one wavelength of the four spectra each); n wavelengths.
__attribute__((target("avx2"))) std::size_t xyz_of_rows_avx2(const double* wx, const double* wy,
                                                             const double* wz, std::size_t n,
                                                             const double* spectra,
                                                             std::size_t length, std::size_t count,
                                                             Xyz* out) {
  std::size_t j = 0;
  for (; j + 4 <= count; j += 4) {
    const double* s0 = spectra + j * length;
    const double* s1 = s0 + length;
    const double* s2 = s1 + length;
    const double* s3 = s2 + length;
    __m256d cx = _mm256_setzero_pd(), cy = _mm256_setzero_pd(), cz = _mm256_setzero_pd();
    std::size_t i = 0;
    for (; i + 4 <= n; i += 4) {
      const __m256d r0 = _mm256_loadu_pd(s0 + i), r1 = _mm256_loadu_pd(s1 + i);
      const __m256d r2 = _mm256_loadu_pd(s2 + i), r3 = _mm256_loadu_pd(s3 + i);
      const __m256d even01 = _mm256_unpacklo_pd(r0, r1), odd01 = _mm256_unpackhi_pd(r0, r1);
      const __m256d even23 = _mm256_unpacklo_pd(r2, r3), odd23 = _mm256_unpackhi_pd(r2, r3);
      add_wavelength(wx, wy, wz, i, _mm256_permute2f128_pd(even01, even23, 0x20), cx, cy, cz);
      add_wavelength(wx, wy, wz, i + 1, _mm256_permute2f128_pd(odd01, odd23, 0x20), cx, cy, cz);
      add_wavelength(wx, wy, wz, i + 2, _mm256_permute2f128_pd(even01, even23, 0x31), cx, cy, cz);
      add_wavelength(wx, wy, wz, i + 3, _mm256_permute2f128_pd(odd01, odd23, 0x31), cx, cy, cz);
    }
    for (; i < n; ++i)
      add_wavelength(wx, wy, wz, i, _mm256_set_pd(s3[i], s2[i], s1[i], s0[i]), cx, cy, cz);
    alignas(32) double x[4], y[4], z[4];
    _mm256_store_pd(x, cx);
    _mm256_store_pd(y, cy);
    _mm256_store_pd(z, cz);
    for (int k = 0; k < 4; ++k) out[j + k] = Xyz{x[k], y[k], z[k]};
  }
  return j;
}

bool cpu_has_avx2() {
  static const bool avx2 = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") != 0;
  }();
  return avx2;
}
#endif

}  // namespace

XyzWeights::XyzWeights(const WavelengthGrid& grid) {
  Spectrum unit(grid.size(), 0.0);
  for (std::size_t i = 0; i < grid.size(); ++i) {
    unit[i] = 1.0;
    const Xyz c = spectrum_to_xyz(unit, grid);
    unit[i] = 0.0;
    x_.push_back(c.x);
    y_.push_back(c.y);
    z_.push_back(c.z);
  }
}

XyzWeights XyzWeights::interpolating(const WavelengthGrid& grid) {
  XyzWeights w;
  const std::size_t n = grid.size();
  w.x_.assign(n, 0.0);
  w.y_.assign(n, 0.0);
  w.z_.assign(n, 0.0);
  if (n == 0) return w;
  const auto& ref = ReferenceSpectra::get();
  // The hat functions at lambda: the two nodes around it and their weights.
  const auto hats = [&](double nm, std::size_t& lower, double& t) {
    if (nm <= grid[0]) {
      lower = 0;
      t = 0.0;
      return;
    }
    if (nm >= grid[n - 1]) {
      lower = n - 1;
      t = 0.0;
      return;
    }
    lower = 0;
    while (lower + 1 < n && grid[lower + 1] <= nm) ++lower;
    t = lower + 1 < n ? (nm - grid[lower]) / (grid[lower + 1] - grid[lower]) : 0.0;
  };
  // Trapezoid rule at 0.25 nm over the table (tabulated every 5 nm and linear between, so the
  // integrand is piecewise quadratic: the step's error is far below the tables' 4 decimals).
  constexpr double kStepNm = 0.25;
  const double first = ref.cie_x_bar.min_nm(), last = ref.cie_x_bar.max_nm();
  const auto steps = static_cast<std::size_t>((last - first) / kStepNm + 0.5);
  for (std::size_t k = 0; k <= steps; ++k) {
    const double nm = first + kStepNm * static_cast<double>(k);
    const double dl = (k == 0 || k == steps) ? 0.5 * kStepNm : kStepNm;
    const double x = ref.cie_x_bar.at(nm, OutOfRange::zero) * dl;
    const double y = ref.cie_y_bar.at(nm, OutOfRange::zero) * dl;
    const double z = ref.cie_z_bar.at(nm, OutOfRange::zero) * dl;
    std::size_t i = 0;
    double t = 0.0;
    hats(nm, i, t);
    w.x_[i] += (1.0 - t) * x;
    w.y_[i] += (1.0 - t) * y;
    w.z_[i] += (1.0 - t) * z;
    if (t > 0.0) {
      w.x_[i + 1] += t * x;
      w.y_[i + 1] += t * y;
      w.z_[i + 1] += t * z;
    }
  }
  return w;
}

Xyz XyzWeights::xyz(std::span<const double> s) const {
  Xyz c;
  for (std::size_t i = 0; i < s.size() && i < x_.size(); ++i) {
    c.x += x_[i] * s[i];
    c.y += y_[i] * s[i];
    c.z += z_[i] * s[i];
  }
  return c;
}

void XyzWeights::xyz_of_rows(const double* spectra, std::size_t length, std::size_t count,
                             Xyz* out) const {
  std::size_t j = 0;
#ifdef CLEARSKY_XYZ_AVX2
  if (cpu_has_avx2()) {
    j = xyz_of_rows_avx2(x_.data(), y_.data(), z_.data(), std::min(length, x_.size()), spectra,
                         length, count, out);
  }
#endif
  for (; j < count; ++j) out[j] = xyz({spectra + j * length, length});
}

}  // namespace clearsky::api
