// J's direction weights, one texel at a time and four texels per AVX2 pass.
#include "models/bruneton/density_weights.h"

#include <algorithm>

#include "models/atmosphere/phase_functions.h"
#include "models/bruneton/spectral_rows.h"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define CLEARSKY_BRUNETON_X86 1
#endif

namespace clearsky::bruneton {

void DensityWeights::prepare(int texel_count, const DensitySphere& sphere) {
  const int padded = (texel_count + 3) / 4 * 4;
  const bool same_shape =
      n_theta == sphere.n_theta && n_nu == sphere.n_nu && n_e == sphere.n_e && texels >= padded;
  if (!same_shape) {
    texels = padded;
    n_theta = sphere.n_theta;
    n_nu = sphere.n_nu;
    n_e = sphere.n_e;
    const std::size_t n_ground = static_cast<std::size_t>(texels) * n_theta * n_e;
    ground.assign(2 * n_ground, 0.0);
    ground_range.assign(static_cast<std::size_t>(texels) * n_theta, {n_e, -1});
  }
  per_slot = sphere.first ? 4 : 2;
  const std::size_t n_slots = static_cast<std::size_t>(texels) * n_theta * (n_nu + 1);
  profile.assign(n_slots * per_slot, 0.0);
}

namespace {

// One texel: the loop of before (its terms and their order define the weights). Consecutive
// azimuths mostly fall in the same two nu slices: their sums are carried in registers while the
// slices stay the same and written back when they change, every slot receiving the same
// additions in the same order as with one store per term.
template <bool First>
void reference_texel(const DensitySphere& s, double sx, double sy, int t, DensityWeights& out) {
  Resolution res;
  res.nu = s.n_nu;
  const int n_e = s.n_e;
  for (int i = 0; i < s.n_theta; ++i) {
    const bool sees_ground = s.ground[i] != 0;
    const double z = s.mu_s * s.cos_t[i];
    constexpr int kSums = First ? 4 : 2;
    // Weight q of slot k at sums[k * kSums + q]; ground column e's g_r, g_m at g[2 e], g[2 e + 1].
    double* const sums = out.profile.data() + out.slot(t, i, 0) * kSums;
    double* const g = out.ground.data() + out.column(t, i, 0) * 2;
    int lowest = n_e, highest = -1;
    double low[4] = {}, high[4] = {};
    int run = -1;  // the lower slice of the pair held in low/high, -1 for none
    auto write_back = [&] {
      if (run < 0) return;
      for (int q = 0; q < kSums; ++q) {
        sums[run * kSums + q] = low[q];
        sums[(run + 1) * kSums + q] = high[q];
      }
      run = -1;
    };
    for (int p = 0; p < s.n_phi; ++p) {
      const std::size_t d = static_cast<std::size_t>(i) * s.n_phi + p;
      const double nu1 = sx * s.wx[d] + sy * s.wy[d] + z;
      const Axis slice = nu_axis_4d(nu1, res);
      const double pr = s.phase_r[d];
      const double pm = s.phase_m[d];
      const double f1 = 1.0 - slice.f;
      const double f2 = slice.f;
      double term_low[4], term_high[4];
      if constexpr (First) {
        // Single scattering gets its phase functions here (2008 code, first iteration).
        const double p1r = rayleigh_phase(nu1);
        const double p1m = (*s.mie_phase)(nu1);
        term_low[0] = f1 * p1r * pr;
        term_high[0] = f2 * p1r * pr;
        term_low[1] = f1 * p1r * pm;
        term_high[1] = f2 * p1r * pm;
        term_low[2] = f1 * p1m * pr;
        term_high[2] = f2 * p1m * pr;
        term_low[3] = f1 * p1m * pm;
        term_high[3] = f2 * p1m * pm;
      } else {
        term_low[0] = f1 * pr;
        term_high[0] = f2 * pr;
        term_low[1] = f1 * pm;
        term_high[1] = f2 * pm;
      }
      if (slice.i1 != slice.i0 + 1) {
        // The last slice alone (its weight f2 is zero): straight to memory.
        write_back();
        for (int q = 0; q < kSums; ++q) {
          sums[slice.i0 * kSums + q] += term_low[q];
          sums[slice.i1 * kSums + q] += term_high[q];
        }
      } else {
        if (slice.i0 != run) {
          write_back();
          run = slice.i0;
          for (int q = 0; q < kSums; ++q) {
            low[q] = sums[run * kSums + q];
            high[q] = sums[(run + 1) * kSums + q];
          }
        }
        for (int q = 0; q < kSums; ++q) {
          low[q] += term_low[q];
          high[q] += term_high[q];
        }
      }
      if (sees_ground) {
        // Light reflected by the ground point seen in direction w (Lambertian, delta E of the
        // previous order at the ground, for the sun at gnormal . s).
        const double mu_ground = (s.r * s.mu_s + s.d_ground[i] * nu1) / s.bottom_m;
        const Axis e = texture_axis(irradiance_u_mu_s(mu_ground, s.sun), n_e);
        g[2 * e.i0] += (1.0 - e.f) * pr;
        g[2 * e.i1] += e.f * pr;
        g[2 * e.i0 + 1] += (1.0 - e.f) * pm;
        g[2 * e.i1 + 1] += e.f * pm;
        lowest = std::min(lowest, e.i0);
        highest = std::max(highest, e.i1);
      }
    }
    write_back();
    out.range(t, i) = {lowest, highest};
  }
}

#ifdef CLEARSKY_BRUNETON_X86

// The vector forms below repeat the scalar operations one for one (no operation is fused: the
// target has no FMA), so every lane rounds as the scalar code does.
struct alignas(32) Lanes {
  double v[4];
};

__attribute__((target("avx2"))) inline __m256d select(__m256d mask, __m256d if_true,
                                                      __m256d if_false) {
  return _mm256_blendv_pd(if_false, if_true, mask);
}

// nu_axis_4d's slice and fraction: the lower slice index (as a double) and f, for nu within
// [-1, 1] after clamping (sx, sy and mu_s are finite).
__attribute__((target("avx2"))) inline void nu_slices(__m256d nu, double last_slice, __m256d& lower,
                                                      __m256d& f) {
  const __m256d minus_one = _mm256_set1_pd(-1.0);
  const __m256d one = _mm256_set1_pd(1.0);
  // std::clamp(nu, -1.0, 1.0)
  __m256d c = select(_mm256_cmp_pd(nu, minus_one, _CMP_LT_OQ), minus_one, nu);
  c = select(_mm256_cmp_pd(one, c, _CMP_LT_OQ), one, c);
  // (c + 1) / 2 * (res.nu - 1): halving is exact, as a product or a quotient.
  const __m256d lerp = _mm256_mul_pd(_mm256_mul_pd(_mm256_add_pd(c, one), _mm256_set1_pd(0.5)),
                                     _mm256_set1_pd(last_slice));
  __m256d k = _mm256_floor_pd(lerp);
  __m256d frac = _mm256_sub_pd(lerp, k);
  const __m256d snap_down = _mm256_cmp_pd(frac, _mm256_set1_pd(1e-9), _CMP_LT_OQ);
  const __m256d snap_up =
      _mm256_andnot_pd(snap_down, _mm256_cmp_pd(frac, _mm256_set1_pd(1.0 - 1e-9), _CMP_GT_OQ));
  k = select(snap_up, _mm256_add_pd(k, one), k);
  frac = _mm256_andnot_pd(_mm256_or_pd(snap_down, snap_up), frac);
  // std::clamp(static_cast<int>(k), 0, res.nu - 1)
  lower = _mm256_min_pd(_mm256_max_pd(k, _mm256_setzero_pd()), _mm256_set1_pd(last_slice));
  f = frac;
}

// texture_axis(u, n): the two texels (as doubles) and the weight of the second.
__attribute__((target("avx2"))) inline void texture_axes(__m256d u, int n, __m256d& first,
                                                         __m256d& second, __m256d& f) {
  const __m256d minus_one = _mm256_set1_pd(-1.0);
  const __m256d size = _mm256_set1_pd(static_cast<double>(n));
  __m256d p = _mm256_sub_pd(_mm256_mul_pd(u, size), _mm256_set1_pd(0.5));
  p = select(_mm256_cmp_pd(p, minus_one, _CMP_GE_OQ), p, minus_one);  // also NaN
  p = select(_mm256_cmp_pd(p, size, _CMP_GT_OQ), size, p);
  __m256d fl = _mm256_floor_pd(p);
  __m256d frac = _mm256_sub_pd(p, fl);
  const __m256d snap_down = _mm256_cmp_pd(frac, _mm256_set1_pd(1e-9), _CMP_LT_OQ);
  const __m256d snap_up =
      _mm256_andnot_pd(snap_down, _mm256_cmp_pd(frac, _mm256_set1_pd(1.0 - 1e-9), _CMP_GT_OQ));
  fl = select(snap_up, _mm256_add_pd(fl, _mm256_set1_pd(1.0)), fl);
  frac = _mm256_andnot_pd(_mm256_or_pd(snap_down, snap_up), frac);
  // fl is within [-1, n]: the texels i and i + 1 clamped to the table.
  const __m256d last = _mm256_set1_pd(n - 1.0);
  first = _mm256_min_pd(_mm256_max_pd(fl, _mm256_setzero_pd()), last);
  second = _mm256_min_pd(_mm256_max_pd(_mm256_add_pd(fl, _mm256_set1_pd(1.0)), _mm256_setzero_pd()),
                         last);
  f = frac;
}

__attribute__((target("avx2"))) inline void store_indices(__m256d index, int* out) {
  _mm_storeu_si128(reinterpret_cast<__m128i*>(out), _mm256_cvttpd_epi32(index));
}

// Lane l of x, twice: [x_l, x_l].
__attribute__((target("avx2"))) inline __m128d lane_pair(__m256d x, int l) {
  const __m128d half = l < 2 ? _mm256_castpd256_pd128(x) : _mm256_extractf128_pd(x, 1);
  return (l & 1) == 0 ? _mm_unpacklo_pd(half, half) : _mm_unpackhi_pd(half, half);
}

// *p += v, two or four doubles: one slot's weights (or one ground column's) at once.
__attribute__((target("avx2"))) inline void add_to(double* p, __m128d v) {
  _mm_storeu_pd(p, _mm_add_pd(_mm_loadu_pd(p), v));
}
__attribute__((target("avx2"))) inline void add_to(double* p, __m256d v) {
  _mm256_storeu_pd(p, _mm256_add_pd(_mm256_loadu_pd(p), v));
}

// Four texels t0 .. t0 + 3. Each direction's terms are computed in vector form and added to
// each texel's slots in the scalar code's order: the lower slice gets the low terms, the next
// slice the high ones (the scratch slot n_nu when the lower is the last slice, whose high terms
// are zero: adding zero to a slot leaves it as it was). A slot's weights lie next to each other,
// so each texel's low (and high) terms go in with one vector addition: lane l's products are
// the scalar code's, f1 x [pr, pm] (later orders) or (f1 x [p1r, p1r, p1m, p1m]) x [pr, pm, pr,
// pm] (the first), one rounding each as there.
template <bool First>
__attribute__((target("avx2"))) void four_texels(const DensitySphere& s, const double* sx_in,
                                                 const double* sy_in, int t0, DensityWeights& out) {
  const __m256d sx = _mm256_loadu_pd(sx_in + t0);
  const __m256d sy = _mm256_loadu_pd(sy_in + t0);
  const double last_slice = s.n_nu - 1;
  const __m256d r_mu_s = _mm256_set1_pd(s.r * s.mu_s);
  const __m256d bottom = _mm256_set1_pd(s.bottom_m);
  const __m256d e_min = _mm256_set1_pd(s.sun.irradiance_min_mu_s);
  const __m256d e_span = _mm256_set1_pd(s.sun.irradiance_span);
  const __m256d one = _mm256_set1_pd(1.0);
  // Rayleigh and Cornette-Shanks as phase_functions.h writes them, constants first.
  const double rayleigh_constant = 3.0 / (16.0 * kPi);
  const double g = First ? s.mie_phase->g : 0.0;
  const double g2 = g * g;
  const double cs_constant = 3.0 / (8.0 * kPi) * (1.0 - g2) / (2.0 + g2);
  const bool tabulated = First && s.mie_phase->table != nullptr;
  constexpr int kSums = First ? 4 : 2;
  alignas(16) int lower[4];
  alignas(16) int g_first[4], g_second[4];
  for (int i = 0; i < s.n_theta; ++i) {
    const bool sees_ground = s.ground[i] != 0;
    const __m256d z = _mm256_set1_pd(s.mu_s * s.cos_t[i]);
    const __m256d d_ground = _mm256_set1_pd(s.d_ground[i]);
    double* sums[4];
    double* ground[4];
    int lowest[4], highest[4];
    for (int l = 0; l < 4; ++l) {
      sums[l] = out.profile.data() + out.slot(t0 + l, i, 0) * kSums;
      ground[l] = out.ground.data() + out.column(t0 + l, i, 0) * 2;
      lowest[l] = s.n_e;
      highest[l] = -1;
    }
    for (int p = 0; p < s.n_phi; ++p) {
      const std::size_t d = static_cast<std::size_t>(i) * s.n_phi + p;
      // sx * wx + sy * wy + z
      const __m256d nu1 = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(sx, _mm256_set1_pd(s.wx[d])),
                                                      _mm256_mul_pd(sy, _mm256_set1_pd(s.wy[d]))),
                                        z);
      __m256d slice, f2;
      nu_slices(nu1, last_slice, slice, f2);
      const __m256d f1 = _mm256_sub_pd(one, f2);
      const double pr = s.phase_r[d];
      const double pm = s.phase_m[d];
      const __m128d phases = _mm_set_pd(pm, pr);  // [pr, pm]
      store_indices(slice, lower);
      if constexpr (First) {
        const __m256d p1r = _mm256_mul_pd(_mm256_set1_pd(rayleigh_constant),
                                          _mm256_add_pd(one, _mm256_mul_pd(nu1, nu1)));
        __m256d p1m;
        if (tabulated) {
          Lanes nu_lanes, phase;
          _mm256_store_pd(nu_lanes.v, nu1);
          for (int l = 0; l < 4; ++l) phase.v[l] = (*s.mie_phase)(nu_lanes.v[l]);
          p1m = _mm256_load_pd(phase.v);
        } else {
          // (1 + g^2 - 2 g mu), then the constant x (1 + mu^2) / (den sqrt(max(den, 0))).
          const __m256d den =
              _mm256_sub_pd(_mm256_set1_pd(1.0 + g2), _mm256_mul_pd(_mm256_set1_pd(2.0 * g), nu1));
          const __m256d root = _mm256_sqrt_pd(_mm256_max_pd(_mm256_setzero_pd(), den));
          p1m = _mm256_div_pd(_mm256_mul_pd(_mm256_set1_pd(cs_constant),
                                            _mm256_add_pd(one, _mm256_mul_pd(nu1, nu1))),
                              _mm256_mul_pd(den, root));
        }
        // Lane l of [f1 p1r, f1 p1m] and [f2 p1r, f2 p1m], spread to [x_r, x_r, x_m, x_m].
        const __m256d l_r = _mm256_mul_pd(f1, p1r), h_r = _mm256_mul_pd(f2, p1r);
        const __m256d l_m = _mm256_mul_pd(f1, p1m), h_m = _mm256_mul_pd(f2, p1m);
        const __m256d low02 = _mm256_unpacklo_pd(l_r, l_m), low13 = _mm256_unpackhi_pd(l_r, l_m);
        const __m256d high02 = _mm256_unpacklo_pd(h_r, h_m), high13 = _mm256_unpackhi_pd(h_r, h_m);
        const __m256d four_phases = _mm256_set_m128d(phases, phases);  // [pr, pm, pr, pm]
        const __m256d low[4] = {
            _mm256_permute4x64_pd(low02, 0x50), _mm256_permute4x64_pd(low13, 0x50),
            _mm256_permute4x64_pd(low02, 0xfa), _mm256_permute4x64_pd(low13, 0xfa)};
        const __m256d high[4] = {
            _mm256_permute4x64_pd(high02, 0x50), _mm256_permute4x64_pd(high13, 0x50),
            _mm256_permute4x64_pd(high02, 0xfa), _mm256_permute4x64_pd(high13, 0xfa)};
        for (int l = 0; l < 4; ++l) {
          double* slot = sums[l] + lower[l] * kSums;
          add_to(slot, _mm256_mul_pd(low[l], four_phases));
          add_to(slot + kSums, _mm256_mul_pd(high[l], four_phases));
        }
      } else {
        for (int l = 0; l < 4; ++l) {
          double* slot = sums[l] + lower[l] * kSums;
          add_to(slot, _mm_mul_pd(lane_pair(f1, l), phases));
          add_to(slot + kSums, _mm_mul_pd(lane_pair(f2, l), phases));
        }
      }
      if (sees_ground) {
        // (r mu_s + d nu1) / Rg, then irradiance_u_mu_s and texture_axis.
        const __m256d mu_ground =
            _mm256_div_pd(_mm256_add_pd(r_mu_s, _mm256_mul_pd(d_ground, nu1)), bottom);
        const __m256d u = _mm256_div_pd(_mm256_sub_pd(mu_ground, e_min), e_span);
        __m256d c0, c1, fe;
        texture_axes(u, s.n_e, c0, c1, fe);
        const __m256d fe1 = _mm256_sub_pd(one, fe);
        store_indices(c0, g_first);
        store_indices(c1, g_second);
        for (int l = 0; l < 4; ++l) {
          const int e0 = g_first[l], e1 = g_second[l];
          add_to(ground[l] + 2 * e0, _mm_mul_pd(lane_pair(fe1, l), phases));
          add_to(ground[l] + 2 * e1, _mm_mul_pd(lane_pair(fe, l), phases));
          lowest[l] = std::min(lowest[l], e0);
          highest[l] = std::max(highest[l], e1);
        }
      }
    }
    for (int l = 0; l < 4; ++l) out.range(t0 + l, i) = {lowest[l], highest[l]};
  }
}

#endif

}  // namespace

void density_weights_reference(const DensitySphere& sphere, const double* sx, const double* sy,
                               int texels, DensityWeights& weights) {
  for (int t = 0; t < texels; ++t) {
    if (sphere.first) {
      reference_texel<true>(sphere, sx[t], sy[t], t, weights);
    } else {
      reference_texel<false>(sphere, sx[t], sy[t], t, weights);
    }
  }
}

void density_weights(const DensitySphere& sphere, const double* sx, const double* sy, int texels,
                     DensityWeights& weights) {
#ifdef CLEARSKY_BRUNETON_X86
  if (using_avx2_kernels()) {
    for (int t0 = 0; t0 < texels; t0 += 4) {
      if (sphere.first) {
        four_texels<true>(sphere, sx, sy, t0, weights);
      } else {
        four_texels<false>(sphere, sx, sy, t0, weights);
      }
    }
    return;
  }
#endif
  density_weights_reference(sphere, sx, sy, texels, weights);
}

}  // namespace clearsky::bruneton
