// Latitude and longitude from decimal or DMS text through GeographicLib::DMS (coordinates.h).
#include "api/parse/coordinates.h"

#include <GeographicLib/Constants.hpp>
#include <GeographicLib/DMS.hpp>
#include <charconv>
#include <cmath>
#include <optional>

#include "api/error/api_error.h"

namespace clearsky::api {
namespace {

using GeographicLib::DMS;

std::string quoted(std::string_view text) { return '"' + std::string(text) + '"'; }

// GeographicLib 2.1 (Debian 12) reads a ':' that follows a seconds component (4"1:1, or a
// fourth colon) as a fourth component and writes past its 3-element arrays: the process
// crashes (found by fuzz/coordinates_fuzz.cpp). The colon notation is D:M or D:M:S, so text
// with a colon is handed over only in that form: at most two colons, and besides them only
// digits, a decimal point, signs, spaces and hemisphere letters (no d, ', " or their
// Unicode forms, which it would count as components too).
bool safe_for_dms(std::string_view text) {
  if (text.find(':') == std::string_view::npos) return true;
  int colons = 0;
  for (const char c : text) {
    if (c == ':') {
      ++colons;
    } else if (!((c >= '0' && c <= '9') || c == '.' || c == '+' || c == '-' || c == ' ' ||
                 std::string_view("NSEWnsew").find(c) != std::string_view::npos)) {
      return false;
    }
  }
  return colons <= 2;
}

// The whole text (spaces around it aside) as a decimal number, exponent included ("1e-05", as
// a JSON body's small numbers are written): GeographicLib reads the 'e' of an exponent as the
// East hemisphere and the exponent's sign as a second term, so "1e-05" would be 1 - 5 = -4
// degrees East (found by fuzz/coordinates_fuzz.cpp). nullopt when it is not one number.
std::optional<double> plain_decimal(std::string_view text) {
  const std::size_t first = text.find_first_not_of(' ');
  if (first == std::string_view::npos) return std::nullopt;
  text = text.substr(first, text.find_last_not_of(' ') - first + 1);
  if (text.starts_with('+')) text.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

// A mantissa digit followed by an exponent ("2e-3", "1.5E+01"): meant as a number, never as
// degrees and a hemisphere.
bool has_exponent(std::string_view text) {
  for (std::size_t i = 1; i + 1 < text.size(); ++i) {
    const char before = text[i - 1], after = text[i + 1];
    if ((text[i] == 'e' || text[i] == 'E') && ((before >= '0' && before <= '9') || before == '.') &&
        ((after >= '0' && after <= '9') || after == '-' || after == '+'))
      return true;
  }
  return false;
}

// Finite and within [-limit_deg, limit_deg].
double in_range(double degrees, const std::string& parameter, const std::string& shown,
                double limit_deg) {
  if (!std::isfinite(degrees))
    throw invalid_parameter(parameter, "must be a finite angle, got " + shown);
  if (!(std::abs(degrees) <= limit_deg)) {
    const std::string range = limit_deg == 90.0 ? "[-90, 90]" : "[-180, 180]";
    throw invalid_parameter(parameter, "must be in " + range + " degrees, got " + shown);
  }
  return degrees;
}

double decode_angle(std::string_view text, const std::string& parameter, DMS::flag wanted,
                    double limit_deg) {
  const std::string shown = quoted(text);
  if (const std::optional<double> decimal = plain_decimal(text))
    return in_range(*decimal, parameter, shown, limit_deg);
  if (has_exponent(text))
    throw invalid_parameter(parameter, "expected decimal degrees or degrees-minutes-seconds, got " +
                                           shown + " (an exponent is for a plain number only)");
  if (!safe_for_dms(text))
    throw invalid_parameter(parameter, "expected decimal degrees or degrees-minutes-seconds, got " +
                                           shown + " (the colon form is D:M or D:M:S)");
  DMS::flag hemisphere = DMS::NONE;
  double degrees = 0.0;
  try {
    degrees = DMS::Decode(std::string(text), hemisphere);
  } catch (const GeographicLib::GeographicErr& e) {
    throw invalid_parameter(parameter, "expected decimal degrees or degrees-minutes-seconds, got " +
                                           shown + " (" + e.what() + ")");
  }
  if (hemisphere != DMS::NONE && hemisphere != wanted) {
    throw invalid_parameter(parameter,
                            std::string("the hemisphere of ") + shown + " belongs to a " +
                                (wanted == DMS::LATITUDE ? "longitude (E/W)" : "latitude (N/S)"));
  }
  return in_range(degrees, parameter, shown, limit_deg);
}

}  // namespace

double parse_latitude(std::string_view text, const std::string& parameter) {
  return decode_angle(text, parameter, DMS::LATITUDE, 90.0);
}

double parse_longitude(std::string_view text, const std::string& parameter) {
  return decode_angle(text, parameter, DMS::LONGITUDE, 180.0);
}

}  // namespace clearsky::api
