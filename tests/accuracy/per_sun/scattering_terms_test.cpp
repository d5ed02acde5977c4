// The single and double scattering terms of Haber and Nishita96 against direct numerical
// integrations of the same physics (paper: "We validated it by comparing its single and double
// scattering terms with those of the Haber and Bruneton models"). Heavy (full grids, nested
// quadratures over the sphere), hence in the accuracy program. Printed ratios are the
// measured differences stated in the models' READMEs; the bounds below hold them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "models/atmosphere/phase_functions.h"
#include "models/core/numeric.h"
#include "models/core/optical_depth.h"
#include "models/core/quadrature.h"
#include "models/core/ray_quadrature.h"
#include "models/core/single_scattering_reference.h"
#include "models/haber/haber.h"
#include "models/nishita96/nishita96.h"
#include "tests/models/haber/haber_reference.h"

namespace clearsky {
namespace {

const std::vector<std::size_t> kWavelengths{0, 12, 30};  // 360, 501, 712.5 nm

TEST(ScatteringTerms, HaberSingleAndDoubleAgainstDirectIntegration) {
  const double sun_zenith = degrees_to_radians(40.0);
  ModelConfig one;
  one.options["scattering_orders"] = 1;
  ModelConfig two;
  two.options["scattering_orders"] = 2;
  const auto single_model = haber::HaberModel::create(one);
  const auto double_model = haber::HaberModel::create(two);
  const auto s1 = single_model->prepare_sun({sun_zenith, 0.0});
  const auto s2 = double_model->prepare_sun({sun_zenith, 0.0});
  const auto& dome1 = dynamic_cast<const haber::HaberSunState&>(*s1).dome();
  const auto& dome2 = dynamic_cast<const haber::HaberSunState&>(*s2).dome();
  const haber::testing::ScatteringReference reference(single_model->grid().layers(),
                                                      single_model->atmosphere(), sun_zenith);
  const double step = single_model->grid().angular_step_rad();
  const Vec3 viewer{0.0, 0.0, 6360e3};
  for (const auto& [ring, sector] : std::vector<std::pair<int, int>>{{0, 0}, {9, 8}, {16, 35}}) {
    const double theta = (ring + 0.5) * step, phi = (sector + 0.5) * step;
    const Vec3 d{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
    const auto single = reference.single(viewer, d, kWavelengths);
    const auto twice = reference.double_scattering(d, kWavelengths);
    for (std::size_t i = 0; i < kWavelengths.size(); ++i) {
      const std::size_t w = kWavelengths[i];
      const double model_single = dome1.node(ring, sector)[w];
      const double model_double = dome2.node(ring, sector)[w] - model_single;
      std::printf(
          "haber view (%.1f, %.1f) deg, %zu: single %.4g / ref %.4g = %.3f; double %.4g / ref %.4g "
          "= %.3f\n",
          radians_to_degrees(theta), radians_to_degrees(phi), w, model_single, single[i],
          model_single / single[i], model_double, twice[i], model_double / twice[i]);
      // Measured 0.990 .. 1.002.
      EXPECT_NEAR(model_single / single[i], 1.0, 0.02);
      // Measured 1.51 .. 2.45: the study's gathering treats each source cell as a point of
      // solid angle (volume / radial width) / distance^2, which overcounts close pairs (the
      // azimuth sectors converge near the zenith: some pairs get more than 4 pi), and divides
      // that solid angle by an extra 4 pi; the net is this overestimate (models/haber/README.md).
      EXPECT_GT(model_double / twice[i], 1.2);
      EXPECT_LT(model_double / twice[i], 3.0);
    }
  }
}

// Double scattering of Nishita96's equation with the inner integral over the whole sphere
// (16 x 32 Gauss-Legendre x midpoint directions) instead of 8 binned sampling directions, the
// single-scattered radiance L1 from the reference integrator plus the sunlit Lambertian ground.
std::vector<double> nishita96_double_reference(const AtmosphereSpectra& a, double sun_zenith_rad,
                                               Vec3 view) {
  const Vec3 sun{std::sin(sun_zenith_rad), 0.0, std::cos(sun_zenith_rad)};
  const double earth = a.parameters.earth_radius_m;
  const double top = a.parameters.top_radius_m;
  const RayQuadratureOptions cheap{6000.0, 3};
  const auto mu_nodes = gauss_legendre(16, -1.0, 1.0);
  constexpr int kAzimuths = 32;
  const double end =
      -earth * view.z + std::sqrt(earth * earth * view.z * view.z - earth * earth + top * top);
  const auto nodes = ray_nodes(ray_breakpoints(earth, view.z, 0.0, end, 3000.0), 2);
  std::vector<double> result(kWavelengths.size(), 0.0);
  for (const RayNode& node : nodes) {
    const Vec3 x = Vec3{0.0, 0.0, earth} + node.distance_m * view;
    const double r = length(x);
    const Vec3 up = (1.0 / r) * x;
    const double h = r - earth;
    const double rho_r = std::exp(-h / a.parameters.rayleigh_scale_height_m);
    const double rho_m = std::exp(-h / a.parameters.mie_scale_height_m);
    std::vector<double> gathered(kWavelengths.size(), 0.0);
    for (const auto& [mu_w, weight_mu] : mu_nodes) {
      const double s = std::sqrt(std::max(0.0, 1.0 - mu_w * mu_w));
      for (int j = 0; j < kAzimuths; ++j) {
        const double phi = 2.0 * kPi * (j + 0.5) / kAzimuths;
        const Vec3 w{s * std::cos(phi), s * std::sin(phi), mu_w};
        const double d_omega = weight_mu * 2.0 * kPi / kAzimuths;
        const RaySunGeometry ray{r, clamp_cosine(dot(w, up)), clamp_cosine(dot(sun, up)),
                                 clamp_cosine(dot(w, sun))};
        const ScatteringAlongRay l1 =
            single_scattering_reference(a, ray, std::numeric_limits<double>::infinity(), cheap);
        Spectrum ground(a.grid.size(), 0.0);
        if (l1.hits_ground) {
          const Vec3 g = x + l1.length_m * w;
          const double cos_sun = dot(normalize(g), sun);
          if (cos_sun > 0.0) ground = transmittance_to_space(a, earth, cos_sun, cheap);
          for (std::size_t k = 0; k < ground.size(); ++k) {
            ground[k] *= std::max(cos_sun, 0.0) * a.ground_albedo[k] / kPi *
                         a.solar_irradiance_w_m2_nm[k] * l1.transmittance[k];
          }
        }
        const double nu = clamp_cosine(dot(view, w));
        for (std::size_t i = 0; i < kWavelengths.size(); ++i) {
          const std::size_t k = kWavelengths[i];
          const double phase = a.rayleigh_scattering_per_m[k] * rho_r * rayleigh_phase(nu) +
                               a.mie_scattering_per_m[k] * rho_m *
                                   cornette_shanks_phase(nu, a.parameters.mie_phase_g);
          gathered[i] += d_omega * phase * (l1.radiance[k] + ground[k]);
        }
      }
    }
    const Spectrum t = transmittance(a, optical_lengths(a, earth, view.z, node.distance_m, cheap));
    for (std::size_t i = 0; i < kWavelengths.size(); ++i)
      result[i] += node.weight_m * t[kWavelengths[i]] * gathered[i];
  }
  return result;
}

TEST(ScatteringTerms, Nishita96DoubleAgainstAFullSphereIntegration) {
  const double sun_zenith = degrees_to_radians(40.0);
  const auto model = std::dynamic_pointer_cast<const Nishita96Model>(
      nishita96_factory().create(ModelConfig{}, {}));
  const auto state = model->prepare_sun({sun_zenith, 0.0});
  const auto& n96 = dynamic_cast<const Nishita96SunState&>(*state);
  std::vector<double> value(model->wavelengths().size());
  for (const auto& [zenith, azimuth] :
       std::vector<std::pair<double, double>>{{0.0, 0.0}, {47.5, 42.5}, {82.5, 177.5}}) {
    const ViewDirection view{degrees_to_radians(zenith), degrees_to_radians(azimuth)};
    model->radiance_orders(n96, Viewpoint{}, view, Nishita96Orders::double_only, value);
    const Vec3 d{std::sin(view.zenith_rad) * std::cos(view.azimuth_rad),
                 std::sin(view.zenith_rad) * std::sin(view.azimuth_rad), std::cos(view.zenith_rad)};
    const auto reference = nishita96_double_reference(model->atmosphere(), sun_zenith, d);
    for (std::size_t i = 0; i < kWavelengths.size(); ++i) {
      const double ratio = value[kWavelengths[i]] / reference[i];
      std::printf("nishita96 view (%.1f, %.1f) deg, %zu: double %.4g / full-sphere %.4g = %.3f\n",
                  zenith, azimuth, kWavelengths[i], value[kWavelengths[i]], reference[i], ratio);
      // Measured 1.19 .. 2.09: 8 sampling directions stand for the whole sphere, each bin's
      // phase mass multiplied by the radiance along its sampling direction only.
      EXPECT_GT(ratio, 1.0);
      EXPECT_LT(ratio, 2.5);
    }
  }
}

}  // namespace
}  // namespace clearsky
