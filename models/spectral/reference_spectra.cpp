// Parses the embedded tables of models/data/spectra.
#include "models/spectral/reference_spectra.h"

#include <sstream>
#include <string>

#include "models/core/embedded_data.h"

namespace clearsky {

namespace {

NumericTable load(const char* path) {
  std::istringstream in{std::string(data::embedded_file(path))};
  return read_numeric_table(in, path);
}

ReferenceSpectra build() {
  ReferenceSpectra r;
  const NumericTable cie = load("spectra/cie1931_2deg_xyz.csv");
  r.cie_x_bar = cie.spectrum(0, cie.column_index("x_bar"));
  r.cie_y_bar = cie.spectrum(0, cie.column_index("y_bar"));
  r.cie_z_bar = cie.spectrum(0, cie.column_index("z_bar"));
  const NumericTable daylight = load("spectra/cie_daylight_s0_s1_s2.csv");
  r.daylight_s0 = daylight.spectrum(0, daylight.column_index("S0"));
  r.daylight_s1 = daylight.spectrum(0, daylight.column_index("S1"));
  r.daylight_s2 = daylight.spectrum(0, daylight.column_index("S2"));
  const NumericTable astm = load("spectra/astm_g173.txt");
  r.astm_g173_extraterrestrial = astm.spectrum(0, 1);
  const NumericTable bins = load("spectra/solar_irradiance_40bins.csv");
  r.solar_irradiance_40_bins = bins.spectrum(0, 1);
  const NumericTable penndorf = load("spectra/rayleigh_penndorf1957_0C.csv");
  r.rayleigh_penndorf_0c_per_m = penndorf.spectrum(0, 1);
  const NumericTable grass = load("spectra/grass_albedo_feister1995.csv");
  r.grass_albedo = grass.spectrum(0, 1);
  const NumericTable spctral2 = load("spectra/spctral2_bird_riordan1986.csv");
  r.spctral2_extraterrestrial =
      spctral2.spectrum(0, spctral2.column_index("extraterrestrial_w_m2_nm"));
  r.spctral2_water_vapour_a_w = spctral2.spectrum(0, spctral2.column_index("water_vapour_a_w"));
  r.spctral2_ozone_a_o = spctral2.spectrum(0, spctral2.column_index("ozone_a_o"));
  r.spctral2_mixed_gases_a_u = spctral2.spectrum(0, spctral2.column_index("mixed_gases_a_u"));
  return r;
}

}  // namespace

const ReferenceSpectra& ReferenceSpectra::get() {
  static const ReferenceSpectra spectra = build();
  return spectra;
}

}  // namespace clearsky
