// Validation and canonical form of the atmosphere parameters.
#include "models/atmosphere/atmosphere_parameters.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "models/core/invalid_input.h"

namespace clearsky {

namespace {

void require(bool ok, const char* name, const char* range) {
  if (!ok) throw InvalidInput(name, std::string("must be ") + range);
}

}  // namespace

void AtmosphereParameters::validate() const {
  require(std::isfinite(earth_radius_m) && earth_radius_m > 0.0, "earth_radius_m",
          "finite and > 0");
  require(std::isfinite(top_radius_m) && top_radius_m > earth_radius_m, "top_radius_m",
          "finite and > earth_radius_m");
  require(rayleigh_scale_height_m > 0.0 && rayleigh_scale_height_m <= 1e5,
          "rayleigh_scale_height_m", "in (0, 100000]");
  require(mie_scale_height_m > 0.0 && mie_scale_height_m <= 1e5, "mie_scale_height_m",
          "in (0, 100000]");
  require(rayleigh_temperature_celsius >= -100.0 && rayleigh_temperature_celsius <= 100.0,
          "rayleigh_temperature_celsius", "in [-100, 100]");
  require(angstrom_alpha >= 0.0 && angstrom_alpha <= 4.0, "alpha", "in [0, 4]");
  require(angstrom_beta >= 0.0 && angstrom_beta <= 2.0, "beta", "in [0, 2]");
  require(mie_single_scattering_albedo >= 0.0 && mie_single_scattering_albedo <= 1.0,
          "mie_single_scattering_albedo", "in [0, 1]");
  require(mie_phase_g > -1.0 && mie_phase_g < 1.0, "g", "in (-1, 1)");
  require(turbidity >= 1.0 && turbidity <= 10.0, "turbidity", "in [1, 10]");
  if (ground_albedo) require(*ground_albedo >= 0.0 && *ground_albedo <= 1.0, "albedo", "in [0, 1]");
}

std::string AtmosphereParameters::canonical_string() const {
  std::ostringstream out;
  out.precision(17);
  out << "R=" << earth_radius_m << ";top=" << top_radius_m << ";HR=" << rayleigh_scale_height_m
      << ";HM=" << mie_scale_height_m << ";T=" << rayleigh_temperature_celsius
      << ";alpha=" << angstrom_alpha << ";beta=" << angstrom_beta
      << ";ssa=" << mie_single_scattering_albedo << ";g=" << mie_phase_g
      << ";turbidity=" << turbidity << ";albedo=";
  if (ground_albedo) {
    out << *ground_albedo;
  } else {
    out << "grass";
  }
  return out.str();
}

}  // namespace clearsky
