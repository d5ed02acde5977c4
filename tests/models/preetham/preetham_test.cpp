// Physics and contract tests of the Preetham model (models/preetham): the paper's zenith
// luminance, the luminance carried by the reconstructed spectrum, symmetry, positivity at
// the horizon, refusal of what it cannot answer, and the sky irradiance quadrature.
#include "models/preetham/preetham.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "models/colour/colour_spaces.h"
#include "models/core/quadrature.h"
#include "models/registry.h"
#include "tests/models/support/fit_domain_checks.h"
#include "tests/support/model_queries.h"

namespace clearsky {
namespace {

using testing::radiance;
using testing::reference_sky_irradiance;
using testing::reference_tilted_irradiance;
using testing::sun_at;

std::shared_ptr<const SkyModel> make_preetham(double turbidity = 2.53,
                                              WavelengthGrid grid = WavelengthGrid::paper_bins()) {
  ModelConfig config;
  config.atmosphere.turbidity = turbidity;
  config.wavelengths = std::move(grid);
  return preetham_factory().create(config, {});
}

// The model answering 0 where its fit turns negative (fit_domain.h).
std::shared_ptr<const SkyModel> clamped_preetham() {
  ModelConfig config;
  config.options["clamp_negative_fit"] = 1.0;
  return preetham_factory().create(config, {});
}

// A low sun: views near the horizon towards it where the fit turns negative are refused by
// default, answered 0 at those wavelengths on request (tests/models/support/fit_domain_checks.h).
TEST(Preetham, RefusesWhereTheFitTurnsNegativeUnlessAskedToClamp) {
  const auto model = make_preetham();
  const auto clamped = clamped_preetham();
  for (double sun_zenith : {30.0, 60.0, 80.0, 85.0, 88.0, 89.5, 90.0}) {
    const int outside =
        testing::expect_refused_only_where_the_fit_turns_negative(*model, *clamped, sun_zenith);
    if (sun_zenith <= 60.0) {
      EXPECT_EQ(outside, 0) << sun_zenith;
    }
    if (sun_zenith >= 88.0) {
      EXPECT_GT(outside, 0) << sun_zenith;
    }
  }
}

TEST(Preetham, DescriptorDeclaresParametersAndLimits) {
  const ModelDescriptor& d = preetham_descriptor();
  EXPECT_EQ(d.id, "preetham");
  const ParameterSpec* t = d.find_parameter("turbidity");
  ASSERT_NE(t, nullptr);
  EXPECT_TRUE(t->atmosphere);
  EXPECT_DOUBLE_EQ(t->default_value, 2.53);
  EXPECT_DOUBLE_EQ(t->min_value, 2.0);
  EXPECT_DOUBLE_EQ(t->max_value, 10.0);
  EXPECT_EQ(d.capabilities.max_altitude_m, 0.0);
  EXPECT_FALSE(d.capabilities.view_from_space);
  EXPECT_FALSE(d.capabilities.view_below_horizon);
  EXPECT_DOUBLE_EQ(d.capabilities.max_sun_zenith_deg, 90.0);
  ASSERT_NE(find_model("preetham"), nullptr);
  EXPECT_EQ(find_model("preetham")->descriptor, &d);
}

TEST(Preetham, RefusesWhatItCannotAnswer) {
  const auto model = make_preetham();
  EXPECT_EQ(model->check_sun(sun_at(90.5)), SampleStatus::sun_below_horizon_unsupported);
  EXPECT_THROW(model->prepare_sun(sun_at(95.0)), std::invalid_argument);
  const auto sun = model->prepare_sun(sun_at(40.0));
  const std::vector<ViewDirection> views = {{degrees_to_radians(100.0), 0.0},
                                            {degrees_to_radians(30.0), 0.0}};
  SpectralBatch batch;
  model->sky_radiance(*sun, {}, views, batch);
  EXPECT_EQ(batch.status[0], SampleStatus::view_below_horizon_unsupported);
  EXPECT_EQ(batch.status[1], SampleStatus::ok);
  model->sky_radiance(*sun, Viewpoint{1000.0}, views, batch);
  EXPECT_EQ(batch.status[1], SampleStatus::viewpoint_unsupported);
  ModelConfig config;
  config.atmosphere.turbidity = 1.5;
  try {
    preetham_factory().create(config, {});
    FAIL() << "turbidity 1.5 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("turbidity", 0), 0u) << e.what();
  }
}

TEST(Preetham, ZenithLuminanceIsThePapersFormulaInCandelas) {
  // (4.0453 T - 4.9710) tan(chi) - 0.2155 T + 2.4192 kcd/m2, chi = (4/9 - T/120)(pi - 2 theta_s):
  // 8.3286 kcd/m2 for T = 2.53 and the sun at 30 degrees.
  EXPECT_NEAR(preetham::zenith_luminance_kcd_m2(2.53, degrees_to_radians(30.0)), 8.328573912818442,
              1e-12);
  const auto model = make_preetham();
  const auto* preetham = dynamic_cast<const PreethamModel*>(model.get());
  const auto sun = model->prepare_sun(sun_at(30.0));
  const auto zenith = preetham->luminance_chromaticity(*sun, {0.0, 0.0});
  EXPECT_NEAR(zenith.luminance_cd_m2, 8328.573912818442, 1e-8);
  EXPECT_NEAR(zenith.chroma_x, preetham::zenith_chromaticity_x(2.53, degrees_to_radians(30.0)),
              1e-14);
}

TEST(Preetham, SpectrumCarriesTheModelLuminanceOverTheStudysBins) {
  const auto model = make_preetham();
  const auto* preetham = dynamic_cast<const PreethamModel*>(model.get());
  const auto sun = model->prepare_sun(sun_at(40.0));
  for (const auto& [zenith, azimuth] :
       std::vector<std::pair<double, double>>{{0, 0}, {30, 135}, {60, 300}, {77.9, 20}}) {
    const Spectrum l = radiance(*model, *sun, zenith, azimuth);
    const double expected = preetham
                                ->luminance_chromaticity(
                                    *sun, {degrees_to_radians(zenith), degrees_to_radians(azimuth)})
                                .luminance_cd_m2;
    EXPECT_NEAR(spectrum_to_luminance(l, model->wavelengths()) / expected, 1.0, 1e-12)
        << zenith << " " << azimuth;
  }
}

TEST(Preetham, SpectrumOnAnotherGridIsThePointSampledSameSpectrum) {
  const auto bins = make_preetham();
  const auto points = make_preetham(2.53, WavelengthGrid::points({360.0, 501.0, 712.5}));
  const auto sun_bins = bins->prepare_sun(sun_at(35.0));
  const auto sun_points = points->prepare_sun(sun_at(35.0));
  const Spectrum a = radiance(*bins, *sun_bins, 50.0, 200.0);
  const Spectrum b = radiance(*points, *sun_points, 50.0, 200.0);
  EXPECT_NEAR(b[0] / a[0], 1.0, 1e-12);
  EXPECT_NEAR(b[1] / a[12], 1.0, 1e-12);
  EXPECT_NEAR(b[2] / a[30], 1.0, 1e-12);
}

TEST(Preetham, SymmetricAboutTheSunsVerticalPlane) {
  const auto model = make_preetham();
  const double sun_azimuth = 135.0;
  const auto sun = model->prepare_sun(sun_at(50.0, sun_azimuth));
  for (double zenith : {10.0, 45.0, 80.0, 90.0}) {
    for (double delta : {5.0, 60.0, 150.0}) {
      const Spectrum a = radiance(*model, *sun, zenith, sun_azimuth + delta);
      const Spectrum b = radiance(*model, *sun, zenith, sun_azimuth - delta);
      for (std::size_t w = 0; w < a.size(); ++w) EXPECT_NEAR(a[w], b[w], 1e-12 * (1.0 + a[w]));
    }
  }
}

TEST(Preetham, PositiveAndFiniteUpToTheHorizonAndForTheSunAtTheHorizon) {
  for (double turbidity : {2.0, 2.53, 10.0}) {
    const auto model = make_preetham(turbidity);
    for (double sun_zenith : {0.0, 45.0, 85.0, 89.9, 90.0}) {
      const auto sun = model->prepare_sun(sun_at(sun_zenith));
      std::vector<ViewDirection> views;
      for (double z = 0.0; z <= 90.0; z += 7.5)
        for (double a = 0.0; a < 360.0; a += 15.0)
          views.push_back({degrees_to_radians(z), degrees_to_radians(a)});
      views.push_back(sun.get()->sun());  // looking straight at the sun
      SpectralBatch batch;
      model->sky_radiance(*sun, {}, views, batch);
      double largest = 0.0;
      for (std::size_t i = 0; i < views.size(); ++i) {
        if (batch.status[i] == SampleStatus::outside_fit_domain)
          continue;  // RefusesWhere...: low sun, T = 10
        ASSERT_EQ(batch.status[i], SampleStatus::ok)
            << turbidity << " " << sun_zenith << " view " << i;
        for (double v : batch.spectrum(i)) {
          ASSERT_TRUE(std::isfinite(v) && v >= 0.0);
          largest = std::max(largest, v);
        }
      }
      EXPECT_GT(largest, 0.0);
      EXPECT_LT(largest, 10.0) << "W/(m2.sr.nm): no sky is this bright";
      const auto sun_irradiance = model->sun_irradiance(*sun, {});
      EXPECT_EQ(sun_irradiance.status, SampleStatus::ok);
    }
  }
}

TEST(Preetham, TurbidityDimsTheSunAndBrightensTheSky) {
  double previous_sun = 1e9, previous_sky = 0.0, previous_zenith = 0.0;
  for (double t : {2.0, 3.0, 5.0, 8.0, 10.0}) {
    const auto model = make_preetham(t);
    const auto sun = model->prepare_sun(sun_at(30.0));
    const double sun_e = model->sun_irradiance(*sun, {}).value[12];
    const double sky_e = model->sky_irradiance(*sun, {}).value[12];
    const double zenith = radiance(*model, *sun, 0.0, 0.0)[12];
    EXPECT_LT(sun_e, previous_sun) << t;
    EXPECT_GT(sky_e, previous_sky) << t;
    EXPECT_GT(zenith, previous_zenith) << t;
    previous_sun = sun_e;
    previous_sky = sky_e;
    previous_zenith = zenith;
  }
}

TEST(Preetham, SunIrradianceIsTheExtraterrestrialSpectrumTimesATransmittance) {
  const auto model = make_preetham();
  double previous = 1e9;
  for (double zenith : {0.0, 30.0, 60.0, 80.0, 90.0}) {
    const auto sun = model->prepare_sun(sun_at(zenith));
    const SpectralSample e = model->sun_irradiance(*sun, {});
    ASSERT_EQ(e.status, SampleStatus::ok);
    for (std::size_t w = 0; w < e.value.size(); ++w) {
      EXPECT_LE(e.value[w], model->atmosphere().solar_irradiance_w_m2_nm[w]);
      EXPECT_GE(e.value[w], 0.0);
    }
    EXPECT_LT(e.value[12], previous);
    previous = e.value[12];
  }
  // Air mass 1 at the zenith (Kasten): 1 / (1 + 0.15 x 93.885^-1.253) = 0.99971.
  EXPECT_NEAR(preetham::relative_air_mass(0.0), 1.0 / (1.0 + 0.15 * std::pow(93.885, -1.253)),
              1e-12);
  // At 501 nm: Rayleigh, aerosol and ozone (k_o = 3.0 + 0.1 x (4.0 - 3.0) per m between the
  // 500 and 510 nm entries); no mixed-gas or water-vapour absorption there.
  const double m = preetham::relative_air_mass(0.0);
  const double expected = std::exp(-0.008735 * m * std::pow(0.501, -4.08)) *
                          std::exp(-(0.04608 * 2.53 - 0.04586) * m * std::pow(0.501, -1.3)) *
                          std::exp(-m * 0.0035 * 3.1);
  EXPECT_NEAR(preetham::sun_transmittance(2.53, 0.0, 501.0), expected, 1e-12);
}

TEST(Preetham, HorizontalSkyIrradianceIsWithinHalfAPercentOfAFineRule) {
  const auto model = make_preetham();
  for (double zenith : {0.0, 40.0, 85.0, 90.0}) {
    const auto sun = model->prepare_sun(sun_at(zenith));
    const SpectralSample fast = model->sky_irradiance(*sun, {});
    const Spectrum fine = reference_sky_irradiance(*clamped_preetham(), *sun, 100, 200);
    ASSERT_EQ(fast.status, SampleStatus::ok);
    for (std::size_t w = 0; w < fine.size(); ++w) {
      EXPECT_NEAR(fast.value[w] / fine[w], 1.0, 0.005)
          << "sun zenith " << zenith << " wavelength " << w;
    }
  }
}

TEST(Preetham, TiltedPlanesSeeLessSkyAwayFromTheSun) {
  const auto model = make_preetham();
  const auto sun = model->prepare_sun(sun_at(40.0, 180.0));
  const double horizontal = model->sky_irradiance(*sun, {}).value[12];
  const double facing_sun =
      model->sky_irradiance(*sun, {}, {degrees_to_radians(90.0), kPi}).value[12];
  const double facing_away =
      model->sky_irradiance(*sun, {}, {degrees_to_radians(90.0), 0.0}).value[12];
  EXPECT_GT(facing_sun, facing_away);
  EXPECT_LT(facing_away, horizontal);
  EXPECT_GT(facing_away, 0.0);
}

TEST(Preetham, TiltedPlaneSkyIrradianceIsWithinHalfAPercentOfAFineRule) {
  const auto model = make_preetham();
  for (double zenith : {30.0, 85.0}) {
    const auto sun = model->prepare_sun(sun_at(zenith, 180.0));
    for (const auto& [tilt, azimuth] :
         std::vector<std::pair<double, double>>{{30, 180}, {90, 180}, {90, 0}, {150, 0}}) {
      const PlaneOrientation plane{degrees_to_radians(tilt), degrees_to_radians(azimuth)};
      const SpectralSample fast = model->sky_irradiance(*sun, {}, plane);
      const Spectrum fine = reference_tilted_irradiance(*clamped_preetham(), *sun, plane);
      ASSERT_EQ(fast.status, SampleStatus::ok);
      for (std::size_t w = 0; w < 31; ++w) {
        EXPECT_NEAR(fast.value[w] / fine[w], 1.0, 0.005)
            << zenith << " " << tilt << " " << azimuth << " " << w;
      }
    }
  }
  // A plane facing straight down sees no sky.
  const auto sun = model->prepare_sun(sun_at(30.0));
  const SpectralSample down = model->sky_irradiance(*sun, {}, {kPi, 0.0});
  for (double v : down.value) EXPECT_EQ(v, 0.0);
}

}  // namespace
}  // namespace clearsky
