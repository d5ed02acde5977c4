// Bird and Riordan's simple spectral model of the cloudless sky, SPCTRAL2 (R. E. Bird and
// C. Riordan, "Simple solar spectral model for direct and diffuse irradiance on horizontal and
// tilted planes at the earth's surface for cloudless atmospheres", J. Climate Appl. Meteor.
// 25(1), 87-97, 1986; NREL technical report SERI/TR-215-2436, 1984). Its table (Table 1:
// extraterrestrial spectrum and the absorption coefficients of water vapour, ozone and the
// uniformly mixed gases, 300..4000 nm) is models/data/spectra/spctral2_bird_riordan1986.csv.
//
// The equations are those of the 1986 paper, numbered as there:
//  - relative air mass M, Kasten 1966 (2-5); pressure-corrected M' = M p/p0;
//  - Rayleigh optical depth 1 / (lambda^4 (115.6406 - 1.335 / lambda^2)), lambda in um (2-4);
//  - water vapour T_w = exp(-0.2385 a_w W M / (1 + 20.07 a_w W M)^0.45), W in cm (2-8);
//  - ozone T_o = exp(-a_o O3 M_o), M_o = (1 + h_o/6370) / (cos^2 Z + 2 h_o/6370)^0.5 with the
//    ozone maximum at h_o = 22 km, O3 in atm-cm (2-9, 2-10);
//  - mixed gases T_u = exp(-1.41 a_u M' / (1 + 118.93 a_u M')^0.45) (2-11);
//  - diffuse: Rayleigh (3-5), aerosol (3-6) and ground-sky multiple reflection (3-7, 3-8) parts,
//    the aerosol forward fraction F_s from the asymmetry g (3-11..3-15), and the short-wave
//    correction C_s = ((lambda + 0.55)^1.8) below 450 nm (3-17), applied once to the sum (3-1).
// Here the aerosols are given as the service's models give them (docs/architecture.md "The
// atmosphere"): Angstrom optical depth beta lambda_um^-alpha, a single-scattering albedo and an
// asymmetry g that do not vary with wavelength, where SPCTRAL2 had its rural aerosol.
// Everything is at 1 au; earth_sun_distance_factor gives the date's correction. Pure functions,
// thread-safe.
#pragma once

namespace clearsky::spctral2 {

// The absorber amounts of the vertical column.
struct Absorbers {
  double precipitable_water_cm = 1.42;
  double ozone_atm_cm = 0.34;
};

// Kasten 1966 relative optical air mass (eq. 2-5); zenith in [0, pi/2] (capped at 90 degrees,
// where it is about 36).
double relative_air_mass(double zenith_rad);
// Ozone air mass (eq. 2-10).
double ozone_air_mass(double zenith_rad);
// (r0/r)^2, the extraterrestrial irradiance of the day over that at 1 au: Spencer 1971 (eq. 2-2,
// 2-3), day_of_year 1..366 (fractional allowed).
double earth_sun_distance_factor(double day_of_year);
// Rayleigh optical depth of the whole atmosphere at sea-level pressure (eq. 2-4).
double rayleigh_optical_depth(double wavelength_nm);

// Transmittances of the three absorbers (eq. 2-8, 2-9, 2-11) for a coefficient of the table.
double water_vapour_transmittance(double a_w, double precipitable_water_cm, double air_mass);
double ozone_transmittance(double a_o, double ozone_atm_cm, double ozone_air_mass);
double mixed_gas_transmittance(double a_u, double pressure_air_mass);

// The product T_o T_w T_u at a wavelength (coefficients read linearly between the table's
// rows; 1 outside 300..4000 nm, where the table says nothing), for the sun at zenith_rad and
// the surface pressure pressure_ratio x 1013.25 hPa.
double absorption_transmittance(double wavelength_nm, const Absorbers& absorbers, double zenith_rad,
                                double pressure_ratio);

struct Atmosphere {
  double pressure_ratio = 1.0;  // surface pressure / 1013.25 hPa
  Absorbers absorbers;
  double angstrom_alpha = 0.8;
  double angstrom_beta = 0.04;  // aerosol optical depth at 1 um
  double aerosol_single_scattering_albedo = 0.8;
  double aerosol_asymmetry_g = 0.7;
  double ground_albedo = 0.2;
};

struct SpectralIrradiance {
  double direct_normal_w_m2_nm = 0;
  double diffuse_horizontal_w_m2_nm = 0;
};

// SPCTRAL2's direct normal (eq. 2-1) and diffuse horizontal (eq. 3-1) irradiance at
// wavelength_nm in [300, 4000], sun at zenith_rad < pi/2 (0 for a sun at or below the horizon),
// at 1 au, with the extraterrestrial spectrum of the table.
SpectralIrradiance spectral_irradiance(double wavelength_nm, double zenith_rad,
                                       const Atmosphere& atmosphere);
// The same with the extraterrestrial irradiance given (W/(m2.nm)), for a model's own spectrum.
SpectralIrradiance spectral_irradiance(double wavelength_nm, double zenith_rad,
                                       const Atmosphere& atmosphere,
                                       double extraterrestrial_w_m2_nm);

// The table's wavelength range.
inline constexpr double kMinWavelengthNm = 300.0;
inline constexpr double kMaxWavelengthNm = 4000.0;
// The table's extraterrestrial spectrum at wavelength_nm (linear between rows).
double extraterrestrial_w_m2_nm(double wavelength_nm);

}  // namespace clearsky::spctral2
