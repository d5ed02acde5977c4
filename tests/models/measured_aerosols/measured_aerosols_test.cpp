// measured_aerosols (models/measured_aerosols): the tabulated and spectral phase functions, the
// optics taken from the AERONET inversion, and the model against Bruneton when it is given
// Bruneton's own aerosols in tabulated form.
#include "models/measured_aerosols/measured_aerosols.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "models/atmosphere/phase_functions.h"
#include "models/atmosphere/spectral_phase_function.h"
#include "models/atmosphere/tabulated_phase_function.h"
#include "models/core/content_hash.h"
#include "models/core/invalid_input.h"
#include "models/measured_aerosols/measured_aerosol_optics.h"
#include "tests/models/bruneton/bruneton_test_support.h"

namespace clearsky {
namespace {

// Integral over the sphere of a phase function of mu, midpoint rule in theta.
template <typename F>
double sphere_integral(const F& phase) {
  constexpr int kCells = 20000;
  double sum = 0.0;
  for (int c = 0; c < kCells; ++c) {
    const double theta = (c + 0.5) * kPi / kCells;
    sum += phase(std::cos(theta)) * std::sin(theta) * kPi / kCells;
  }
  return 2.0 * kPi * sum;
}

TabulatedPhaseFunction cornette_shanks_table(double g, int angles) {
  std::vector<double> a, v;
  for (int i = 0; i < angles; ++i) {
    a.push_back(180.0 * i / (angles - 1));
    v.push_back(cornette_shanks_phase(std::cos(a.back() * kDegree), g));
  }
  return TabulatedPhaseFunction(a, v);
}

TEST(TabulatedPhaseFunction, NormalisedAndFollowsTheTable) {
  const aeronet::PhaseFunctionFile& file = default_aerosol_inversion();
  for (std::size_t w = 0; w < file.wavelengths_nm.size(); ++w) {
    const TabulatedPhaseFunction p(file.angles_deg, file.retrievals[0].phase[w]);
    EXPECT_NEAR(sphere_integral(p), 1.0, 2e-3) << file.wavelengths_nm[w];
    EXPECT_GT(p.asymmetry(), 0.55);
    EXPECT_LT(p.asymmetry(), 0.7);
    // AERONET's values over 4 pi, to the normalisation's ~0.5%, at the tabulated angles.
    for (std::size_t a = 0; a < file.angles_deg.size(); a += 10)
      EXPECT_NEAR(
          p(std::cos(file.angles_deg[a] * kDegree)) * 4.0 * kPi / file.retrievals[0].phase[w][a],
          1.0, 0.02)
          << file.angles_deg[a];
  }
  // A constant is isotropic; a finely tabulated Cornette-Shanks is Cornette-Shanks.
  const TabulatedPhaseFunction flat(std::vector<double>{0.0, 90.0, 180.0},
                                    std::vector<double>{2.0, 2.0, 2.0});
  EXPECT_NEAR(flat(0.3), isotropic_phase(), 1e-9);
  const TabulatedPhaseFunction cs = cornette_shanks_table(0.7, 721);
  for (double mu : {-1.0, -0.5, 0.0, 0.5, 0.9, 0.99})
    EXPECT_NEAR(cs(mu) / cornette_shanks_phase(mu, 0.7), 1.0, 0.01) << mu;
  EXPECT_THROW(TabulatedPhaseFunction(std::vector<double>{0.0, 170.0}, std::vector<double>{1, 1}),
               InvalidInput);
  EXPECT_THROW(TabulatedPhaseFunction(std::vector<double>{0.0, 180.0}, std::vector<double>{1, -1}),
               InvalidInput);
}

TEST(SpectralPhaseFunction, InterpolatesBetweenAndHoldsBeyondTheKnownWavelengths) {
  const TabulatedPhaseFunction a = cornette_shanks_table(0.5, 181);
  const TabulatedPhaseFunction b = cornette_shanks_table(0.8, 181);
  const SpectralPhaseFunction s({442.0, 674.0}, {a, b},
                                WavelengthGrid::points({360.0, 442.0, 558.0, 674.0, 800.0}));
  float out[5];
  for (double mu : {-0.9, 0.0, 0.7, 0.95}) {
    s.evaluate(mu, out);
    EXPECT_FLOAT_EQ(out[0], static_cast<float>(a(mu)));
    EXPECT_FLOAT_EQ(out[1], static_cast<float>(a(mu)));
    EXPECT_FLOAT_EQ(out[2], static_cast<float>(0.5 * (a(mu) + b(mu))));
    EXPECT_FLOAT_EQ(out[3], static_cast<float>(b(mu)));
    EXPECT_FLOAT_EQ(out[4], static_cast<float>(b(mu)));
    EXPECT_NEAR(s.at(mu, 2), 0.5 * (a(mu) + b(mu)), 1e-12);
  }
  EXPECT_NEAR(sphere_integral(s.at_wavelength(558.0)), 1.0, 2e-3);
  EXPECT_NEAR(s.at_wavelength(558.0)(0.5), 0.5 * (a(0.5) + b(0.5)), 2e-3 * a(0.5));
}

TEST(MeasuredAerosolOptics, RetrievalSelectionAndOpticalDepth) {
  const aeronet::PhaseFunctionFile& file = default_aerosol_inversion();
  EXPECT_EQ(select_retrieval(file, -1.0), 5u);  // the mean
  EXPECT_EQ(select_retrieval(file, 0.0), 0u);
  EXPECT_EQ(select_retrieval(file, 12.0), 1u);  // 11:46
  EXPECT_EQ(select_retrieval(file, 13.0), 2u);  // 12:46 (13:19 is 5 min further)
  EXPECT_EQ(select_retrieval(file, 13.1), 3u);  // 13:19
  EXPECT_EQ(select_retrieval(file, 17.5), 4u);  // after the last: the last
  const aeronet::PhaseFunctionRetrieval mean = selected_retrieval(file, 5);
  double aod = 0.0;
  for (const auto& r : file.retrievals) aod += r.aod_440 / 5.0;
  EXPECT_NEAR(mean.aod_440, aod, 1e-15);

  const WavelengthGrid grid = WavelengthGrid::points({440.0, 550.0, 870.0});
  AtmosphereParameters p;
  p.mie_single_scattering_albedo = 0.9;
  const AtmosphereSpectra atmosphere = AtmosphereSpectra::build(p, grid);
  const AerosolOptics optics = measured_aerosol_optics(file, 11.3, 2.0, atmosphere);
  const aeronet::PhaseFunctionRetrieval& r = file.retrievals[0];
  EXPECT_NEAR(optics.mie_extinction_per_m[0] * p.mie_scale_height_m, 2.0 * r.aod_440, 1e-12);
  EXPECT_NEAR(optics.mie_extinction_per_m[2] / optics.mie_extinction_per_m[0],
              std::pow(870.0 / 440.0, -r.angstrom_440_870), 1e-12);
  EXPECT_NEAR(optics.mie_scattering_per_m[1], 0.9 * optics.mie_extinction_per_m[1], 1e-18);
  // The key names the inversion, the retrieval and the scale; times of one retrieval share it.
  EXPECT_EQ(optics.description, measured_aerosol_optics(file, 11.0, 2.0, atmosphere).description);
  EXPECT_NE(optics.description, measured_aerosol_optics(file, 14.0, 2.0, atmosphere).description);
  EXPECT_NE(optics.description, measured_aerosol_optics(file, 11.3, 1.0, atmosphere).description);
  EXPECT_NE(optics.description, measured_aerosol_optics(file, -1.0, 2.0, atmosphere).description);
  EXPECT_NE(optics.description.find(hex64(file.content_hash)), std::string::npos);
}

// Bruneton's own aerosols (Angstrom extinction, Cornette-Shanks g = 0.7) handed to the engine
// as measured optics give Bruneton's sky: the tabulation (1-degree steps) changes the radiance by
// well under 1%.
TEST(MeasuredAerosols, BrunetonsAerosolsAsOpticsGiveBrunetonsSky) {
  const ModelConfig config = testing::small_bruneton_config();
  const auto bruneton = BrunetonModel::create(bruneton_descriptor(), config, {});
  const AtmosphereSpectra& atmosphere = bruneton->atmosphere();
  AerosolOptics optics;
  optics.mie_extinction_per_m = atmosphere.mie_extinction_per_m;
  optics.mie_scattering_per_m = atmosphere.mie_scattering_per_m;
  const TabulatedPhaseFunction cs = cornette_shanks_table(0.7, 181);
  optics.precomputation_phase = std::make_shared<const TabulatedPhaseFunction>(cs);
  optics.phase = std::make_shared<const SpectralPhaseFunction>(
      std::vector<double>{500.0}, std::vector<TabulatedPhaseFunction>{cs}, config.wavelengths);
  optics.description = "test-optics";
  optics.cache_prefix = "test";
  const auto tabulated = BrunetonModel::build_with_aerosols(
      validated_config(bruneton_descriptor(), config), {}, optics);
  const SunPosition sun{.zenith_rad = 40.0 * kDegree, .azimuth_rad = 0.0};
  const auto state_a = bruneton->prepare_sun(sun);
  const auto state_b = tabulated->prepare_sun(sun);
  std::vector<ViewDirection> views;
  for (double z : {0.0, 30.0, 60.0, 85.0})
    for (double a : {0.0, 20.0, 90.0, 180.0})
      views.push_back({.zenith_rad = z * kDegree, .azimuth_rad = a * kDegree});
  SpectralBatch ra, rb;
  bruneton->sky_radiance(*state_a, Viewpoint{}, views, ra);
  tabulated->sky_radiance(*state_b, Viewpoint{}, views, rb);
  for (std::size_t i = 0; i < views.size(); ++i)
    for (std::size_t w = 0; w < 3; ++w)
      EXPECT_NEAR(rb.spectrum(i)[w] / ra.spectrum(i)[w], 1.0, 0.01) << i << " " << w;
}

TEST(MeasuredAerosols, UsesTheInversionAndCachesByIt) {
  testing::MemoryTableCache cache;
  PrecomputeContext context;
  context.cache = &cache;
  // Counted by key: Bruneton's tables may come from the process's shared copy (another test of
  // this binary built them), in which case they are not stored again.
  const auto measured_blobs = [&] {
    return std::count_if(cache.blobs.begin(), cache.blobs.end(), [](const auto& blob) {
      return blob.first.rfind("measured_aerosols-", 0) == 0;
    });
  };
  ModelConfig config = testing::small_bruneton_config();
  config.options["retrieval_time_utc_h"] = 14.0;
  const auto model = measured_aerosols_factory().create(config, context);
  ASSERT_EQ(measured_blobs(), 1);
  // Bruneton's tables are not the measured aerosols' (a blob of its own, or its shared copy).
  const auto bruneton = bruneton_factory().create(testing::small_bruneton_config(), context);
  EXPECT_EQ(measured_blobs(), 1);
  // A twentieth of the optical depth: hardly any aureole.
  config.options["aod_scale"] = 0.05;
  const auto thin = measured_aerosols_factory().create(config, context);
  EXPECT_EQ(measured_blobs(), 2);
  const SunPosition sun{.zenith_rad = 30.0 * kDegree, .azimuth_rad = 0.0};
  const std::vector<ViewDirection> near_sun{{.zenith_rad = 35.0 * kDegree, .azimuth_rad = 0.0}};
  auto radiance = [&](const SkyModel& m) {
    SpectralBatch out;
    m.sky_radiance(*m.prepare_sun(sun), Viewpoint{}, near_sun, out);
    return out.spectrum(0)[0];
  };
  const double full = radiance(*model);
  const double less = radiance(*thin);
  EXPECT_GT(full, 1.5 * less);  // the aureole is the aerosols'
  // Loaded back from the cache: the same numbers.
  config.options["aod_scale"] = 1.0;
  const auto again = measured_aerosols_factory().create(config, context);
  EXPECT_EQ(measured_blobs(), 2);
  EXPECT_EQ(radiance(*again), full);
  (void)bruneton;
}

}  // namespace
}  // namespace clearsky
