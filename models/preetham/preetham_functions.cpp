// Preetham 1999 appendices 1, 2 and 6.
#include "models/preetham/preetham_functions.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "models/core/numeric.h"
#include "models/spectral/tabulated_spectrum.h"

namespace clearsky::preetham {

PerezCoefficients luminance_coefficients(double t) {
  return {0.1787 * t - 1.4630, -0.3554 * t + 0.4275, -0.0227 * t + 5.3251, 0.1206 * t - 2.5771,
          -0.0670 * t + 0.3703};
}

PerezCoefficients chromaticity_x_coefficients(double t) {
  return {-0.0193 * t - 0.2592, -0.0665 * t + 0.0008, -0.0004 * t + 0.2125, -0.0641 * t - 0.8989,
          -0.0033 * t + 0.0452};
}

PerezCoefficients chromaticity_y_coefficients(double t) {
  return {-0.0167 * t - 0.2608, -0.0950 * t + 0.0092, -0.0079 * t + 0.2102, -0.0441 * t - 1.6537,
          -0.0109 * t + 0.0529};
}

double perez(const PerezCoefficients& p, double cos_theta, double gamma_rad) {
  // exp(B / 1e-9) underflows to 0 for the fitted B < 0: the horizon limit, without a division
  // by zero.
  const double mu = std::max(cos_theta, 1e-9);
  const double cos_gamma = std::cos(gamma_rad);
  return (1.0 + p.a * std::exp(p.b / mu)) *
         (1.0 + p.c * std::exp(p.d * gamma_rad) + p.e * cos_gamma * cos_gamma);
}

double zenith_luminance_kcd_m2(double t, double sun_zenith_rad) {
  const double chi = (4.0 / 9.0 - t / 120.0) * (kPi - 2.0 * sun_zenith_rad);
  return (4.0453 * t - 4.9710) * std::tan(chi) - 0.2155 * t + 2.4192;
}

double zenith_chromaticity_x(double t, double s) {
  const double s2 = s * s, s3 = s2 * s;
  return (0.00166 * s3 - 0.00375 * s2 + 0.00209 * s) * t * t +
         (-0.02903 * s3 + 0.06377 * s2 - 0.03202 * s + 0.00394) * t +
         (0.11693 * s3 - 0.21196 * s2 + 0.06052 * s + 0.25886);
}

double zenith_chromaticity_y(double t, double s) {
  const double s2 = s * s, s3 = s2 * s;
  return (0.00275 * s3 - 0.00610 * s2 + 0.00317 * s) * t * t +
         (-0.04214 * s3 + 0.08970 * s2 - 0.04153 * s + 0.00516) * t +
         (0.15346 * s3 - 0.26756 * s2 + 0.06670 * s + 0.26688);
}

BasisWeights daylight_basis_weights(double x, double y) {
  const double m = 0.0241 + 0.2562 * x - 0.7341 * y;
  return {(-1.3515 - 1.7703 * x + 5.9114 * y) / m, (0.0300 - 31.4424 * x + 30.0717 * y) / m};
}

double relative_air_mass(double sun_zenith_rad) {
  const double zenith_deg = radians_to_degrees(std::clamp(sun_zenith_rad, 0.0, 0.5 * kPi));
  return 1.0 /
         (std::cos(degrees_to_radians(zenith_deg)) + 0.15 * std::pow(93.885 - zenith_deg, -1.253));
}

namespace {

// Absorption coefficients (1/m) of ozone k_o, water vapour k_wa and mixed gases k_g
// (Preetham 1999 table 2), at 440, 450, ..., 790 nm as the study's code tabulates them.
struct AbsorptionTables {
  TabulatedSpectrum ozone, vapour, gas;

  AbsorptionTables() {
    const std::vector<double> k_o = {0.0,  0.3, 0.6, 0.9,  1.4,  2.1,  3.0,  4.0,  4.8,
                                     6.3,  7.5, 8.5, 10.3, 12.0, 12.0, 11.5, 12.5, 12.0,
                                     10.5, 9.0, 7.9, 6.7,  5.7,  4.8,  3.6,  2.8,  2.3,
                                     1.8,  1.4, 1.1, 1.0,  0.9,  0.7,  0.4,  0.0,  0.0};
    std::vector<double> k_wa(k_o.size(), 0.0), k_g(k_o.size(), 0.0);
    // Water vapour absorbs at 690..780 nm, mixed gases (the oxygen A band) at 760..770 nm.
    const std::vector<std::pair<int, double>> vapour_bands = {
        {25, 1.6}, {26, 2.4}, {27, 1.25},  {28, 100.0}, {29, 87.0},
        {30, 6.1}, {31, 0.1}, {32, 0.001}, {33, 0.001}, {34, 0.06}};
    for (const auto& [i, k] : vapour_bands) k_wa[i] = k;
    k_g[32] = 3.0;
    k_g[33] = 0.21;
    std::vector<double> nm;
    for (std::size_t i = 0; i < k_o.size(); ++i)
      nm.push_back(440.0 + 10.0 * static_cast<double>(i));
    ozone = TabulatedSpectrum(nm, k_o);
    vapour = TabulatedSpectrum(nm, k_wa);
    gas = TabulatedSpectrum(nm, k_g);
  }
};

const AbsorptionTables& absorption() {
  static const AbsorptionTables tables;
  return tables;
}

}  // namespace

double sun_transmittance(double t, double sun_zenith_rad, double wavelength_nm) {
  const double m = relative_air_mass(sun_zenith_rad);
  const double lambda_um = wavelength_nm / 1000.0;
  const double rayleigh = std::exp(-0.008735 * m * std::pow(lambda_um, -4.08));
  const double beta = 0.04608 * t - 0.04586;
  const double aerosol = std::exp(-beta * m * std::pow(lambda_um, -1.3));
  const auto& k = absorption();
  constexpr double kOzoneThicknessM = 0.0035;
  constexpr double kPrecipitableWaterM = 0.02;
  const double k_o = k.ozone.at(wavelength_nm, OutOfRange::hold_end_values);
  const double k_g = k.gas.at(wavelength_nm, OutOfRange::hold_end_values);
  const double k_wa = k.vapour.at(wavelength_nm, OutOfRange::hold_end_values);
  const double ozone = std::exp(-m * kOzoneThicknessM * k_o);
  const double gas = std::exp(-1.41 * k_g * m / std::pow(1.0 + 118.93 * k_g * m, 0.45));
  const double vapour_path = k_wa * kPrecipitableWaterM * m;
  const double vapour = std::exp(-0.2385 * vapour_path / std::pow(1.0 + 20.07 * vapour_path, 0.45));
  return rayleigh * aerosol * ozone * gas * vapour;
}

}  // namespace clearsky::preetham
