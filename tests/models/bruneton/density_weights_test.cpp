// J's direction weights (models/bruneton/density_weights.h): the vector path against the one
// texel at a time of before, bit for bit, and the weights' sums against the sphere's.
#include "models/bruneton/density_weights.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "models/atmosphere/phase_functions.h"
#include "models/atmosphere/tabulated_phase_function.h"
#include "models/bruneton/spectral_rows.h"
#include "models/core/numeric.h"

namespace clearsky::bruneton {
namespace {

// The sphere of a layer near the ground, as the precomputation builds it: 16 x 32 directions,
// the phases towards a view of cosine mu, the lower zeniths seeing the ground.
struct Layer {
  std::vector<double> cos_t, wx, wy, phase_r, phase_m, d_ground;
  std::vector<char> ground;
  MiePhase mie;
  DensitySphere sphere;

  Layer(double r, double mu, double mu_s, int n_nu, bool first, MiePhase mie_phase)
      : mie(std::move(mie_phase)) {
    const int n_theta = 16, n_phi = 32;
    const double bottom = 6360e3;
    const double dtheta = kPi / n_theta;
    const double horizon = -std::sqrt(1.0 - bottom * bottom / (r * r));
    for (int i = 0; i < n_theta; ++i) {
      const double ct = std::cos((i + 0.5) * dtheta), st = std::sin((i + 0.5) * dtheta);
      cos_t.push_back(ct);
      ground.push_back(ct < horizon ? 1 : 0);
      d_ground.push_back(
          ct < horizon ? -r * ct - std::sqrt(r * r * (ct * ct - 1.0) + bottom * bottom) : 0.0);
      for (int p = 0; p < n_phi; ++p) {
        const double phi = (p + 0.5) * dtheta;
        wx.push_back(std::cos(phi) * st);
        wy.push_back(std::sin(phi) * st);
        const double nu2 = std::sqrt(1.0 - mu * mu) * wx.back() + mu * ct;
        const double dw = dtheta * dtheta * st;
        phase_r.push_back(rayleigh_phase(nu2) * dw);
        phase_m.push_back(mie(nu2) * dw);
      }
    }
    sphere.n_theta = n_theta;
    sphere.n_phi = n_phi;
    sphere.n_nu = n_nu;
    sphere.n_e = 64;
    sphere.cos_t = cos_t.data();
    sphere.wx = wx.data();
    sphere.wy = wy.data();
    sphere.phase_r = phase_r.data();
    sphere.phase_m = phase_m.data();
    sphere.ground = ground.data();
    sphere.d_ground = d_ground.data();
    sphere.r = r;
    sphere.mu_s = mu_s;
    sphere.bottom_m = bottom;
    sphere.mie_phase = &mie;
    sphere.first = first;
  }
};

// The sun directions of the nu slices of a texel row (bruneton_tables.cpp's density_column),
// padded to a multiple of 4.
void slice_suns(double mu, double mu_s, int n_nu, std::vector<double>& sx,
                std::vector<double>& sy) {
  const int lanes = (n_nu + 3) / 4 * 4;
  sx.assign(lanes, 0.0);
  sy.assign(lanes, 0.0);
  const double vx = std::sqrt(1.0 - mu * mu);
  for (int k = 0; k < n_nu; ++k) {
    const double var = vx * std::sqrt(1.0 - mu_s * mu_s);
    const double nu = std::clamp(texel_nu(k, n_nu), mu_s * mu - var, mu_s * mu + var);
    sx[k] = vx == 0.0 ? 0.0 : (nu - mu_s * mu) / vx;
    sy[k] = std::sqrt(std::max(0.0, 1.0 - sx[k] * sx[k] - mu_s * mu_s));
  }
}

void expect_same_weights(const Layer& layer, double mu) {
  std::vector<double> sx, sy;
  const int n_nu = layer.sphere.n_nu;
  slice_suns(mu, layer.sphere.mu_s, n_nu, sx, sy);
  DensityWeights fast, reference;
  fast.prepare(n_nu, layer.sphere);
  reference.prepare(n_nu, layer.sphere);
  density_weights(layer.sphere, sx.data(), sy.data(), n_nu, fast);
  density_weights_reference(layer.sphere, sx.data(), sy.data(), n_nu, reference);
  bool touched_ground = false;
  for (int t = 0; t < n_nu; ++t) {
    for (int i = 0; i < layer.sphere.n_theta; ++i) {
      // Slot n_nu is scratch; the others hold each sum bit for bit.
      for (int k = 0; k < n_nu; ++k) {
        const std::size_t s = fast.slot(t, i, k);
        ASSERT_EQ(fast.a_r(s), reference.a_r(s)) << t << " " << i << " " << k;
        ASSERT_EQ(fast.a_m(s), reference.a_m(s)) << t << " " << i << " " << k;
        if (layer.sphere.first) {
          ASSERT_EQ(fast.b_r(s), reference.b_r(s)) << t << " " << i << " " << k;
          ASSERT_EQ(fast.b_m(s), reference.b_m(s)) << t << " " << i << " " << k;
        }
      }
      ASSERT_EQ(fast.range(t, i), reference.range(t, i)) << t << " " << i;
      for (int c = 0; c < layer.sphere.n_e; ++c) {
        const std::size_t w = fast.column(t, i, c);
        ASSERT_EQ(fast.g_r(w), reference.g_r(w)) << t << " " << i << " " << c;
        ASSERT_EQ(fast.g_m(w), reference.g_m(w)) << t << " " << i << " " << c;
        touched_ground = touched_ground || fast.g_r(w) != 0.0;
      }
    }
  }
  if (layer.sphere.r < 6361e3) {
    EXPECT_TRUE(touched_ground);
  }
}

TEST(DensityWeights, VectorPathIsTheOneTexelSumBitForBit) {
  if (!using_avx2_kernels()) GTEST_SKIP() << "no AVX2: only the one-texel path runs";
  std::mt19937 random(7);
  std::uniform_real_distribution<double> cosine(-1.0, 1.0);
  const MiePhase cornette_shanks{0.8, nullptr};
  const double angles[] = {0.0, 30.0, 90.0, 150.0, 180.0};
  const double values[] = {40.0, 1.0, 0.1, 0.05, 0.2};
  const MiePhase tabulated{0.0, std::make_shared<TabulatedPhaseFunction>(angles, values)};
  for (const bool first : {false, true}) {
    for (const int n_nu : {8, 4, 5, 2}) {
      for (const double r : {6360e3 + 10.0, 6361e3, 6380e3, 6419e3}) {
        // The texel grid's edges (the sun at the zenith, the view along the horizon) and random
        // directions.
        std::vector<std::pair<double, double>> views = {{1.0, 1.0}, {0.0, 0.3}, {-1.0, -0.1975}};
        for (int n = 0; n < 6; ++n) views.push_back({cosine(random), cosine(random)});
        for (const auto& [mu, mu_s] : views) {
          const Layer layer(r, mu, mu_s, n_nu, first,
                            first && n_nu == 5 ? tabulated : cornette_shanks);
          expect_same_weights(layer, mu);
        }
      }
    }
  }
}

// The weights are a quadrature of the sphere: each direction gives its phase to the nu slices
// (in two shares summing to it), so a later order's Rayleigh-phase slice weights sum to the
// integral of the phase, 1 (to the quadrature's error), whatever the sun; the directions that
// see the ground give it again to the ground's columns. Every weight is finite, not negative.
TEST(DensityWeights, SumToThePhaseIntegralOfTheSky) {
  const MiePhase mie{0.8, nullptr};
  const Layer layer(6419e3, 0.4, 0.7, 8, false, mie);
  std::vector<double> sx, sy;
  slice_suns(0.4, 0.7, 8, sx, sy);
  DensityWeights weights;
  weights.prepare(8, layer.sphere);
  density_weights(layer.sphere, sx.data(), sy.data(), 8, weights);
  for (int t = 0; t < 8; ++t) {
    double sky = 0.0, ground = 0.0;
    for (int i = 0; i < layer.sphere.n_theta; ++i) {
      for (int k = 0; k < 8; ++k) {
        const double w = weights.a_r(weights.slot(t, i, k));
        ASSERT_TRUE(std::isfinite(w) && w >= 0.0);
        sky += w;
      }
      for (int c = 0; c < layer.sphere.n_e; ++c) ground += weights.g_r(weights.column(t, i, c));
    }
    EXPECT_NEAR(sky, 1.0, 0.01) << t;
    double ground_directions = 0.0;
    for (int i = 0; i < layer.sphere.n_theta; ++i) {
      if (!layer.ground[i]) continue;
      for (int p = 0; p < layer.sphere.n_phi; ++p)
        ground_directions += layer.phase_r[static_cast<std::size_t>(i) * layer.sphere.n_phi + p];
    }
    EXPECT_GT(ground, 0.0) << t;
    EXPECT_NEAR(ground, ground_directions, 1e-12) << t;
  }
}

}  // namespace
}  // namespace clearsky::bruneton
