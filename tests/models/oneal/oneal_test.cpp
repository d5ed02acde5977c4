// O'Neal: Schuler's Chapman approximation against the exact optical lengths, the Chapman
// identity below the horizontal, physical properties everywhere, convergence with the number
// of samples, views from space, aerial perspective.
#include "models/oneal/oneal.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "models/core/optical_depth.h"
#include "models/core/single_scattering_reference.h"
#include "models/oneal/oneal_functions.h"
#include "models/registry.h"
#include "tests/models/support/sky_properties.h"
#include "tests/support/sanitizers.h"

namespace clearsky {
namespace {

using testing::radiance_of;
using testing::sun_at_degrees;
using testing::view_at_degrees;

constexpr double kR = 6360e3;

std::shared_ptr<const SkyModel> model_with(int samples) {
  ModelConfig config;
  config.options["samples"] = samples;
  return ONealModel::create(config, {});
}

const SkyModel& paper_model() {
  static const auto model = model_with(4);
  return *model;
}

TEST(ONeal, IsRegisteredWithItsCapabilities) {
  const ModelFactory* factory = find_model("oneal");
  ASSERT_NE(factory, nullptr);
  const ModelCapabilities& c = factory->descriptor->capabilities;
  EXPECT_GT(c.max_altitude_m, 60e3);
  EXPECT_TRUE(c.view_from_space && c.view_below_horizon && c.aerial_perspective);
  EXPECT_EQ(c.max_sun_zenith_deg, 180.0);
  EXPECT_EQ(factory->descriptor->find_parameter("samples")->default_value, 4.0);
  ModelConfig bad;
  bad.options["samples"] = 0;
  EXPECT_THROW(factory->create(bad, {}), std::invalid_argument);
}

TEST(ONealScale, SchulersApproximationIsWithinAFewPercentOfTheExactOpticalLength) {
  // rho * scale(H, mu) against the numerical optical length to the top from the ground: at
  // the zenith H c / (c + 1) is within 4 % (Rayleigh, c = 28) and 2 % (Mie, c = 73) of H;
  // down to mu = 0.35 within 10 % and 5 %, always below; at the horizon H sqrt(R/H) is 20 %
  // below Chapman's grazing value H sqrt(pi R / 2H).
  const AtmosphereSpectra atmosphere = AtmosphereSpectra::build({}, WavelengthGrid::paper_bins());
  for (double mu : {1.0, 0.7, 0.4, 0.35}) {
    const auto exact =
        optical_lengths_to_space(atmosphere, kR, mu, RayQuadratureOptions::reference());
    const auto approximate = oneal::optical_lengths_to_infinity(atmosphere.parameters, kR, mu);
    ASSERT_TRUE(exact && approximate);
    EXPECT_NEAR(approximate->rayleigh_m / exact->rayleigh_m, 1.0, mu == 1.0 ? 0.04 : 0.10) << mu;
    EXPECT_NEAR(approximate->mie_m / exact->mie_m, 1.0, mu == 1.0 ? 0.02 : 0.05) << mu;
    EXPECT_LT(approximate->rayleigh_m, exact->rayleigh_m);
  }
  EXPECT_NEAR(oneal::scale_m(8000.0, kR, 0.0) / (8000.0 * std::sqrt(kPi * kR / (2.0 * 8000.0))),
              std::sqrt(2.0 / kPi), 1e-12);
}

TEST(ONealScale, ChapmanIdentityBelowTheHorizontal) {
  // L(r, -mu) + L(r, mu) = 2 rho(r sqrt(1 - mu^2)) H c: the whole chord through the tangent
  // point; continuous at mu = 0.
  const AtmosphereParameters p;
  const double r = kR + 20e3;
  for (double mu : {0.01, 0.05, 0.07}) {  // the ground hides mu < -0.079 from 20 km
    const auto up = oneal::optical_lengths_to_infinity(p, r, mu);
    const auto down = oneal::optical_lengths_to_infinity(p, r, -mu);
    ASSERT_TRUE(up && down);
    const double tangent_altitude = r * std::sqrt(1.0 - mu * mu) - kR;
    EXPECT_NEAR((up->rayleigh_m + down->rayleigh_m) /
                    (2.0 * std::exp(-tangent_altitude / 8000.0) * oneal::scale_m(8000.0, kR, 0.0)),
                1.0, 1e-12);
  }
  const auto above = oneal::optical_lengths_to_infinity(p, r, 1e-12);
  const auto below = oneal::optical_lengths_to_infinity(p, r, -1e-12);
  EXPECT_NEAR(above->mie_m / below->mie_m, 1.0, 1e-9);
  EXPECT_FALSE(
      oneal::optical_lengths_to_infinity(p, r, -0.2).has_value());  // the ground is in the way
}

TEST(ONeal, FiniteAndNonNegativeEverywhere) {
  testing::expect_finite_non_negative_everywhere(paper_model());
  testing::expect_finite_non_negative_everywhere(*model_with(2));
}

TEST(ONeal, SymmetricAboutTheSunPlane) {
  testing::expect_symmetric_about_the_sun_plane(paper_model(), 0.0);
  testing::expect_symmetric_about_the_sun_plane(paper_model(), 2e6);
}

TEST(ONeal, ContinuousAcrossTheHorizon) {
  testing::expect_continuous_across_the_horizon(*model_with(32), 0.01);
}

TEST(ONeal, ConvergesTowardsTheReferenceWithMoreSamples) {
  CLEARSKY_SKIP_REFINEMENT_UNDER_SANITIZERS();
  // 4 samples miss the dense lowest kilometres (the first is 7.5 km up a zenith view): the
  // radiance is far too low, as the paper reports ("underestimates by a factor of about 3"
  // with respect to the measurements); with many samples only the Chapman approximation's
  // error remains: within 8 % (largest at 360 nm for low views, where the observer-side
  // optical length is a difference of two approximated Chapman values).
  const auto many = model_with(512);
  const SunPosition sun = sun_at_degrees(40.0);
  const std::vector<ViewDirection> views = {view_at_degrees(0.0, 0.0), view_at_degrees(50.0, 180.0),
                                            view_at_degrees(70.0, 20.0)};
  const SpectralBatch few = radiance_of(paper_model(), sun, 0.0, views);
  const SpectralBatch converged = radiance_of(*many, sun, 0.0, views);
  for (std::size_t i = 0; i < views.size(); ++i) {
    const auto ref = single_scattering_reference(paper_model().atmosphere(),
                                                 RaySunGeometry::from(kR, {0.0}, views[i], sun));
    for (std::size_t w = 0; w < ref.radiance.size(); w += 3) {
      EXPECT_LT(few.spectrum(i)[w], ref.radiance[w]) << i << ' ' << w;
      EXPECT_NEAR(converged.spectrum(i)[w] / ref.radiance[w], 1.0, 0.08) << i << ' ' << w;
    }
  }
}

TEST(ONeal, ViewFromSpaceLookingDown) {
  const auto many = model_with(64);
  const double altitude = 1000e3;
  const std::vector<ViewDirection> views = {view_at_degrees(180.0, 0.0), view_at_degrees(0.0, 0.0)};
  const SpectralBatch out = radiance_of(*many, sun_at_degrees(30.0), altitude, views);
  const auto ref = single_scattering_reference(
      many->atmosphere(), RaySunGeometry::from(kR, {altitude}, views[0], sun_at_degrees(30.0)));
  // The air's light (the whole view's aerial perspective); the radiance adds the ground's
  // (tests/models/core/lambertian_ground_test.cpp).
  const AerialPerspectiveSample air =
      many->aerial_perspective(*many->prepare_sun(sun_at_degrees(30.0)), {altitude}, views[0],
                               std::numeric_limits<double>::infinity());
  for (std::size_t w = 0; w < ref.radiance.size(); ++w) {
    EXPECT_NEAR(air.radiance[w] / ref.radiance[w], 1.0, 0.05) << w;
    EXPECT_GT(out.spectrum(0)[w], air.radiance[w]) << w;
    EXPECT_EQ(out.spectrum(1)[w], 0.0);
  }
}

TEST(ONeal, SunBelowTheHorizon) {
  const std::vector<ViewDirection> views = {view_at_degrees(0.0, 0.0)};
  const SpectralBatch day = radiance_of(paper_model(), sun_at_degrees(60.0), 0.0, views);
  const SpectralBatch dusk = radiance_of(paper_model(), sun_at_degrees(100.0), 0.0, views);
  const SpectralBatch night = radiance_of(paper_model(), sun_at_degrees(180.0), 0.0, views);
  for (std::size_t w = 0; w < day.wavelength_count; ++w) {
    EXPECT_LT(dusk.spectrum(0)[w], 0.01 * day.spectrum(0)[w]);
    EXPECT_EQ(night.spectrum(0)[w], 0.0);
  }
  const SpectralSample shadowed =
      paper_model().sun_irradiance(*paper_model().prepare_sun(sun_at_degrees(91.0)), {0.0});
  for (double v : shadowed.value) EXPECT_EQ(v, 0.0);
}

TEST(ONeal, AerialPerspective) {
  const auto model = model_with(32);
  const auto state = model->prepare_sun(sun_at_degrees(50.0));
  // A low view (75 degrees) over 5 km: the observer-side optical length is the difference of
  // two approximated Chapman values of the whole rays, so its relative error is several
  // times that of each (6 % of the optical depth here, 15 % at 85 degrees): within 8 % in
  // radiance and 6 % in transmittance.
  const ViewDirection view = view_at_degrees(75.0, 30.0);
  const AerialPerspectiveSample none = model->aerial_perspective(*state, {0.0}, view, 0.0);
  ASSERT_EQ(none.status, SampleStatus::ok);
  const AerialPerspectiveSample near = model->aerial_perspective(*state, {0.0}, view, 5e3);
  const AerialPerspectiveSample far = model->aerial_perspective(*state, {0.0}, view, 50e3);
  const auto ref = single_scattering_reference(
      model->atmosphere(), RaySunGeometry::from(kR, {0.0}, view, sun_at_degrees(50.0)), 5e3);
  for (std::size_t w = 0; w < near.radiance.size(); ++w) {
    EXPECT_EQ(none.radiance[w], 0.0);
    EXPECT_EQ(none.transmittance[w], 1.0);
    EXPECT_LT(near.radiance[w], far.radiance[w]);
    EXPECT_GT(near.transmittance[w], far.transmittance[w]);
    EXPECT_NEAR(near.radiance[w] / ref.radiance[w], 1.0, 0.08) << w;
    EXPECT_NEAR(near.transmittance[w] / ref.transmittance[w], 1.0, 0.06) << w;
  }
}

}  // namespace
}  // namespace clearsky
