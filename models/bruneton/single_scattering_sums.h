// The sum along a view ray of single scattering (Bruneton and Neyret 2008, Eq. 6; the 2008
// code's inscatter1) for one texel, before the scattering coefficients: over the ray's samples
// lit by the sun, the trapezoid weight x the density x T(origin, sample) x T(sample, sun), with
// Rayleigh and Mie densities apart.
//
// The geometry of each sample (its lookup of the sun's transmittance, its weights) is found
// first, the spectral sums then run in one pass per group of wavelengths with the two running
// sums in registers: the same operations in the same order as one sample at a time through
// memory (sum_rows() for T(sample, sun), then a product and an addition per wavelength, never
// fused), so the tables are the same bit for bit (tests/models/bruneton/
// single_scattering_sums_test.cpp).
#pragma once

namespace clearsky::bruneton {

// One sample of the view ray, lit by the sun.
struct SunlitSample {
  // T(sample, sun): the bilinear lookup's rows of the transmittance table and their weights,
  // the terms of weight zero left out.
  const float* rows[4];
  float weights[4];
  int count = 0;
  const float* view = nullptr;       // T(origin, sample), one value per wavelength
  float weight_r = 0, weight_m = 0;  // trapezoid weight x Rayleigh / Mie density
};

// For each wavelength w in [0, stride): sum_r[w] += weight_r x (view[w] x sun[w]) and sum_m[w]
// likewise, sample after sample, where sun = sum_rows(rows, weights). stride is a multiple of 8.
void add_sunlit_samples(const SunlitSample* samples, int count, int stride, float* sum_r,
                        float* sum_m);

// The same one sample at a time through sum_rows(): what the precomputation did before, the path
// of CPUs without AVX2 and the tests' reference.
void add_sunlit_samples_reference(const SunlitSample* samples, int count, int stride, float* sum_r,
                                  float* sum_m);

}  // namespace clearsky::bruneton
