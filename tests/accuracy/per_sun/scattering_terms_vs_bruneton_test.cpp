// The single and double scattering terms of Haber and Nishita96 against Bruneton's (paper: "We
// validated it by comparing its single and double scattering terms with those of the Haber and
// Bruneton models", section "Nishita96 Model"). Bruneton's single scattering is its radiance with
// scattering_orders = 1, its double scattering the radiance with 2 orders minus that. Haber's terms
// likewise from its scattering_orders option; Nishita96's from radiance_orders(). Like for like:
// ground albedo 0 for all three (Haber has no ground at all; Bruneton and Nishita96 would otherwise
// add grass-reflected light to their double scattering), 3 wavelengths, ground-level observer, sun
// at azimuth 0 (view azimuths are from the sun; Haber's dome is read bilinearly between its cell
// centres). Prints the ratio model term / Bruneton term per sun, direction and wavelength, then
// min / median / max per model and term; the bounds below hold the measured ranges.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "models/bruneton/bruneton.h"
#include "models/core/numeric.h"
#include "models/haber/haber.h"
#include "models/nishita96/nishita96.h"

namespace clearsky {
namespace {

ModelConfig terms_config() {
  ModelConfig c;
  c.wavelengths = WavelengthGrid::points({440.0, 550.0, 680.0});
  c.atmosphere.ground_albedo = 0.0;
  return c;
}

ModelConfig bruneton_config(int orders) {
  ModelConfig c = terms_config();
  c.options["scattering_orders"] = orders;
  // The paper's 4D resolution (32 x 128 x 32 x 8); 3 wavelengths keep it to a few seconds. The
  // reduced 16 x 64 x 16 x 4 (README: nearly the same RMSE) moved Bruneton's double scattering
  // by -13% .. +37% at these views (e.g. 1.315e-3 against 0.960e-3 at sun 40, view 30 degrees
  // opposite the sun, 680 nm), enough to shift the ranges below.
  return c;
}

ModelConfig haber_config(int orders) {
  ModelConfig c = terms_config();
  c.options["scattering_orders"] = orders;
  return c;
}

std::vector<double> radiance(const SkyModel& model, const SunState& sun,
                             const ViewDirection& view) {
  SpectralBatch out;
  model.sky_radiance(sun, Viewpoint{}, std::span<const ViewDirection>(&view, 1), out);
  EXPECT_EQ(out.status[0], SampleStatus::ok);
  const auto s = out.spectrum(0);
  return {s.begin(), s.end()};
}

struct Range {
  double min, median, max;
};

Range range_of(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  const double median = n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
  return {v.front(), median, v.back()};
}

TEST(ScatteringTermsVsBruneton, HaberAndNishita96SingleAndDouble) {
  const auto start = std::chrono::steady_clock::now();
  const auto bruneton1 = bruneton_factory().create(bruneton_config(1), {});
  const auto bruneton2 = bruneton_factory().create(bruneton_config(2), {});
  const auto haber1 = haber::HaberModel::create(haber_config(1));
  const auto haber2 = haber::HaberModel::create(haber_config(2));
  const auto n96 = std::dynamic_pointer_cast<const Nishita96Model>(
      nishita96_factory().create(terms_config(), {}));
  ASSERT_NE(n96, nullptr);
  const std::vector<double>& nm = bruneton1->wavelengths().nanometres();

  std::vector<ViewDirection> views{{0.0, 0.0}};
  for (double zenith : {30.0, 60.0, 80.0}) {
    for (double azimuth : {0.0, 90.0, 180.0})
      views.push_back({degrees_to_radians(zenith), degrees_to_radians(azimuth)});
  }

  std::vector<double> haber_single, haber_double, n96_single, n96_double;
  std::printf("%5s %5s %5s %4s | %10s %7s %7s | %10s %7s %7s\n", "sun", "view", "azim", "nm",
              "B single", "Haber", "N96", "B double", "Haber", "N96");
  for (double sun_zenith_deg : {40.0, 70.0}) {
    const SunPosition sun{degrees_to_radians(sun_zenith_deg), 0.0};
    const auto b1_state = bruneton1->prepare_sun(sun);
    const auto b2_state = bruneton2->prepare_sun(sun);
    const auto h1_state = haber1->prepare_sun(sun);
    const auto h2_state = haber2->prepare_sun(sun);
    const auto n96_state = n96->prepare_sun(sun);
    const auto& n96_tables = dynamic_cast<const Nishita96SunState&>(*n96_state);
    for (const ViewDirection& view : views) {
      const auto b1 = radiance(*bruneton1, *b1_state, view);
      const auto b2 = radiance(*bruneton2, *b2_state, view);
      const auto h1 = radiance(*haber1, *h1_state, view);
      const auto h2 = radiance(*haber2, *h2_state, view);
      std::vector<double> ns(nm.size()), nd(nm.size());
      n96->radiance_orders(n96_tables, Viewpoint{}, view, Nishita96Orders::single_only, ns);
      n96->radiance_orders(n96_tables, Viewpoint{}, view, Nishita96Orders::double_only, nd);
      for (std::size_t w = 0; w < nm.size(); ++w) {
        const double b_double = b2[w] - b1[w];
        ASSERT_GT(b1[w], 0.0);
        ASSERT_GT(b_double, 0.0);
        haber_single.push_back(h1[w] / b1[w]);
        haber_double.push_back((h2[w] - h1[w]) / b_double);
        n96_single.push_back(ns[w] / b1[w]);
        n96_double.push_back(nd[w] / b_double);
        std::printf("%5.0f %5.0f %5.0f %4.0f | %10.4g %7.3f %7.3f | %10.4g %7.3f %7.3f\n",
                    sun_zenith_deg, radians_to_degrees(view.zenith_rad),
                    radians_to_degrees(view.azimuth_rad), nm[w], b1[w], haber_single.back(),
                    n96_single.back(), b_double, haber_double.back(), n96_double.back());
      }
    }
  }
  const auto print = [](const char* name, const std::vector<double>& ratios) {
    const Range r = range_of(ratios);
    std::printf("%-18s ratio to Bruneton: min %.3f, median %.3f, max %.3f\n", name, r.min, r.median,
                r.max);
    return r;
  };
  const Range hs = print("Haber single", haber_single);
  const Range hd = print("Haber double", haber_double);
  const Range ns = print("Nishita96 single", n96_single);
  const Range nd = print("Nishita96 double", n96_double);
  std::printf("run time %.1f s\n",
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());

  // Haber single, measured 0.743 .. 1.257 (median 0.988): its Rayleigh phase function is
  // isotropic, 1/(4 pi) against 3/(16 pi) (1 + cos^2), a ratio between 0.67 (towards and away
  // from the sun) and 1.33 (at 90 degrees from it); the Mie part agrees.
  EXPECT_GT(hs.min, 0.70);
  EXPECT_LT(hs.max, 1.30);
  // Nishita96 single, measured 0.879 .. 0.994 (median 0.968), lowest near the sun and in the
  // red (Mie-dominated): the study's zero integrand at the observer, and Bruneton's 50-step
  // trapezoid, which overestimates the Mie term by up to ~8% (models/bruneton/README.md).
  EXPECT_GT(ns.min, 0.85);
  EXPECT_LT(ns.max, 1.02);
  // Haber double, measured 0.264 .. 2.008 (median 1.379): orders >= 2 are scattered
  // isotropically towards the viewer, so the forward Mie peak of the second scattering around
  // the sun is missing (views at 60 and 80 degrees towards a sun at 70 degrees: 0.26 .. 0.79,
  // lowest in the red; towards a sun at 40 degrees 0.64 .. 1.27); at the zenith and at 90 and
  // 180 degrees from the sun the study's gathering overcounts (1.05 .. 2.01; against a direct
  // integration 1.51 .. 2.45, scattering_terms_test.cpp).
  EXPECT_GT(hd.min, 0.2);
  EXPECT_LT(hd.max, 2.5);
  EXPECT_GT(hd.median, 1.1);
  // Nishita96 double, measured 1.171 .. 5.298 (median 2.124): 8 sampling directions stand for
  // the whole sphere (against a full-sphere integration of its own equation 1.19 .. 2.09 at a
  // 40 degree sun, scattering_terms_test.cpp); the overestimate grows with the wavelength and
  // the sun zenith (40 degrees: 1.17 .. 2.69; 70 degrees: 1.78 .. 5.30).
  EXPECT_GT(nd.min, 1.0);
  EXPECT_LT(nd.max, 6.0);
  EXPECT_GT(nd.median, 1.5);
}

}  // namespace
}  // namespace clearsky
