// The Preetham, Shirley and Smits (1999) daylight model as pure functions ("A Practical
// Analytic Model for Daylight", SIGGRAPH 1999; paper section "Preetham Model"):
//  - Perez et al. (1993) distribution F(theta, gamma) = (1 + A exp(B / cos theta))
//    (1 + C exp(D gamma) + E cos^2 gamma) for the luminance Y and the chromaticities x, y,
//    with coefficients linear in turbidity T (Preetham 1999 appendix 2);
//  - the value in a view: zenith value x F(theta, gamma) / F(0, theta_s);
//  - zenith luminance Y_z = (4.0453 T - 4.9710) tan(chi) - 0.2155 T + 2.4192 in kcd/m2,
//    chi = (4/9 - T/120)(pi - 2 theta_s), and zenith chromaticities cubic in theta_s and
//    quadratic in T (appendix 2);
//  - the spectrum S0 + M1 S1 + M2 S2 of the CIE daylight basis with M1, M2 from (x, y)
//    (appendix 6) scaled so that 683 lm/W x integral of y_bar L = Y;
//  - the sun's transmittance (appendix 1): Rayleigh, aerosol (Angstrom alpha 1.3, beta
//    0.04608 T - 0.04586), ozone (0.35 cm), mixed gases and water vapour (2 cm).
// Angles in radians. Valid for the sun above the horizon and T in [2, 10] (below 2 the zenith
// luminance turns negative for a high sun). Pure functions; thread-safe.
#pragma once

#include <array>

namespace clearsky::preetham {

struct PerezCoefficients {
  double a = 0, b = 0, c = 0, d = 0, e = 0;
};

PerezCoefficients luminance_coefficients(double turbidity);
PerezCoefficients chromaticity_x_coefficients(double turbidity);
PerezCoefficients chromaticity_y_coefficients(double turbidity);

// F(theta, gamma) with cos_theta clamped to a tiny positive value at the horizon (where the
// gradation term exp(B / cos theta) -> 0 for the fitted B < 0).
double perez(const PerezCoefficients& p, double cos_theta, double gamma_rad);

double zenith_luminance_kcd_m2(double turbidity, double sun_zenith_rad);
double zenith_chromaticity_x(double turbidity, double sun_zenith_rad);
double zenith_chromaticity_y(double turbidity, double sun_zenith_rad);

// Weights of the CIE daylight basis for chromaticity (x, y) as Preetham 1999 appendix 6 gives
// them, M1 = (-1.3515 - 1.7703 x + 5.9114 y) / M, M2 = (0.0300 - 31.4424 x + 30.0717 y) / M,
// M = 0.0241 + 0.2562 x - 0.7341 y. The 5.9114 differs from CIE 15's 2.9456: the 2016 study's
// code uses Preetham's value, and so do we (its RMSE depends on it).
struct BasisWeights {
  double m1 = 0, m2 = 0;
};
BasisWeights daylight_basis_weights(double chroma_x, double chroma_y);

// Air mass of the direct sun (Kasten 1966 as given in appendix 1).
double relative_air_mass(double sun_zenith_rad);
// Transmittance of the direct sun at wavelength_nm (appendix 1 with the study's tables of
// ozone, mixed-gas and water-vapour absorption, 440..790 nm every 10 nm, held beyond).
double sun_transmittance(double turbidity, double sun_zenith_rad, double wavelength_nm);

}  // namespace clearsky::preetham
