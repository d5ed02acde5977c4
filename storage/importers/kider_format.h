// The Kider et al. 2014 measurement format (Kider et al. 2014, ACM TOG 33(6)): one capture
// is 81 text files named DATE___HH.MM.SS_-_INDEX____AZIMUTH___ELEVATION.asd.rad.txt, each a
// header line then "wavelength_nm radiance" rows, 350..2500 nm every 1 nm, W/(m2.sr.nm).
// AZIMUTH is counter-clockwise from North and ELEVATION above the horizon, both in degrees;
// kider_view_direction() is the one place that converts them to the project's convention.
// Parsing reads streams (no file access here); errors name the source and the line.
#pragma once

#include <istream>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "models/evaluation/measured_sky.h"

namespace clearsky::storage {

// A malformed or short Kider file: the message reads "SOURCE:LINE: what is wrong".
class KiderFormatError : public std::runtime_error {
 public:
  KiderFormatError(const std::string& source, long line, const std::string& what);
  const std::string& source() const { return source_; }
  long line() const { return line_; }

 private:
  std::string source_;
  long line_;
};

struct KiderFileName {
  std::string capture_label;                                           // "2013-05-27___09.30.00"
  int year = 0, month = 0, day = 0, hour = 0, minute = 0, second = 0;  // local time of the site
  int index = 0;                                                       // scan index 0..80
  double azimuth_ccw_deg = 0;  // as written: counter-clockwise from North
  double elevation_deg = 0;    // above the horizon
};

// Decodes a file's base name; nullopt when it is not a Kider .asd.rad.txt name (the archives
// also hold raw .asd.txt files, which are ignored).
std::optional<KiderFileName> parse_kider_file_name(std::string_view base_name);

// The sample direction of a Kider file name: zenith = 90 - elevation, clockwise azimuth =
// 360 - counter-clockwise azimuth (radians, in [0, 2 pi)).
ViewDirection kider_view_direction(double azimuth_ccw_deg, double elevation_deg);

// First and last wavelength rows of a complete Kider spectrum.
constexpr double kKiderFirstWavelengthNm = 350.0;
constexpr double kKiderLastWavelengthNm = 2500.0;

// Reads one .asd.rad.txt spectrum. Throws KiderFormatError for a missing header, a row that is
// not two finite numbers, non-increasing wavelengths, or a file that does not cover
// 350..2500 nm (a short file is reported at its last line).
TabulatedSpectrum read_kider_spectrum(std::istream& in, const std::string& source);

// One decoded file of a capture.
struct KiderSampleFile {
  std::string source;  // where it came from, for messages
  KiderFileName name;
  TabulatedSpectrum radiance;
};

struct KiderImportOptions {
  SiteLocation site = kider_cornell_site();
  int utc_offset_minutes = -240;  // the file names give local time; Kider's site: EDT = UTC-4
};

// Assembles the files of one capture: exactly the scan indices 0..80 once each, ordered by
// index; sample 0 (North, lowest ring) is flagged kSampleKnownDefective (kept as measured).
// Throws std::invalid_argument naming the capture when samples are missing or repeated.
MeasuredCapture assemble_kider_capture(std::vector<KiderSampleFile> files,
                                       const KiderImportOptions& options);

constexpr int kKiderSampleCount = 81;

}  // namespace clearsky::storage
