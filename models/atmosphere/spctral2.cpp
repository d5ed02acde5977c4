// SPCTRAL2 (Bird and Riordan 1986): the equations of models/atmosphere/spctral2.h.
#include "models/atmosphere/spctral2.h"

#include <algorithm>
#include <cmath>

#include "models/core/numeric.h"
#include "models/spectral/reference_spectra.h"

namespace clearsky::spctral2 {

namespace {

constexpr double kOzoneHeightOverEarthRadius = 22.0 / 6370.0;  // eq. 2-10
constexpr double kDiffuseAirMass = 1.8;                        // the primed terms, eq. 3-8, 3-15

bool inside_table(double wavelength_nm) {
  return wavelength_nm >= kMinWavelengthNm && wavelength_nm <= kMaxWavelengthNm;
}

double coefficient(const TabulatedSpectrum& table, double wavelength_nm) {
  return table.at(wavelength_nm, OutOfRange::zero);
}

struct Transmittances {
  double rayleigh = 1, aerosol_scattering = 1, aerosol_absorption = 1, water = 1, ozone = 1,
         mixed = 1;
};

Transmittances transmittances(double wavelength_nm, double air_mass, double ozone_mass,
                              const Atmosphere& a) {
  const ReferenceSpectra& r = ReferenceSpectra::get();
  const double pressure_air_mass = air_mass * a.pressure_ratio;
  const double tau_aerosol = a.angstrom_beta * std::pow(wavelength_nm / 1000.0, -a.angstrom_alpha);
  const double ssa = a.aerosol_single_scattering_albedo;
  Transmittances t;
  t.rayleigh = std::exp(-pressure_air_mass * rayleigh_optical_depth(wavelength_nm));
  t.aerosol_scattering = std::exp(-ssa * tau_aerosol * air_mass);          // eq. 3-9
  t.aerosol_absorption = std::exp(-(1.0 - ssa) * tau_aerosol * air_mass);  // eq. 3-10
  t.water = water_vapour_transmittance(coefficient(r.spctral2_water_vapour_a_w, wavelength_nm),
                                       a.absorbers.precipitable_water_cm, air_mass);
  t.ozone = ozone_transmittance(coefficient(r.spctral2_ozone_a_o, wavelength_nm),
                                a.absorbers.ozone_atm_cm, ozone_mass);
  t.mixed = mixed_gas_transmittance(coefficient(r.spctral2_mixed_gases_a_u, wavelength_nm),
                                    pressure_air_mass);
  return t;
}

}  // namespace

double relative_air_mass(double zenith_rad) {
  const double zenith_deg = std::min(zenith_rad / kDegree, 90.0);
  return 1.0 /
         (std::cos(degrees_to_radians(zenith_deg)) + 0.15 * std::pow(93.885 - zenith_deg, -1.253));
}

double ozone_air_mass(double zenith_rad) {
  const double c = std::cos(std::min(zenith_rad, 0.5 * kPi));
  return (1.0 + kOzoneHeightOverEarthRadius) / std::sqrt(c * c + 2.0 * kOzoneHeightOverEarthRadius);
}

double earth_sun_distance_factor(double day_of_year) {
  const double gamma = 2.0 * kPi * (day_of_year - 1.0) / 365.0;
  return 1.00011 + 0.034221 * std::cos(gamma) + 0.00128 * std::sin(gamma) +
         0.000719 * std::cos(2.0 * gamma) + 0.000077 * std::sin(2.0 * gamma);
}

double rayleigh_optical_depth(double wavelength_nm) {
  const double um = wavelength_nm / 1000.0;
  return 1.0 / (std::pow(um, 4) * (115.6406 - 1.335 / (um * um)));
}

double water_vapour_transmittance(double a_w, double precipitable_water_cm, double air_mass) {
  const double x = a_w * precipitable_water_cm * air_mass;
  return std::exp(-0.2385 * x / std::pow(1.0 + 20.07 * x, 0.45));
}

double ozone_transmittance(double a_o, double ozone_atm_cm, double ozone_air_mass) {
  return std::exp(-a_o * ozone_atm_cm * ozone_air_mass);
}

double mixed_gas_transmittance(double a_u, double pressure_air_mass) {
  const double x = a_u * pressure_air_mass;
  return std::exp(-1.41 * x / std::pow(1.0 + 118.93 * x, 0.45));
}

double absorption_transmittance(double wavelength_nm, const Absorbers& absorbers, double zenith_rad,
                                double pressure_ratio) {
  if (!inside_table(wavelength_nm)) return 1.0;
  const ReferenceSpectra& r = ReferenceSpectra::get();
  const double m = relative_air_mass(zenith_rad);
  return water_vapour_transmittance(coefficient(r.spctral2_water_vapour_a_w, wavelength_nm),
                                    absorbers.precipitable_water_cm, m) *
         ozone_transmittance(coefficient(r.spctral2_ozone_a_o, wavelength_nm),
                             absorbers.ozone_atm_cm, ozone_air_mass(zenith_rad)) *
         mixed_gas_transmittance(coefficient(r.spctral2_mixed_gases_a_u, wavelength_nm),
                                 m * pressure_ratio);
}

double extraterrestrial_w_m2_nm(double wavelength_nm) {
  return ReferenceSpectra::get().spctral2_extraterrestrial.at(wavelength_nm, OutOfRange::zero);
}

SpectralIrradiance spectral_irradiance(double wavelength_nm, double zenith_rad,
                                       const Atmosphere& atmosphere) {
  return spectral_irradiance(wavelength_nm, zenith_rad, atmosphere,
                             extraterrestrial_w_m2_nm(wavelength_nm));
}

SpectralIrradiance spectral_irradiance(double wavelength_nm, double zenith_rad,
                                       const Atmosphere& atmosphere,
                                       double extraterrestrial_w_m2_nm) {
  if (!inside_table(wavelength_nm) || !(zenith_rad < 0.5 * kPi)) return {};
  const double cos_zenith = std::cos(zenith_rad);
  const double m = relative_air_mass(zenith_rad);
  const Transmittances t = transmittances(wavelength_nm, m, ozone_air_mass(zenith_rad), atmosphere);
  const Transmittances primed =
      transmittances(wavelength_nm, kDiffuseAirMass, ozone_air_mass(zenith_rad), atmosphere);
  const double e0 = extraterrestrial_w_m2_nm;
  // eq. 2-1 (T_a = T_as T_aa)
  const double direct_normal =
      e0 * t.rayleigh * t.aerosol_scattering * t.aerosol_absorption * t.water * t.ozone * t.mixed;
  // Aerosol forward-scattered fraction (eq. 3-11..3-15).
  const double alg = std::log(1.0 - atmosphere.aerosol_asymmetry_g);
  const double afs = alg * (1.459 + alg * (0.1595 + alg * 0.4129));
  const double bfs = alg * (0.0783 + alg * (-0.3824 - alg * 0.5874));
  const double fs = 1.0 - 0.5 * std::exp((afs + bfs * cos_zenith) * cos_zenith);
  const double fs_primed = 1.0 - 0.5 * std::exp((afs + bfs / kDiffuseAirMass) / kDiffuseAirMass);
  const double common = e0 * cos_zenith * t.ozone * t.mixed * t.water * t.aerosol_absorption;
  const double rayleigh_part = common * (1.0 - std::pow(t.rayleigh, 0.95)) * 0.5;  // eq. 3-5
  const double aerosol_part =
      common * std::pow(t.rayleigh, 1.5) * (1.0 - t.aerosol_scattering) * fs;  // eq. 3-6
  // Sky reflectivity (eq. 3-8) and the ground-sky multiple reflection (eq. 3-7).
  const double sky_reflectivity =
      primed.ozone * primed.water * primed.aerosol_absorption *
      (0.5 * (1.0 - primed.rayleigh) +
       (1.0 - fs_primed) * primed.rayleigh * (1.0 - primed.aerosol_scattering));
  const double rg = atmosphere.ground_albedo;
  const double ground_part = (direct_normal * cos_zenith + rayleigh_part + aerosol_part) *
                             sky_reflectivity * rg / (1.0 - sky_reflectivity * rg);
  const double um = wavelength_nm / 1000.0;
  const double short_wave = um <= 0.45 ? std::pow(um + 0.55, 1.8) : 1.0;  // eq. 3-17
  return {direct_normal, (rayleigh_part + aerosol_part + ground_part) * short_wave};
}

}  // namespace clearsky::spctral2
