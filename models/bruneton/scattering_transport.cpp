// The transport's per-sample lookups of J, AVX2/F16C/FMA and through sum_rows().
#include "models/bruneton/scattering_transport.h"

#include "models/bruneton/spectral_rows.h"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define CLEARSKY_BRUNETON_X86 1
#endif

namespace clearsky::bruneton {

namespace {

// The rows and float weights of one texel's lookup: both mu_s texels of each of the lookup's
// rows, the terms of weight zero left out (gather_4d()'s order and tests).
struct TexelRows {
  const std::uint16_t* rows[2 * TransportLookup::kCapacity];
  float weights[2 * TransportLookup::kCapacity];
  int count = 0;
};

void texel_rows(const TransportLookup& lookup, const Axis& axis, int stride, TexelRows& out) {
  const double ms_weight[2] = {1.0 - axis.f, axis.f};
  const std::size_t ms_offset[2] = {static_cast<std::size_t>(axis.i0) * stride,
                                    static_cast<std::size_t>(axis.i1) * stride};
  out.count = 0;
  for (int k = 0; k < lookup.count; ++k) {
    for (int e = 0; e < 2; ++e) {
      const double w = lookup.weights[k] * ms_weight[e];
      if (w == 0.0) continue;
      out.rows[out.count] = lookup.rows[k] + ms_offset[e];
      out.weights[out.count++] = static_cast<float>(w);
    }
  }
}

#ifdef CLEARSKY_BRUNETON_X86

__attribute__((target("avx2,fma,f16c"))) inline __m256 load_halves(const std::uint16_t* p) {
  return _mm256_cvtph_ps(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p)));
}

// acc + view_weight x sample, rounded after the product as the scalar code does: the empty asm
// keeps the compiler from fusing the two into one multiply-add (GCC contracts them by default
// in C++ when FMA is enabled).
__attribute__((target("avx2,fma,f16c"))) inline void accumulate(float* acc, __m256 view_weight,
                                                                __m256 sample) {
  __m256 product = _mm256_mul_ps(view_weight, sample);
  __asm__("" : "+x"(product));
  _mm256_storeu_ps(acc, _mm256_add_ps(_mm256_loadu_ps(acc), product));
}

// One texel (Texels = 1) or two with as many rows each (Texels = 2), Chunks x 8 wavelengths
// from `offset`: each lane is the chain of multiply-adds of sum_rows_f16_avx2 (from zero, in
// the rows' order); the chains of the chunks and texels are independent and overlap.
template <int Chunks, int Texels>
__attribute__((target("avx2,fma,f16c"))) inline void add_texels(const TexelRows* const* texels,
                                                                float* const* acc,
                                                                const float* view_weight,
                                                                int offset) {
  __m256 sum[Texels][Chunks];
  for (int t = 0; t < Texels; ++t)
    for (int c = 0; c < Chunks; ++c) sum[t][c] = _mm256_setzero_ps();
  const int count = texels[0]->count;
  for (int k = 0; k < count; ++k) {
    for (int t = 0; t < Texels; ++t) {
      const __m256 w = _mm256_set1_ps(texels[t]->weights[k]);
      const std::uint16_t* row = texels[t]->rows[k] + offset;
      for (int c = 0; c < Chunks; ++c)
        sum[t][c] = _mm256_fmadd_ps(w, load_halves(row + 8 * c), sum[t][c]);
    }
  }
  for (int t = 0; t < Texels; ++t)
    for (int c = 0; c < Chunks; ++c)
      accumulate(acc[t] + offset + 8 * c, _mm256_loadu_ps(view_weight + offset + 8 * c), sum[t][c]);
}

// All chunks of a row of `stride` values, in groups that fit the registers.
template <int Texels>
__attribute__((target("avx2,fma,f16c"))) void add_texels_all(const TexelRows* const* texels,
                                                             float* const* acc,
                                                             const float* view_weight, int stride) {
  int offset = 0;
  for (; offset + 40 <= stride; offset += 40)
    add_texels<5, Texels>(texels, acc, view_weight, offset);
  switch ((stride - offset) / 8) {
    case 4:
      add_texels<4, Texels>(texels, acc, view_weight, offset);
      break;
    case 3:
      add_texels<3, Texels>(texels, acc, view_weight, offset);
      break;
    case 2:
      add_texels<2, Texels>(texels, acc, view_weight, offset);
      break;
    case 1:
      add_texels<1, Texels>(texels, acc, view_weight, offset);
      break;
    default:
      break;
  }
}

