// The Haber model: grid of the study, checks of every answer (finite, non-negative, symmetric
// about the sun's vertical plane), the sun below the horizon, shared per-sun states, and its
// single scattering against a direct integration. Unit tests use a coarse grid (24 sectors)
// except where the study's grid is cheap (grid construction, single scattering only).
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <thread>
#include <vector>

#include "models/core/numeric.h"
#include "models/haber/haber.h"
#include "models/registry.h"
#include "tests/models/haber/haber_reference.h"

namespace clearsky::haber {
namespace {

ModelConfig coarse_config(int orders = 4) {
  ModelConfig config;
  config.options["azimuth_sectors"] = 24;
  config.options["scattering_orders"] = orders;
  return config;
}

std::vector<ViewDirection> sky_directions() {
  std::vector<ViewDirection> views;
  for (double zenith : {0.0, 10.0, 33.0, 56.0, 78.0, 89.0, 90.0}) {
    for (double azimuth = 0.0; azimuth < 360.0; azimuth += 22.5) {
      views.push_back({degrees_to_radians(zenith), degrees_to_radians(azimuth)});
    }
  }
  return views;
}

TEST(HaberModel, GridOfTheStudy) {
  const auto model = HaberModel::create(ModelConfig{});
  EXPECT_EQ(model->grid().ring_count(), 20);
  EXPECT_EQ(model->grid().shell_count(), 128);
  EXPECT_EQ(model->grid().cell_count(), 65268u);  // the paper's count
  EXPECT_NEAR(
      std::pow(model->grid().ring_cells()[1].radius_m / model->grid().ring_cells()[0].radius_m,
               1.0),
      1.09125, 5e-5);
  const ModelFactory* factory = find_model("haber");
  ASSERT_NE(factory, nullptr);
  EXPECT_TRUE(factory->descriptor->capabilities.per_sun_precomputation);
  EXPECT_GT(factory->descriptor->capabilities.max_sun_zenith_deg, 90.0);
}

TEST(HaberModel, RadianceIsFiniteNonNegativeAndSymmetricAboutTheSunPlane) {
  const auto model = HaberModel::create(coarse_config());
  const SunPosition sun{degrees_to_radians(40.0), degrees_to_radians(130.0)};
  const auto state = model->prepare_sun(sun);
  const auto views = sky_directions();
  SpectralBatch out;
  model->sky_radiance(*state, Viewpoint{}, views, out);
  std::vector<ViewDirection> mirrored;
  for (const auto& v : views)
    mirrored.push_back({v.zenith_rad, 2.0 * sun.azimuth_rad - v.azimuth_rad});
  SpectralBatch mirrored_out;
  model->sky_radiance(*state, Viewpoint{}, mirrored, mirrored_out);
  for (std::size_t i = 0; i < views.size(); ++i) {
    ASSERT_EQ(out.status[i], SampleStatus::ok) << i;
    ASSERT_EQ(mirrored_out.status[i], SampleStatus::ok) << i;
    const auto l = out.spectrum(i);
    const auto m = mirrored_out.spectrum(i);
    for (std::size_t w = 0; w < l.size(); ++w) {
      EXPECT_TRUE(std::isfinite(l[w]) && l[w] >= 0.0);
      EXPECT_NEAR(l[w], m[w], 1e-12 + 1e-9 * l[w]);
    }
    EXPECT_GT(l[12], 1e-3);  // blue-green sky in daylight, W/(m2.sr.nm)
  }
  const SpectralSample sun_light = model->sun_irradiance(*state, Viewpoint{});
  ASSERT_EQ(sun_light.status, SampleStatus::ok);
  EXPECT_GT(sun_light.value[12], 0.5 * model->atmosphere().solar_irradiance_w_m2_nm[12]);
  EXPECT_LT(sun_light.value[12], model->atmosphere().solar_irradiance_w_m2_nm[12]);
}

TEST(HaberModel, SunBelowTheHorizonGivesATwilightSkyAndNoDirectSun) {
  const auto model = HaberModel::create(coarse_config(2));
  const auto views = sky_directions();
  double previous = std::numeric_limits<double>::infinity();
  // Up to 95 degrees part of the 35 km atmosphere within the grid is still lit; at 108
  // degrees the Earth's shadow covers all of it and the sky is exactly dark.
  for (double zenith : {85.0, 92.0, 95.0, 108.0}) {
    const auto state = model->prepare_sun({degrees_to_radians(zenith), 0.0});
    SpectralBatch out;
    model->sky_radiance(*state, Viewpoint{}, views, out);
    double total = 0.0;
    for (std::size_t i = 0; i < views.size(); ++i) {
      ASSERT_EQ(out.status[i], SampleStatus::ok) << zenith;
      for (double v : out.spectrum(i)) {
        ASSERT_TRUE(std::isfinite(v) && v >= 0.0);
        total += v;
      }
    }
    if (zenith < 100.0) {
      EXPECT_GT(total, 0.0) << zenith;
      EXPECT_LT(total, previous) << zenith;  // darker as the sun goes down
    } else {
      EXPECT_EQ(total, 0.0) << zenith;
    }
    previous = total;
    if (zenith > 90.0) {
      const SpectralSample direct = model->sun_irradiance(*state, Viewpoint{});
      ASSERT_EQ(direct.status, SampleStatus::ok);
      for (double v : direct.value) EXPECT_EQ(v, 0.0);
    }
  }
}

TEST(HaberModel, RefusesViewsItCannotAnswer) {
  const auto model = HaberModel::create(coarse_config(1));
  const auto state = model->prepare_sun({0.5, 0.0});
  const std::vector<ViewDirection> views{{degrees_to_radians(120.0), 0.0}};
  SpectralBatch out;
  model->sky_radiance(*state, Viewpoint{}, views, out);
  EXPECT_EQ(out.status[0], SampleStatus::view_below_horizon_unsupported);
  model->sky_radiance(*state, Viewpoint{1000.0}, std::vector<ViewDirection>{{0.1, 0.0}}, out);
  EXPECT_EQ(out.status[0], SampleStatus::viewpoint_unsupported);
}

TEST(HaberModel, ConcurrentRequestsForOneSunBucketBuildOneState) {
  ModelConfig config = coarse_config();
  config.options["sun_zenith_bucket_deg"] = 1.0;
  const auto model = HaberModel::create(config);
  constexpr int kThreads = 6;
  std::vector<std::shared_ptr<const SunState>> states(kThreads);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    // Different suns of the same 1-degree bucket (29.6 .. 30.1 degrees), different azimuths.
    threads.emplace_back([&, t] {
      states[t] =
          model->prepare_sun({degrees_to_radians(29.6 + 0.1 * t), degrees_to_radians(10.0 * t)});
    });
  }
  for (auto& thread : threads) thread.join();
  EXPECT_EQ(model->cache_stats().builds, 1u);
  const auto& first = dynamic_cast<const HaberSunState&>(*states[0]);
  for (const auto& s : states) {
    const auto& state = dynamic_cast<const HaberSunState&>(*s);
    EXPECT_EQ(&state.dome(), &first.dome());
    EXPECT_DOUBLE_EQ(state.dome_sun_zenith_rad(), degrees_to_radians(30.0));
  }
  EXPECT_DOUBLE_EQ(states[3]->sun().azimuth_rad,
                   degrees_to_radians(30.0));  // the exact sun is kept
  model->prepare_sun({degrees_to_radians(31.0), 0.0});
  EXPECT_EQ(model->cache_stats().builds, 2u);
}

// The per-sun domes are bounded in bytes by the build's context (serve --sun-state-memory): with
// room for one dome, a second bucket drops the first, and the byte count is that of one dome.
TEST(HaberModel, PerSunDomesAreBoundedInBytesByTheContext) {
  ModelConfig config = coarse_config();
  config.options["sun_zenith_bucket_deg"] = 1.0;
  PrecomputeContext context;
  context.sun_state_memory_bytes = 1;
  const auto model = HaberModel::create(config, context);
  const auto first = model->prepare_sun({degrees_to_radians(30.0), 0.0});
  const std::size_t dome_bytes = dynamic_cast<const HaberSunState&>(*first).dome().memory_bytes();
  EXPECT_EQ(model->cache_stats().bytes, dome_bytes);
  model->prepare_sun({degrees_to_radians(40.0), 0.0});
  EXPECT_EQ(model->cache_stats().evictions, 1u);
  EXPECT_EQ(model->cache_stats().bytes, dome_bytes);    // same grid: domes of one size
  model->prepare_sun({degrees_to_radians(30.0), 0.0});  // dropped: built again
  EXPECT_EQ(model->cache_stats().builds, 3u);
}

// Single scattering of the dome (one order, the study's grid) against direct integration along
// the view ray at dome nodes: the grid sums one sample per shell with the transmittance at the
// cell centre. Measured differences at 360, 501 and 712.5 nm: within 3% everywhere except
// near the horizon (ring 17, 87.5 degrees), within 6% there.
TEST(HaberModel, SingleScatteringMatchesDirectIntegration) {
  ModelConfig config;
  config.options["scattering_orders"] = 1;
  const auto model = HaberModel::create(config);
  const double sun_zenith = degrees_to_radians(40.0);
  const auto state = model->prepare_sun({sun_zenith, 0.0});
  const auto& dome = dynamic_cast<const HaberSunState&>(*state).dome();
  const testing::ScatteringReference reference(model->grid().layers(), model->atmosphere(),
                                               sun_zenith);
  const double step = model->grid().angular_step_rad();
  const Vec3 viewer{0.0, 0.0, model->grid().layers().earth_radius_m()};
  for (int ring : {0, 5, 9, 13, 17}) {
    for (int sector : {0, 8, 20, 35}) {
      const double theta = (ring + 0.5) * step;
      const double phi = (sector + 0.5) * step;
      const Vec3 direction{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                           std::cos(theta)};
      for (std::size_t w : {0u, 12u, 30u}) {
        const double expected = reference.single(viewer, direction, w);
        const double tolerance = (ring == 17 ? 0.06 : 0.03) * expected;
        EXPECT_NEAR(dome.node(ring, sector)[w], expected, tolerance)
            << "ring " << ring << " sector " << sector << " w " << w;
      }
    }
  }
}

}  // namespace
}  // namespace clearsky::haber
