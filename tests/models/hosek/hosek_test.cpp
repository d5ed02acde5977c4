// Physics and contract tests of the Hosek-Wilkie model (models/hosek): the tables and their
// interpolation, the study's rescaling, the solar disc with limb darkening, symmetry,
// positivity at the horizon, the declared spectral range, the native RGB/XYZ versions and
// the sky irradiance quadrature.
#include "models/hosek/hosek.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <thread>
#include <vector>

#include "models/colour/colour_spaces.h"
#include "models/core/quadrature.h"
#include "models/registry.h"
#include "models/spectral/reference_spectra.h"
#include "tests/models/support/fit_domain_checks.h"
#include "tests/support/model_queries.h"

namespace clearsky {
namespace {

using testing::radiance;
using testing::reference_sky_irradiance;
using testing::reference_tilted_irradiance;
using testing::sun_at;

std::shared_ptr<const SkyModel> make_hosek(double turbidity = 2.53,
                                           std::optional<double> albedo = std::nullopt,
                                           double native_bands = 0.0,
                                           WavelengthGrid grid = WavelengthGrid::paper_bins()) {
  ModelConfig config;
  config.atmosphere.turbidity = turbidity;
  config.atmosphere.ground_albedo = albedo;
  config.wavelengths = std::move(grid);
  if (native_bands != 0.0) config.options["native_bands"] = native_bands;
  return hosek_factory().create(config, {});
}

// The model answering 0 where its fit turns negative (fit_domain.h).
std::shared_ptr<const SkyModel> clamped_hosek() {
  ModelConfig config;
  config.options["clamp_negative_fit"] = 1.0;
  return hosek_factory().create(config, {});
}

// A low sun: views near the horizon towards it where the fit turns negative are refused by
// default, answered 0 at those wavelengths on request (tests/models/support/fit_domain_checks.h).
TEST(Hosek, RefusesWhereTheFitTurnsNegativeUnlessAskedToClamp) {
  const auto model = make_hosek();
  const auto clamped = clamped_hosek();
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

// Index of grid wavelength nm in the paper's bins.
std::size_t bin(double nm) { return WavelengthGrid::paper_bins().index_of(nm); }

TEST(Hosek, DescriptorDeclaresParametersRangeAndLimits) {
  const ModelDescriptor& d = hosek_descriptor();
  EXPECT_EQ(d.id, "hosek");
  EXPECT_DOUBLE_EQ(d.min_wavelength_nm, 320.0);
  EXPECT_DOUBLE_EQ(d.max_wavelength_nm, 720.0);
  ASSERT_EQ(d.native_wavelengths_nm.size(), 11u);
  EXPECT_DOUBLE_EQ(d.native_wavelengths_nm[5], 520.0);
  for (const char* name : {"turbidity", "albedo"}) {
    const ParameterSpec* p = d.find_parameter(name);
    ASSERT_NE(p, nullptr) << name;
    EXPECT_TRUE(p->atmosphere) << name;
  }
  EXPECT_DOUBLE_EQ(d.find_parameter("turbidity")->default_value, 2.53);
  EXPECT_FALSE(d.find_parameter("native_bands")->atmosphere);
  EXPECT_EQ(d.capabilities.max_altitude_m, 0.0);
  EXPECT_FALSE(d.capabilities.view_below_horizon);
  EXPECT_DOUBLE_EQ(d.capabilities.max_sun_zenith_deg, 90.0);
  ASSERT_NE(find_model("hosek"), nullptr);
}

TEST(Hosek, TablesAreReadByTheirIndices) {
  const auto& t = hosek::Tables::get();
  // First rows of spectral_sky_coefficients.csv and spectral_sky_radiance_scale.csv.
  EXPECT_DOUBLE_EQ(t.spectral[0].coefficients[0][0][0][0], -13.41049);
  EXPECT_DOUBLE_EQ(t.spectral[0].coefficients[0][0][0][8], 0.8826913);
  EXPECT_DOUBLE_EQ(t.spectral[0].radiance[0][0][1], 0.0003169257);
  EXPECT_DOUBLE_EQ(t.original_solar_radiance[6], 25503.8);
  EXPECT_DOUBLE_EQ(t.limb_darkening[0][1], 0.767174);
  EXPECT_DOUBLE_EQ(t.solar[6][1][44][3], 22345.08);  // 560 nm, turbidity 2, last segment
  EXPECT_DOUBLE_EQ(t.xyz[0].coefficients[0][0][0][0], -1.117001);
  EXPECT_DOUBLE_EQ(t.rgb[0].radiance[0][0][0], 1.962684);
}

TEST(Hosek, CookingPicksControlPointsAndInterpolatesTurbidityAndAlbedo) {
  const auto& channel = hosek::Tables::get().spectral[4];
  // Elevation pi/2 is the last control point, 0 the first; integer turbidity is one knot.
  const auto top = hosek::cook(channel, 3.0, 0.0, 0.5 * kPi);
  const auto bottom = hosek::cook(channel, 3.0, 1.0, 0.0);
  for (int k = 0; k < hosek::kCoefficientCount; ++k) {
    EXPECT_NEAR(top.coefficients[k], channel.coefficients[0][2][5][k], 1e-12);
    EXPECT_NEAR(bottom.coefficients[k], channel.coefficients[1][2][0][k], 1e-12);
  }
  EXPECT_NEAR(top.radiance_scale, channel.radiance[0][2][5], 1e-15);
  const double e = 0.4;
  const auto mid = hosek::cook(channel, 2.25, 0.3, e);
  const auto t2a0 = hosek::cook(channel, 2.0, 0.0, e), t3a0 = hosek::cook(channel, 3.0, 0.0, e);
  const auto t2a1 = hosek::cook(channel, 2.0, 1.0, e), t3a1 = hosek::cook(channel, 3.0, 1.0, e);
  for (int k = 0; k < hosek::kCoefficientCount; ++k) {
    const double expected = 0.7 * (0.75 * t2a0.coefficients[k] + 0.25 * t3a0.coefficients[k]) +
                            0.3 * (0.75 * t2a1.coefficients[k] + 0.25 * t3a1.coefficients[k]);
    EXPECT_NEAR(mid.coefficients[k], expected, 1e-12 * (1.0 + std::abs(expected)));
  }
  // Turbidity 10 is the last knot alone.
  const auto ten = hosek::cook(channel, 10.0, 0.0, 0.5 * kPi);
  EXPECT_NEAR(ten.radiance_scale, channel.radiance[0][9][5], 1e-15);
}

TEST(Hosek, ZenithRadianceIsTheStudysRescaledBandInterpolation) {
  // At 501 nm: bands 480 and 520 with weights 0.475 and 0.525, each cooked with the grass
  // albedo at 501 nm, times solar(501 bin) / (original(501) x 6.87e-5 sr).
  const auto model = make_hosek();
  const auto sun = model->prepare_sun(sun_at(35.0));
  const Spectrum l = radiance(*model, *sun, 0.0, 0.0);
  const auto& t = hosek::Tables::get();
  const double albedo = ReferenceSpectra::get().grass_albedo.at(501.0, OutOfRange::hold_end_values);
  const double elevation = degrees_to_radians(55.0);
  const auto v = hosek::view_terms(1.0, std::cos(degrees_to_radians(35.0)));
  const double raw =
      0.475 * hosek::radiance(hosek::cook(t.spectral[4], 2.53, albedo, elevation), v) +
      0.525 * hosek::radiance(hosek::cook(t.spectral[5], 2.53, albedo, elevation), v);
  const double original =
      0.475 * t.original_solar_radiance[4] + 0.525 * t.original_solar_radiance[5];
  const double solar = model->atmosphere().solar_irradiance_w_m2_nm[bin(501.0)];
  EXPECT_NEAR(l[bin(501.0)], raw * solar / (original * 6.87e-5), 1e-12);
  // A clear-sky zenith at 500 nm is of the order of 0.05..0.2 W/(m2.sr.nm).
  EXPECT_GT(l[bin(501.0)], 0.03);
  EXPECT_LT(l[bin(501.0)], 0.3);
}

TEST(Hosek, WavelengthsOutsideTheFitAreDeclaredNotAnswered) {
  const auto model =
      make_hosek(2.53, std::nullopt, 0.0, WavelengthGrid::points({300.0, 320.0, 720.0, 750.0}));
  EXPECT_FALSE(model->answers_wavelength(0));
  EXPECT_TRUE(model->answers_wavelength(1));
  EXPECT_TRUE(model->answers_wavelength(2));
  EXPECT_FALSE(model->answers_wavelength(3));
  const auto sun = model->prepare_sun(sun_at(30.0));
  const Spectrum l = radiance(*model, *sun, 20.0, 10.0);
  EXPECT_EQ(l[0], 0.0);
  EXPECT_GT(l[1], 0.0);
  EXPECT_GT(l[2], 0.0);
  EXPECT_EQ(l[3], 0.0);
  // The paper's grid: 360..712.5 nm answered (31 bins), 724.25 nm and beyond not.
  const auto paper = make_hosek();
  EXPECT_TRUE(paper->answers_wavelength(30));
  EXPECT_FALSE(paper->answers_wavelength(31));
}

TEST(Hosek, SymmetricAboutTheSunsVerticalPlane) {
  const auto model = make_hosek();
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

TEST(Hosek, PositiveAndFiniteUpToTheHorizonAndForTheSunAtTheHorizon) {
  for (double turbidity : {1.0, 2.53, 10.0}) {
    const auto model = make_hosek(turbidity);
    for (double sun_zenith : {0.0, 45.0, 85.0, 89.9, 90.0}) {
      const auto sun = model->prepare_sun(sun_at(sun_zenith));
      std::vector<ViewDirection> views;
      for (double z = 0.0; z <= 90.0; z += 7.5)
        for (double a = 0.0; a < 360.0; a += 15.0)
          views.push_back({degrees_to_radians(z), degrees_to_radians(a)});
      views.push_back(sun->sun());
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
      EXPECT_LT(largest, 50.0);
      const auto e = model->sun_irradiance(*sun, {});
      ASSERT_EQ(e.status, SampleStatus::ok);
      for (double v : e.value) EXPECT_TRUE(std::isfinite(v) && v >= 0.0);
    }
  }
  const auto model = make_hosek();
  EXPECT_EQ(model->check_sun(sun_at(90.01)), SampleStatus::sun_below_horizon_unsupported);
  EXPECT_THROW(model->prepare_sun(sun_at(100.0)), std::invalid_argument);
}

TEST(Hosek, TurbidityDimsTheSunAndBrightensTheSky) {
  double previous_sun = 1e9, previous_sky = 0.0;
  for (double t : {1.0, 2.0, 2.53, 4.0, 7.0, 10.0}) {
    const auto model = make_hosek(t);
    const auto sun = model->prepare_sun(sun_at(30.0));
    const double sun_e = model->sun_irradiance(*sun, {}).value[12];
    const double sky_e = model->sky_irradiance(*sun, {}).value[12];
    EXPECT_LT(sun_e, previous_sun) << t;
    EXPECT_GT(sky_e, previous_sky) << t;
    previous_sun = sun_e;
    previous_sky = sky_e;
  }
}

TEST(Hosek, BrighterGroundBrightensTheSky) {
  const auto dark = make_hosek(2.53, 0.0);
  const auto bright = make_hosek(2.53, 1.0);
  const auto sun_dark = dark->prepare_sun(sun_at(30.0));
  const auto sun_bright = bright->prepare_sun(sun_at(30.0));
  for (std::size_t w = 0; w < 31; ++w) {
    EXPECT_GT(radiance(*bright, *sun_bright, 60.0, 300.0)[w],
              radiance(*dark, *sun_dark, 60.0, 300.0)[w])
        << w;
  }
}

TEST(Hosek, NativeBandsEqualTheStudysEvaluationForAConstantAlbedo) {
  // With one albedo for every wavelength the band states are the same in both modes.
  const auto study = make_hosek(2.53, 0.25, 0.0);
  const auto native = make_hosek(2.53, 0.25, 1.0);
  const auto a = study->prepare_sun(sun_at(40.0));
  const auto b = native->prepare_sun(sun_at(40.0));
  const Spectrum la = radiance(*study, *a, 55.0, 20.0);
  const Spectrum lb = radiance(*native, *b, 55.0, 20.0);
  for (std::size_t w = 0; w < la.size(); ++w) EXPECT_NEAR(lb[w], la[w], 1e-13) << w;
  // With grass (albedo varying within a band) they differ, by little.
  const auto grass_study = make_hosek();
  const auto grass_native = make_hosek(2.53, std::nullopt, 1.0);
  const auto c = grass_study->prepare_sun(sun_at(40.0));
  const auto d = grass_native->prepare_sun(sun_at(40.0));
  const Spectrum lc = radiance(*grass_study, *c, 55.0, 20.0);
  const Spectrum ld = radiance(*grass_native, *d, 55.0, 20.0);
  for (std::size_t w = 0; w < 31; ++w) EXPECT_NEAR(ld[w] / lc[w], 1.0, 0.05) << w;
}

TEST(Hosek, LimbDarkeningIsOneAtTheCentreAndDarkensTheLimb) {
  const double disc = kPi * std::pow(std::sin(hosek::kSolarRadiusRad), 2);
  for (int b = 0; b < hosek::kBandCount; ++b) {
    EXPECT_NEAR(hosek::limb_darkening(b, 1.0), 1.0, 2e-3) << b;  // fitted polynomials
    EXPECT_LT(hosek::limb_darkening(b, 0.1), hosek::limb_darkening(b, 0.9)) << b;
    const double weighted = hosek::limb_darkened_disc_solid_angle(b);
    EXPECT_GT(weighted, 0.6 * disc) << b;
    EXPECT_LT(weighted, disc) << b;
  }
  EXPECT_NEAR(hosek::solar_surface_cosine(0.0), 1.0, 1e-15);
  EXPECT_LT(hosek::solar_surface_cosine(1.01 * hosek::kSolarRadiusRad), 0.0);
}

TEST(Hosek, SolarDiscRadianceIntegratesToTheSunIrradiance) {
  const auto model = make_hosek();
  const auto* hosek_model = dynamic_cast<const HosekModel*>(model.get());
  for (double zenith : {20.0, 60.0, 85.0}) {
    const SunPosition sun_position = sun_at(zenith, 100.0);
    const auto sun = model->prepare_sun(sun_position);
    // Midpoint rule on a fine polar grid around the disc centre, independent of the model's.
    const double r = hosek::kSolarRadiusRad;
    const int rings = 100, sectors = 32;
    Spectrum sum(model->wavelengths().size(), 0.0);
    const Vec3 c = sun_position.unit_vector();
    const Vec3 east = normalize(cross(Vec3{0, 0, 1}, c));
    const Vec3 up = cross(c, east);
    for (int i = 0; i < rings; ++i) {
      const double gamma = r * (i + 0.5) / rings;
      const double area =
          2.0 * kPi * (std::cos(r * i / rings) - std::cos(r * (i + 1) / rings)) / sectors;
      for (int j = 0; j < sectors; ++j) {
        const double psi = 2.0 * kPi * (j + 0.5) / sectors;
        const Vec3 d =
            std::cos(gamma) * c + std::sin(gamma) * (std::cos(psi) * up + std::sin(psi) * east);
        sum += area * hosek_model->sun_disc_radiance(*sun, SkyDirection::from_unit_vector(d));
      }
    }
    const SpectralSample e = model->sun_irradiance(*sun, {});
    for (std::size_t w = 0; w < 31; ++w)
      EXPECT_NEAR(sum[w] / e.value[w], 1.0, 2e-3) << zenith << " " << w;
    // Limb darkening: the centre outshines a point near the limb.
    const Spectrum centre = hosek_model->sun_disc_radiance(*sun, sun_position);
    const Vec3 near_limb = std::cos(0.95 * r) * c + std::sin(0.95 * r) * east;
    const Spectrum limb =
        hosek_model->sun_disc_radiance(*sun, SkyDirection::from_unit_vector(near_limb));
    EXPECT_GT(centre[12], 1.3 * limb[12]);
    const Vec3 outside = std::cos(1.1 * r) * c + std::sin(1.1 * r) * east;
    EXPECT_EQ(hosek_model->sun_disc_radiance(*sun, SkyDirection::from_unit_vector(outside))[12],
              0.0);
  }
}

TEST(Hosek, SunIrradianceIsTheExtraterrestrialSpectrumTimesTheFitsTransmittance) {
  // The fit's disc-centre radiance over its original solar radiance is the direct
  // transmittance; integrated over the disc (limb-darkening weighted) for a high sun it
  // equals that at the centre, which is the study's sun irradiance.
  const auto model = make_hosek();
  const auto& t = hosek::Tables::get();
  double previous = 1e9;
  for (double zenith : {0.0, 30.0, 60.0, 80.0}) {
    const auto sun = model->prepare_sun(sun_at(zenith));
    const SpectralSample e = model->sun_irradiance(*sun, {});
    const std::size_t w = bin(559.75);  // between bands 520 and 560 (weight 0.99375)
    const double elevation = degrees_to_radians(90.0 - zenith);
    const double centre = 0.00625 * hosek::solar_centre_radiance(5, 2.53, elevation) +
                          0.99375 * hosek::solar_centre_radiance(6, 2.53, elevation);
    const double original =
        0.00625 * t.original_solar_radiance[5] + 0.99375 * t.original_solar_radiance[6];
    const double solar = model->atmosphere().solar_irradiance_w_m2_nm[w];
    EXPECT_NEAR(e.value[w] / (solar * centre / original), 1.0, 2e-3) << zenith;
    EXPECT_LT(e.value[w], solar);
    EXPECT_LT(e.value[w], previous);
    previous = e.value[w];
  }
  // The sun at the horizon: the lower half of the disc is hidden, the upper half dim.
  const auto horizon = model->prepare_sun(sun_at(90.0));
  const SpectralSample low = model->sun_irradiance(*horizon, {});
  EXPECT_LT(low.value[bin(559.75)],
            0.05 * model->atmosphere().solar_irradiance_w_m2_nm[bin(559.75)]);
}

TEST(Hosek, HorizontalSkyIrradianceIsWithinHalfAPercentOfAFineRule) {
  const auto model = make_hosek();
  for (double zenith : {0.0, 40.0, 85.0, 90.0}) {
    const auto sun = model->prepare_sun(sun_at(zenith));
    const SpectralSample fast = model->sky_irradiance(*sun, {});
    const Spectrum fine = reference_sky_irradiance(*clamped_hosek(), *sun, 100, 200);
    ASSERT_EQ(fast.status, SampleStatus::ok);
    for (std::size_t w = 0; w < 31; ++w) {
      EXPECT_NEAR(fast.value[w] / fine[w], 1.0, 0.005)
          << "sun zenith " << zenith << " wavelength " << w;
    }
    for (std::size_t w = 31; w < fine.size(); ++w) EXPECT_EQ(fast.value[w], 0.0);
  }
}

TEST(Hosek, TristimulusVersionsAgreeWithTheSpectralFit) {
  // The XYZ and RGB versions were fitted to the spectral model under the fit's own solar
  // spectrum: Y from XYZ matches the y_bar integral of the spectral bands (linear between
  // bands, 360..720 nm), and RGB matches the sRGB transform of XYZ.
  const auto& t = hosek::Tables::get();
  const auto& y_bar = ReferenceSpectra::get().cie_y_bar;
  const double elevation = degrees_to_radians(50.0), albedo = 0.2, turbidity = 3.0;
  const auto xyz_state =
      hosek::make_tristimulus_state(hosek::Tristimulus::xyz, turbidity, albedo, elevation);
  const auto rgb_state =
      hosek::make_tristimulus_state(hosek::Tristimulus::rgb, turbidity, albedo, elevation);
  for (const auto& [view_zenith, gamma] :
       std::vector<std::pair<double, double>>{{0.0, 40.0}, {45.0, 90.0}, {70.0, 30.0}}) {
    const double vz = degrees_to_radians(view_zenith), g = degrees_to_radians(gamma);
    const auto xyz = hosek::tristimulus_radiance(xyz_state, vz, g);
    const auto rgb = hosek::tristimulus_radiance(rgb_state, vz, g);
    const auto v = hosek::view_terms(std::cos(vz), std::cos(g));
    std::array<double, hosek::kBandCount> band{};
    for (int b = 0; b < hosek::kBandCount; ++b)
      band[b] = hosek::radiance(hosek::cook(t.spectral[b], turbidity, albedo, elevation), v);
    double y = 0.0;
    for (double nm = 360.0; nm < 720.0; nm += 1.0) {
      const double x = (nm + 0.5 - 320.0) / 40.0;
      const int b = static_cast<int>(x);
      y += y_bar.at(nm + 0.5, OutOfRange::zero) * ((b + 1 - x) * band[b] + (x - b) * band[b + 1]);
    }
    EXPECT_NEAR(xyz[1] / y, 1.0, 0.05) << view_zenith << " " << gamma;
    const LinearSrgb expected = xyz_to_linear_srgb({xyz[0], xyz[1], xyz[2]});
    EXPECT_NEAR(rgb[0] / expected.r, 1.0, 0.1);
    EXPECT_NEAR(rgb[1] / expected.g, 1.0, 0.1);
    EXPECT_NEAR(rgb[2] / expected.b, 1.0, 0.1);
  }
}

TEST(Hosek, TiltedPlaneSkyIrradianceIsWithinHalfAPercentOfAFineRule) {
  const auto model = make_hosek();
  for (double zenith : {30.0, 85.0}) {
    const auto sun = model->prepare_sun(sun_at(zenith, 180.0));
    for (const auto& [tilt, azimuth] :
         std::vector<std::pair<double, double>>{{30, 180}, {90, 180}, {90, 0}, {150, 0}}) {
      const PlaneOrientation plane{degrees_to_radians(tilt), degrees_to_radians(azimuth)};
      const SpectralSample fast = model->sky_irradiance(*sun, {}, plane);
      const Spectrum fine = reference_tilted_irradiance(*clamped_hosek(), *sun, plane);
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

TEST(Hosek, ConcurrentQueriesOnOneModelAgreeWithSerialOnes) {
  // The model and its sun states are immutable: threads share them without locks.
  const auto model = make_hosek();
  const auto sun = model->prepare_sun(sun_at(35.0));
  std::vector<ViewDirection> views;
  for (int i = 0; i < 64; ++i)
    views.push_back({degrees_to_radians(1.3 * i), degrees_to_radians(5.7 * i)});
  SpectralBatch serial;
  model->sky_radiance(*sun, {}, views, serial);
  std::vector<SpectralBatch> results(4);
  std::vector<std::thread> threads;
  for (auto& result : results) {
    threads.emplace_back([&model, &views, &result] {
      const auto own_sun = model->prepare_sun(sun_at(35.0));
      for (int repeat = 0; repeat < 20; ++repeat) model->sky_radiance(*own_sun, {}, views, result);
    });
  }
  for (auto& thread : threads) thread.join();
  for (const auto& result : results) EXPECT_EQ(result.values, serial.values);
}

}  // namespace
}  // namespace clearsky