__attribute__((target("avx2,fma,f16c"))) void add_transport_sample_avx2(
    const TransportLookup& lookup, const Axis* mu_s_axes, int n_mu_s, const float* view_weight,
    int stride, float* acc) {
  TexelRows rows[2];
  int m = 0;
  for (; m + 2 <= n_mu_s; m += 2) {
    texel_rows(lookup, mu_s_axes[m], stride, rows[0]);
    texel_rows(lookup, mu_s_axes[m + 1], stride, rows[1]);
    float* out[2] = {acc + static_cast<std::size_t>(m) * stride,
                     acc + static_cast<std::size_t>(m + 1) * stride};
    if (rows[0].count == rows[1].count) {
      const TexelRows* pair[2] = {&rows[0], &rows[1]};
      add_texels_all<2>(pair, out, view_weight, stride);
    } else {
      for (int t = 0; t < 2; ++t) {
        const TexelRows* one[1] = {&rows[t]};
        add_texels_all<1>(one, &out[t], view_weight, stride);
      }
    }
  }
  if (m < n_mu_s) {
    texel_rows(lookup, mu_s_axes[m], stride, rows[0]);
    const TexelRows* one[1] = {&rows[0]};
    float* out[1] = {acc + static_cast<std::size_t>(m) * stride};
    add_texels_all<1>(one, out, view_weight, stride);
  }
}

#endif

}  // namespace

TransportLookup transport_lookup(const HalfTable4D& table, const Axis& r, const Axis& mu,
                                 const Axis& nu) {
  const int r_index[2] = {r.i0, r.i1};
  const double r_weight[2] = {1.0 - r.f, r.f};
  const int mu_index[2] = {mu.i0, mu.i1};
  const double mu_weight[2] = {1.0 - mu.f, mu.f};
  const int nu_index[2] = {nu.i0, nu.i1};
  const double nu_weight[2] = {1.0 - nu.f, nu.f};
  TransportLookup lookup;
  for (int a = 0; a < 2; ++a) {
    if (r_weight[a] == 0.0) continue;
    for (int b = 0; b < 2; ++b) {
      const double w_rmu = r_weight[a] * mu_weight[b];
      if (w_rmu == 0.0) continue;
      // gather_4d's weight 1 times w_rmu times the row scale, the same rounding.
      const double w_row = 1.0 * w_rmu * table.row_scale[table.row_index(r_index[a], mu_index[b])];
      for (int d = 0; d < 2; ++d) {
        if (nu_weight[d] == 0.0) continue;
        const double w = w_row * nu_weight[d];
        // Zero here makes both of gather_4d's mu_s terms zero: it leaves them out.
        if (w == 0.0) continue;
        lookup.rows[lookup.count] = table.texel(r_index[a], mu_index[b], nu_index[d], 0);
        lookup.weights[lookup.count++] = w;
      }
    }
  }
  return lookup;
}

void add_transport_sample_reference(const TransportLookup& lookup, const Axis* mu_s_axes,
                                    int n_mu_s, const float* view_weight, int stride, float* acc) {
  ScratchRow sample(stride);
  TexelRows rows;
  for (int m = 0; m < n_mu_s; ++m) {
    texel_rows(lookup, mu_s_axes[m], stride, rows);
    sum_rows(rows.rows, rows.weights, rows.count, stride, sample.data());
    float* out = acc + static_cast<std::size_t>(m) * stride;
    for (int w = 0; w < stride; ++w) out[w] += view_weight[w] * sample.data()[w];
  }
}

void add_transport_sample(const TransportLookup& lookup, const Axis* mu_s_axes, int n_mu_s,
                          const float* view_weight, int stride, float* acc) {
#ifdef CLEARSKY_BRUNETON_X86
  // The AVX2 kernel reproduces sum_rows_f16_avx2; the portable sum_rows rounds differently.
  if (using_avx2_kernels()) {
    add_transport_sample_avx2(lookup, mu_s_axes, n_mu_s, view_weight, stride, acc);
    return;
  }
#endif
  add_transport_sample_reference(lookup, mu_s_axes, n_mu_s, view_weight, stride, acc);
}

}  // namespace clearsky::bruneton
