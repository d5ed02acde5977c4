// The Lambertian ground of the single-scattering models that answer views meeting the ground
// (Nishita93, O'Neal; their READMEs): the radiance it sends back in every direction is
//   L_ground = albedo / pi  (E_sun T_sun(mu_s) max(mu_s, 0) + E_sky(mu_s)),
// with the shared ground albedo (docs/model-contract.md "The atmosphere parameter table"), E_sun
// the extraterrestrial solar irradiance, T_sun the transmittance from the ground point to the
// sun (the caller's, 0 in the Earth's shadow) and E_sky the model's own sky irradiance on the
// horizontal ground. The sky irradiance depends on the sun only through its zenith cosine at
// the ground point, so it is tabulated once per model over mu_s in [-0.2, 1] (49 nodes, linear
// between them; below -0.2, 11.5 degrees below the horizon, the sky above the ground is in the
// Earth's shadow for a 60 km atmosphere and it is 0). The caller adds L_ground times the view's
// transmittance to the ground. Immutable after construction; thread-safe.
#pragma once

#include <functional>
#include <span>
#include <vector>

#include "models/spectral/spectrum.h"

namespace clearsky {

class LambertianGround {
 public:
  static constexpr double kLowestSunCosine = -0.2;
  static constexpr int kSunCosineNodes = 49;

  LambertianGround() = default;
  // sky_irradiance(mu_s): the horizontal sky irradiance on the ground, W/(m2.nm), for a sun of
  // zenith cosine mu_s; called once per node.
  LambertianGround(Spectrum albedo, Spectrum solar_irradiance,
                   const std::function<Spectrum(double mu_s)>& sky_irradiance);

  // out += view_transmittance * L_ground for a ground point whose sun zenith cosine is mu_s.
  void add_reflected(double mu_s, std::span<const double> sun_transmittance,
                     std::span<const double> view_transmittance, std::span<double> out) const;

  // The tabulated sky irradiance at mu_s (tests).
  Spectrum sky_irradiance(double mu_s) const;

 private:
  Spectrum albedo_over_pi_, solar_irradiance_;
  std::vector<Spectrum> sky_irradiance_;  // at the nodes
};

}  // namespace clearsky
