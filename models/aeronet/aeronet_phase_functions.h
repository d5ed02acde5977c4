// Reader of an AERONET almucantar inversion file of phase functions (".pfn", version 2 layout,
// Dubovik and King 2000, "A flexible inversion algorithm for retrieval of aerosol optical
// properties from Sun and sky radiance measurements", JGR 105(D16); Dubovik et al. 2000, JGR
// 105(D8), for the accuracy of the retrieved quantities), as models/data/aeronet holds one:
//
//   line 1  day and site: "dd:mm:yyyy,Locations=NAME,long=X,lat=Y,elev=Z,Nmeas=N,PI=...,Email=..."
//   line 2  "Level 1.5 Almucantar Retrievals, Version 2" (level and version)
//   line 3  "Phase Functions - Total Mode,..." (the product)
//   line 4  column names: Date(dd-mm-yyyy), Time(hh:mm:ss), Julian_Day, then "ANGLE[WLnm]" for
//           every scattering angle (degrees) at every wavelength (nm), then retrieval metadata,
//           among them alpha440-870 (Angstrom exponent between 440 and 870 nm) and
//           tau440(measured) (aerosol optical depth at 440 nm), and albedo_440 .. albedo-1020
//           (the SURFACE albedo the inversion used, not the aerosols' single-scattering
//           albedo, which AERONET publishes in a separate product, ".ssa")
//   line 5+ one retrieval per line, times in UTC
//
// Phase functions are normalised by AERONET so that (1/2) int P(theta) sin(theta) dtheta = 1.
// Missing values are written -999. What this reader refuses, each with an InvalidInput whose
// field is "inversion" and whose reason names the line (1-based), and the column when it is a
// value: an empty or truncated file, another product or layout (the header lines), a wavelength
// with another number of angles or other angles than the first, fewer than 10 angles, angles
// that do not increase from 0 to 180 degrees, a retrieval line with more or fewer fields than
// the header, an empty field or one that is not a number or not finite (nan, inf, overflow) in
// a value the models use, -999 in such a value (a phase-function value, tau440(measured),
// alpha440-870), a date or time that is not one, retrievals of more than one day or whose times
// do not increase (retrieval_time_utc_h of models/measured_aerosols picks among one day's
// retrievals by time), a file with no retrieval. Other columns may hold -999 or be empty. Pure
// function of the text; thread-safe.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace clearsky::aeronet {

struct PhaseFunctionRetrieval {
  std::string date;             // as written, dd:mm:yyyy
  std::string time;             // as written, hh:mm:ss (UTC)
  double time_utc_h = 0;        // hours since midnight UTC
  double aod_440 = 0;           // tau440(measured)
  double angstrom_440_870 = 0;  // alpha440-870
  // phase[w][a]: at wavelengths_nm[w] and angles_deg[a] of the file, AERONET's normalisation.
  std::vector<std::vector<double>> phase;
  // Aerosol optical depth at a wavelength by the Angstrom law through tau440 and alpha440-870.
  double aod_at(double wavelength_nm) const;
};

struct PhaseFunctionFile {
  std::string site;                                // Locations=
  double latitude_deg = 0;                         // lat=
  double longitude_deg = 0;                        // long=
  std::string level;                               // "Level 1.5 Almucantar Retrievals, Version 2"
  std::vector<double> wavelengths_nm;              // increasing, from the column names
  std::vector<double> angles_deg;                  // the same for every wavelength, 0 .. 180
  std::vector<PhaseFunctionRetrieval> retrievals;  // in file order, times increasing
  std::string first_day;                           // ISO 8601 yyyy-mm-dd of the first retrieval
  std::string last_day;                            // and of the last (the same day today)
  std::uint64_t content_hash = 0;  // FNV-1a of the whole text (models/core/content_hash.h)
};

// Throws InvalidInput (field "inversion") as described above.
PhaseFunctionFile parse_phase_function_file(std::string_view text);

}  // namespace clearsky::aeronet
