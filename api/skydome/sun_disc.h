// The solar disc of a skydome (GET /v1/skydome sun=disc, docs/renderers.md): the model's direct
// normal irradiance E_n(lambda) (SkyModel::sun_irradiance, the sun already attenuated by the
// atmosphere) spread over the pixels the disc covers, so that the sum over those pixels of
// radiance x pixel solid angle (SkydomeProjection::pixel_solid_angle_sr) equals E_n at every
// wavelength, however small the disc is against a pixel.
//
// - Angular radius 0.2666 degrees: the Sun's mean angular radius at 1 AU (959.6 arcsec; IAU 2015
//   Resolution B3 nominal solar radius 695,700 km at 1 au). The +-1.7% of its yearly variation
//   is not applied: the models' extraterrestrial spectrum is the 1 AU one too.
// - Limb darkening I(mu)/I(1) = sum_k c_k(lambda) mu^k, mu the cosine on the solar surface
//   (mu = sqrt(1 - (sin rho / sin R)^2) at angle rho from the disc centre), with the degree-5
//   coefficients of Neckel and Labs 1994 ("Solar limb darkening 1986-1990", Solar Physics 153)
//   as tabulated at 320..720 nm by Hosek and Wilkie 2013 ("Adding a Solar-Radiance Function to
//   the Hosek-Wilkie Skylight Model", models/hosek/README.md), linear in wavelength between
//   their bands and the nearest band outside them.
// - The disc is sampled on 64 rings x 384 azimuths (samples at most 0.0044 degrees apart, a
//   fifth of the smallest pixel, a 4096-pixel cube face's 0.022 degrees); each sample adds its
//   solid angle to the pixel that sees its direction (SkydomeProjection::pixel). Samples below
//   the horizon are hidden by the ground and carry nothing, so a setting sun carries the part
//   of E_n above the horizon; a sun whose disc is wholly below carries nothing.
// Immutable once built; thread-safe.
#pragma once

#include <span>
#include <vector>

#include "api/skydome/skydome_projection.h"
#include "models/core/geometry.h"

namespace clearsky::api {

inline constexpr double kSunAngularRadiusDeg = 0.2666;

// I(mu)/I(1) at wavelength_nm (the law above).
double solar_limb_darkening(double wavelength_nm, double mu);

class SolarDiscPixels {
 public:
  struct Pixel {
    int x = 0, y = 0;
    std::vector<double> radiance;  // to add to the sky's, W/(m2.sr.nm), one per wavelength
  };

  SolarDiscPixels(const SkydomeProjection& projection, const SkyDirection& sun,
                  std::span<const double> wavelengths_nm,
                  std::span<const double> direct_normal_w_m2_nm);

  // Sorted by (y, x).
  const std::vector<Pixel>& pixels() const { return pixels_; }
  // The pixel (x, y), or nullptr when the disc does not cover it.
  const Pixel* find(int x, int y) const;
  // Whether row y holds a pixel of the disc.
  bool covers_row(int y) const { return y >= first_row_ && y <= last_row_; }
  std::size_t memory_bytes() const;

 private:
  std::vector<Pixel> pixels_;
  int first_row_ = 1, last_row_ = 0;
};

// The disc's solid angle at kSunAngularRadiusDeg, sr: 2 pi (1 - cos R).
double sun_disc_solid_angle_sr();

}  // namespace clearsky::api
