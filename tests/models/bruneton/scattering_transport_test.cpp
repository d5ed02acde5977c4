// The transport's per-sample lookups (models/bruneton/scattering_transport.h) against
// gather_4d() and sum_rows() one texel at a time, as the precomputation did before: the same
// value bit for bit.
#include "models/bruneton/scattering_transport.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "models/bruneton/spectral_rows.h"

namespace clearsky::bruneton {
namespace {

// A 4D table of random rows (half values of either sign, power-of-two row scales, some rows
// zero as the precomputation leaves the dark ones).
HalfTable4D random_table(const Resolution& res, int stride, std::mt19937& random) {
  HalfTable4D table;
  table.allocate(res, stride);
  std::uniform_real_distribution<float> value(-1.0f, 4.0f);
  std::vector<float> row(table.row_texels() * stride);
  for (int r = 0; r < res.r; ++r) {
    for (int mu = 0; mu < res.mu; ++mu) {
      const float scale = std::ldexp(1.0f, (r * 7 + mu) % 40 - 20);
      const bool dark = (r + mu) % 5 == 0;
      for (float& v : row) v = dark ? 0.0f : value(random) * scale;
      table.store_row(r, mu, row.data());
    }
  }
  return table;
}

void check(int wavelengths) {
  Resolution res;
  res.r = 4;
  res.mu = 6;
  res.mu_s = 9;
  res.nu = 3;
  const int stride = padded_stride(wavelengths);
  std::mt19937 random(11);
  const HalfTable4D table = random_table(res, stride, random);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> pick(0, 3);
  // An axis at a random position, at a texel centre (one texel), or at an edge (both texels
  // the last one).
  auto axis = [&](int n) {
    const int kind = pick(random);
    if (kind == 0) return texture_axis((random() % n + 0.5) / n, n);
    if (kind == 1) return texture_axis(1.0 - 0.1 / n, n);
    return texture_axis(unit(random), n);
  };
  std::vector<float> view_weight(stride);
  for (int trial = 0; trial < 200; ++trial) {
    for (float& w : view_weight) w = static_cast<float>(unit(random) * 1e3);
    const Axis r = axis(res.r), mu = axis(res.mu);
    const Axis nu = trial % 2 ? nu_axis_4d(texel_nu(pick(random) % res.nu, res.nu), res)
                              : nu_axis_4d(2.0 * unit(random) - 1.0, res);
    std::vector<Axis> mu_s(res.mu_s);
    for (Axis& a : mu_s) a = axis(res.mu_s);
    const TransportLookup lookup = transport_lookup(table, r, mu, nu);
    // Earlier samples' sums in the accumulators.
    std::vector<float> fast(static_cast<std::size_t>(res.mu_s) * stride);
    for (float& v : fast) v = static_cast<float>(unit(random));
    std::vector<float> before = fast;
    add_transport_sample(lookup, mu_s.data(), res.mu_s, view_weight.data(), stride, fast.data());
    // The precomputation of before: a 4D lookup per texel, then acc += view_weight x sample.
    RowList<std::uint16_t> list;
    std::vector<float> sample(stride);
    for (int m = 0; m < res.mu_s; ++m) {
      list.clear();
      gather_4d(table, Coord4{r, mu, mu_s[m], nu}, 1.0, list);
      list.sum(stride, sample.data());
      float* acc = before.data() + static_cast<std::size_t>(m) * stride;
      for (int w = 0; w < stride; ++w) acc[w] += view_weight[w] * sample[w];
    }
    ASSERT_EQ(fast, before) << "trial " << trial;
    std::vector<float> reference(before.size());
    // The reference path of CPUs without AVX2 gives the same as well.
    for (std::size_t i = 0; i < reference.size(); ++i) reference[i] = 0.0f;
    std::vector<float> zero = reference;
    add_transport_sample_reference(lookup, mu_s.data(), res.mu_s, view_weight.data(), stride,
                                   reference.data());
    add_transport_sample(lookup, mu_s.data(), res.mu_s, view_weight.data(), stride, zero.data());
    ASSERT_EQ(reference, zero) << "trial " << trial;
  }
}

TEST(ScatteringTransport, SameAsOneLookupPerTexel) {
  check(40);  // the default grid: 5 chunks of 8
  check(3);   // one chunk
  check(81);  // 11 chunks: 2 x 5 + 1
  check(30);  // 4 chunks
}

}  // namespace
}  // namespace clearsky::bruneton
