// Nishita96: sampling directions, the nearest-direction phase binning (regression test of the
// study's indexing bug), per-sun tables, finite non-negative symmetric radiance, the sun below
// the horizon, single flight, and the single-scattering term against the reference
// integrator. Unit tests use small tables (9 nodes) except where the paper's are cheap.
#include "models/nishita96/nishita96.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <thread>
#include <vector>

#include "models/core/numeric.h"
#include "models/core/single_scattering_reference.h"
#include "models/registry.h"

namespace clearsky {
namespace {

using nishita96::kSamplingDirections;

std::shared_ptr<const Nishita96Model> make_model(int nodes = 9, double bucket_deg = 0.0) {
  ModelConfig config;
  config.options["table_nodes"] = nodes;
  config.options["sun_zenith_bucket_deg"] = bucket_deg;
  return std::dynamic_pointer_cast<const Nishita96Model>(nishita96_factory().create(config, {}));
}

std::array<Vec3, kSamplingDirections> directions_for(double sun_zenith_rad) {
  std::array<Vec3, kSamplingDirections> d;
  const auto angles = nishita96::sampling_angles_rad(sun_zenith_rad);
  for (int k = 0; k < kSamplingDirections; ++k) d[k] = nishita96::direction_of_angle(angles[k]);
  return d;
}

TEST(Nishita96Functions, SamplingDirectionsAreTheStudysEight) {
  const auto d = directions_for(degrees_to_radians(30.0));
  EXPECT_NEAR(d[0].z, 1.0, 1e-15);                                 // zenith
  EXPECT_NEAR(d[1].z, -1.0, 1e-15);                                // nadir
  EXPECT_NEAR(d[2].x, 1.0, 1e-15);                                 // horizontal towards the sun
  EXPECT_NEAR(d[3].x, -1.0, 1e-15);                                // and away
  EXPECT_NEAR(d[4].z, std::cos(degrees_to_radians(30.0)), 1e-15);  // sun
  EXPECT_NEAR(dot(d[5], d[4]), -1.0, 1e-15);                       // anti-sun
  EXPECT_NEAR(dot(d[6], d[4]), 0.0, 1e-15);                        // orthogonal to the sun
  EXPECT_NEAR(dot(d[7], d[4]), 0.0, 1e-15);
  for (const Vec3& v : d) EXPECT_EQ(v.y, 0.0);  // all in the sun's vertical plane
}

TEST(Nishita96Functions, BinnedPhaseIntegralsSumToOne) {
  const auto d = directions_for(degrees_to_radians(40.0));
  for (const Vec3& view :
       {Vec3{0, 0, 1}, normalize(Vec3{0.3, 0.5, 0.8}), normalize(Vec3{-1, 0.2, 0.1})}) {
    const auto p = nishita96::binned_phase_integrals(view, d, 0.7);
    EXPECT_NEAR(std::accumulate(p.rayleigh.begin(), p.rayleigh.end(), 0.0), 1.0, 2e-3);
    EXPECT_NEAR(std::accumulate(p.mie.begin(), p.mie.end(), 0.0), 1.0, 2e-2);
  }
}

// Regression test (2016 study's code): the nearest-direction search compared each candidate
// against sampling direction [theta index] instead of [candidate], which credited all the
// phase mass to the zenith and nadir tables. Looking at the sun, the forward Mie peak must
// land on the sun's table, and each bin gets a share.
TEST(Nishita96Functions, PhaseMassGoesToTheNearestSamplingDirection) {
  const double sun_zenith = degrees_to_radians(40.0);
  const auto d = directions_for(sun_zenith);
  const auto p = nishita96::binned_phase_integrals(d[4], d, 0.7);
  EXPECT_GT(p.mie[4], 0.5);
  for (int k = 0; k < kSamplingDirections; ++k) EXPECT_GT(p.rayleigh[k], 0.01) << k;
  EXPECT_LT(p.rayleigh[0] + p.rayleigh[1], 0.5);
}

TEST(Nishita96Tables, PaperGridIs33CubedPerDirectionAndFitsIn24MB) {
  const auto model = make_model(33);
  const auto state = model->prepare_sun({degrees_to_radians(30.0), 0.0});
  EXPECT_LT(state->memory_bytes(), 24u * 1000u * 1000u);
  const auto& tables = dynamic_cast<const Nishita96SunState&>(*state).tables();
  const auto& zenith = tables.table(0);
  // Box corners: +-875.7 km and 0..60 km; the zenith table's axis runs down from the top.
  const Vec3 corner = zenith.node_position(0, 0, 0);
  EXPECT_NEAR(corner.x, -875.67e3, 10.0);
  EXPECT_NEAR(corner.y, -875.67e3, 10.0);
  EXPECT_NEAR(corner.z - 6360e3, 60e3, 1e-6);
  EXPECT_NEAR(zenith.node_position(16, 16, 32).z, 6360e3, 1e-6);
  // Node lookups reproduce the stored values.
  std::vector<float> value(model->wavelengths().size());
  zenith.lookup(zenith.node_position(16, 20, 30), value);
  for (std::size_t w = 0; w < value.size(); ++w)
    EXPECT_NEAR(value[w], zenith.node(16, 20, 30)[w], 1e-6 * value[w] + 1e-12);
  // Looking up at the ground, under the sun: light scattered in the whole column.
  zenith.lookup({0.0, 0.0, 6360e3}, value);
  EXPECT_GT(value[0], 1e-3);
}

TEST(Nishita96Model, RadianceIsFiniteNonNegativeAndSymmetricAboutTheSunPlane) {
  const auto model = make_model();
  for (double sun_zenith : {0.0, 35.0, 80.0, 90.0, 96.0}) {
    const SunPosition sun{degrees_to_radians(sun_zenith), degrees_to_radians(123.0)};
    std::vector<ViewDirection> views;
    for (double zenith : {0.0, 5.0, 45.0, 85.0, 90.0}) {
      for (double offset : {0.0, 10.0, 70.0, 135.0, 180.0}) {
        views.push_back({degrees_to_radians(zenith), sun.azimuth_rad + degrees_to_radians(offset)});
        views.push_back({degrees_to_radians(zenith), sun.azimuth_rad - degrees_to_radians(offset)});
      }
    }
    SpectralBatch out;
    model->sky_radiance(*model->prepare_sun(sun), Viewpoint{}, views, out);
    for (std::size_t i = 0; i < views.size(); i += 2) {
      ASSERT_EQ(out.status[i], SampleStatus::ok) << sun_zenith;
      ASSERT_EQ(out.status[i + 1], SampleStatus::ok) << sun_zenith;
      for (std::size_t w = 0; w < out.wavelength_count; ++w) {
        const double a = out.spectrum(i)[w], b = out.spectrum(i + 1)[w];
        ASSERT_TRUE(is_finite_non_negative(a));
        EXPECT_NEAR(a, b, 1e-9 * a + 1e-15) << sun_zenith << " view " << i;
      }
      if (sun_zenith < 90.0) {
        EXPECT_GT(out.spectrum(i)[12], 1e-3);
      }
    }
  }
}

TEST(Nishita96Model, RefusesViewsBelowTheHorizonAndFromSpace) {
  const auto model = make_model();
  const auto state = model->prepare_sun({0.5, 0.0});
  SpectralBatch out;
  model->sky_radiance(*state, Viewpoint{},
                      std::vector<ViewDirection>{{degrees_to_radians(100.0), 0.0}}, out);
  EXPECT_EQ(out.status[0], SampleStatus::view_below_horizon_unsupported);
  model->sky_radiance(*state, Viewpoint{100e3}, std::vector<ViewDirection>{{0.1, 0.0}}, out);
  EXPECT_EQ(out.status[0], SampleStatus::viewpoint_unsupported);
  EXPECT_TRUE(nishita96_descriptor().capabilities.per_sun_precomputation);
  ASSERT_NE(find_model("nishita96"), nullptr);
}

TEST(Nishita96Model, ConcurrentRequestsForOneSunBucketBuildOneTableSet) {
  const auto model = make_model(9, 0.5);
  std::vector<std::shared_ptr<const SunState>> states(6);
  std::vector<std::thread> threads;
  for (int t = 0; t < 6; ++t) {
    threads.emplace_back([&, t] {
      states[t] = model->prepare_sun({degrees_to_radians(44.8 + 0.05 * t), 0.1 * t});
    });
  }
  for (auto& thread : threads) thread.join();
  EXPECT_EQ(model->cache_stats().builds, 1u);
  for (const auto& s : states) {
    EXPECT_EQ(&dynamic_cast<const Nishita96SunState&>(*s).tables(),
              &dynamic_cast<const Nishita96SunState&>(*states[0]).tables());
  }
}

// The single-scattering term (Nishita93's, reused) against the double-precision reference
// integrator, without the study's zero sample at the observer. Measured: within 1.5%.
TEST(Nishita96Model, SingleScatteringTermMatchesTheReferenceIntegrator) {
  ModelConfig config;
  config.options["table_nodes"] = 5;
  config.options["study_viewer_sample"] = 0;
  const auto model =
      std::dynamic_pointer_cast<const Nishita96Model>(nishita96_factory().create(config, {}));
  const SunPosition sun{degrees_to_radians(40.0), 0.0};
  const auto state = model->prepare_sun(sun);
  const auto& n96 = dynamic_cast<const Nishita96SunState&>(*state);
  std::vector<double> single(model->wavelengths().size());
  for (double zenith : {0.0, 30.0, 60.0, 85.0}) {
    for (double azimuth : {0.0, 90.0, 180.0}) {
      const ViewDirection view{degrees_to_radians(zenith), degrees_to_radians(azimuth)};
      model->radiance_orders(n96, Viewpoint{}, view, Nishita96Orders::single_only, single);
      const ScatteringAlongRay reference = single_scattering_reference(
          model->atmosphere(), RaySunGeometry::from(6360e3, Viewpoint{}, view, sun));
      for (std::size_t w : {0u, 12u, 30u}) {
        EXPECT_NEAR(single[w], reference.radiance[w], 0.015 * reference.radiance[w])
            << zenith << " " << azimuth;
      }
    }
  }
}

}  // namespace
}  // namespace clearsky

namespace clearsky {
namespace {

TEST(Nishita96Functions, PhaseBinsOfTheSunEqualTheDirectBinning) {
  const auto d = directions_for(degrees_to_radians(33.0));
  const nishita96::PhaseBins bins(d, 32);
  for (const Vec3& view :
       {Vec3{0, 0, 1}, normalize(Vec3{0.3, -0.5, 0.8}), normalize(Vec3{-1, 0.2, 0.05})}) {
    const auto direct = nishita96::binned_phase_integrals(view, d, 0.7);
    const auto fast = bins.integrate(view, 0.7);
    for (int k = 0; k < kSamplingDirections; ++k) {
      EXPECT_NEAR(fast.rayleigh[k], direct.rayleigh[k], 1e-12);
      EXPECT_NEAR(fast.mie[k], direct.mie[k], 1e-12);
    }
  }
}

}  // namespace
}  // namespace clearsky
