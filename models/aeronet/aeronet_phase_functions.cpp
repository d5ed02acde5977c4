// Parsing of the AERONET phase-function inversion file (aeronet_phase_functions.h).
#include "models/aeronet/aeronet_phase_functions.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>

#include "models/core/content_hash.h"
#include "models/core/invalid_input.h"

namespace clearsky::aeronet {

namespace {

constexpr double kMissing = -999.0;
// Fewer angles than this cannot resolve the forward peak the tables interpolate (AERONET
// publishes 83 per wavelength, models/data/aeronet).
constexpr std::size_t kMinimumAngles = 10;

[[noreturn]] void refuse(std::size_t line, const std::string& reason) {
  throw InvalidInput("inversion", "line " + std::to_string(line) + ": " + reason);
}

std::vector<std::string_view> split_lines(std::string_view text) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    lines.push_back(line);
    start = end + 1;
  }
  while (!lines.empty() && lines.back().empty()) lines.pop_back();
  return lines;
}

std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(line.substr(start, comma == std::string_view::npos ? comma : comma - start));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return fields;
}

std::optional<double> to_number(std::string_view s) {
  double v = 0.0;
  const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (error != std::errc{} || end != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

// from_chars reads "nan", "inf" and "infinity" (any case) and overflowing decimals as numbers
// that are not finite; the refusal says so rather than "not a number" for a number that overflows.
bool non_finite(std::string_view s) {
  double v = 0.0;
  const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (end != s.data() + s.size() || s.empty()) return false;
  return error == std::errc::result_out_of_range || (error == std::errc{} && !std::isfinite(v));
}

// "dd:mm:yyyy" (AERONET writes the retrieval day with colons whatever the column name says) to
// a sortable yyyymmdd, else nothing.
std::optional<int> day_number(std::string_view s) {
  if (s.size() != 10 || s[2] != ':' || s[5] != ':') return std::nullopt;
  const auto d = to_number(s.substr(0, 2));
  const auto m = to_number(s.substr(3, 2));
  const auto y = to_number(s.substr(6, 4));
  if (!d || !m || !y || *d < 1 || *d > 31 || *m < 1 || *m > 12 || *y < 1900) return std::nullopt;
  return static_cast<int>(*y) * 10000 + static_cast<int>(*m) * 100 + static_cast<int>(*d);
}

// yyyymmdd to ISO 8601 "yyyy-mm-dd".
std::string iso_day(int day) {
  char text[16];
  std::snprintf(text, sizeof text, "%04d-%02d-%02d", day / 10000, day / 100 % 100, day % 100);
  return text;
}

// "KEY=value" among the fields of line 1.
std::string_view header_value(const std::vector<std::string_view>& fields, std::string_view key) {
  for (std::string_view f : fields)
    if (f.size() > key.size() && f.substr(0, key.size()) == key && f[key.size()] == '=')
      return f.substr(key.size() + 1);
  return {};
}

// "hh:mm:ss" to hours.
std::optional<double> hours(std::string_view s) {
  if (s.size() != 8 || s[2] != ':' || s[5] != ':') return std::nullopt;
  const auto h = to_number(s.substr(0, 2));
  const auto m = to_number(s.substr(3, 2));
  const auto sec = to_number(s.substr(6, 2));
  if (!h || !m || !sec || *h > 23 || *m > 59 || *sec > 60) return std::nullopt;
  return *h + *m / 60.0 + *sec / 3600.0;
}

// "ANGLE[WLnm]": angle and wavelength, else nothing.
std::optional<std::pair<double, double>> phase_column(std::string_view name) {
  const std::size_t open = name.find('[');
  if (open == std::string_view::npos || name.size() < open + 4 ||
      name.substr(name.size() - 3) != "nm]")
    return std::nullopt;
  const auto angle = to_number(name.substr(0, open));
  const auto wavelength = to_number(name.substr(open + 1, name.size() - open - 4));
  if (!angle || !wavelength) return std::nullopt;
  return std::make_pair(*angle, *wavelength);
}

}  // namespace

double PhaseFunctionRetrieval::aod_at(double wavelength_nm) const {
  return aod_440 * std::pow(wavelength_nm / 440.0, -angstrom_440_870);
}

PhaseFunctionFile parse_phase_function_file(std::string_view text) {
  PhaseFunctionFile file;
  file.content_hash = fnv1a_64(text);
  const std::vector<std::string_view> lines = split_lines(text);
  if (lines.size() < 4) refuse(lines.size() + 1, "truncated: the four header lines are missing");
  const std::vector<std::string_view> site = split_fields(lines[0]);
  file.site = std::string(header_value(site, "Locations"));
  const auto latitude = to_number(header_value(site, "lat"));
  const auto longitude = to_number(header_value(site, "long"));
  if (file.site.empty() || !latitude || !longitude)
    refuse(1, "not an AERONET inversion header (Locations=, long=, lat= expected)");
  file.latitude_deg = *latitude;
  file.longitude_deg = *longitude;
  if (lines[1].find("Almucantar Retrievals") == std::string_view::npos)
    refuse(2,
           "not an AERONET almucantar retrieval (\"Level ... Almucantar Retrievals, Version "
           "...\" expected)");
  file.level = std::string(lines[1]);
  if (lines[2].substr(0, 15) != "Phase Functions")
    refuse(3,
           "not a phase-function product (\"Phase Functions ...\" expected; SSA, size "
           "distribution and other inversion products are other files)");

  const std::vector<std::string_view> names = split_fields(lines[3]);
  if (names.size() < 3 || names[0] != "Date(dd-mm-yyyy)" || names[1] != "Time(hh:mm:ss)")
    refuse(4, "column names Date(dd-mm-yyyy),Time(hh:mm:ss),... expected");
  // Phase columns grouped by wavelength, angles in file order.
  std::map<double, std::vector<std::pair<double, std::size_t>>> by_wavelength;
  std::optional<std::size_t> aod_column, alpha_column;
  for (std::size_t c = 0; c < names.size(); ++c) {
    if (const auto pc = phase_column(names[c])) by_wavelength[pc->second].push_back({pc->first, c});
    if (names[c] == "tau440(measured)") aod_column = c;
    if (names[c] == "alpha440-870") alpha_column = c;
  }
  if (by_wavelength.empty()) refuse(4, "no phase-function column (\"ANGLE[WLnm]\")");
  if (!aod_column) refuse(4, "column tau440(measured) missing");
  if (!alpha_column) refuse(4, "column alpha440-870 missing");
  for (const auto& [wavelength, columns] : by_wavelength) {
    std::vector<double> angles;
    for (const auto& [angle, column] : columns) angles.push_back(angle);
    if (file.angles_deg.empty()) file.angles_deg = angles;
    if (!(wavelength > 0.0))
      refuse(4, "phase-function wavelength " + std::to_string(wavelength) + " nm is not positive");
    if (angles.size() != file.angles_deg.size())
      refuse(4, std::to_string(angles.size()) + " phase-function angles at " +
                    std::to_string(wavelength) + " nm where " +
                    std::to_string(file.wavelengths_nm[0]) + " nm has " +
                    std::to_string(file.angles_deg.size()));
    if (angles != file.angles_deg)
      refuse(4, "the phase functions at " + std::to_string(wavelength) +
                    " nm have other angles than at " + std::to_string(file.wavelengths_nm[0]) +
                    " nm");
    file.wavelengths_nm.push_back(wavelength);
  }
  if (file.angles_deg.size() < kMinimumAngles)
    refuse(4, std::to_string(file.angles_deg.size()) + " phase-function angles per wavelength, " +
                  std::to_string(kMinimumAngles) + " at least expected");
  if (file.angles_deg.front() != 0.0 || file.angles_deg.back() != 180.0)
    refuse(4, "phase-function angles must run from 0 to 180 degrees");
  for (std::size_t a = 1; a < file.angles_deg.size(); ++a)
    if (!(file.angles_deg[a] > file.angles_deg[a - 1]))
      refuse(4, "phase-function angles must increase");

  for (std::size_t l = 4; l < lines.size(); ++l) {
    const std::size_t line_number = l + 1;
    const std::vector<std::string_view> fields = split_fields(lines[l]);
    if (fields.size() != names.size())
      refuse(line_number, std::to_string(fields.size()) + " fields where the header names " +
                              std::to_string(names.size()) + " (truncated line?)");
    auto value = [&](std::size_t column) {
      const auto v = to_number(fields[column]);
      if (!v && non_finite(fields[column]))
        refuse(line_number, "column " + std::string(names[column]) + ": \"" +
                                std::string(fields[column]) + "\" is not finite");
      if (fields[column].empty())
        refuse(line_number, "column " + std::string(names[column]) + " is empty (missing value)");
      if (!v)
        refuse(line_number, "column " + std::string(names[column]) + ": \"" +
                                std::string(fields[column]) + "\" is not a number");
      if (*v == kMissing)
        refuse(line_number, "column " + std::string(names[column]) + " is missing (-999)");
      return *v;
    };
    PhaseFunctionRetrieval r;
    r.date = std::string(fields[0]);
    r.time = std::string(fields[1]);
    const auto day = day_number(fields[0]);
    if (!day) refuse(line_number, "column Date(dd-mm-yyyy): \"" + r.date + "\" is not a date");
    const auto t = hours(fields[1]);
    if (!t) refuse(line_number, "column Time(hh:mm:ss): \"" + r.time + "\" is not a time");
    r.time_utc_h = *t;
    // retrieval_time_utc_h selects a retrieval by the hour of one day: a file of several days
    // would make that choice ambiguous, and retrievals out of order or twice at one time too.
    if (!file.retrievals.empty()) {
      const PhaseFunctionRetrieval& previous = file.retrievals.back();
      if (r.date != previous.date)
        refuse(line_number, "retrievals of several days (" + previous.date + " and " + r.date +
                                "): one day per file");
      if (!(r.time_utc_h > previous.time_utc_h))
        refuse(line_number, "retrieval time " + r.time + " is not after the previous one (" +
                                previous.time + ")");
    } else {
      file.first_day = iso_day(*day);
    }
    file.last_day = iso_day(*day);
    r.aod_440 = value(*aod_column);
    r.angstrom_440_870 = value(*alpha_column);
    if (!(r.aod_440 > 0.0)) refuse(line_number, "column tau440(measured) must be positive");
    for (const auto& [wavelength, columns] : by_wavelength) {
      std::vector<double> phase;
      for (const auto& [angle, column] : columns) {
        const double v = value(column);
        if (!(v > 0.0))
          refuse(line_number, "column " + std::string(names[column]) + " must be positive");
        phase.push_back(v);
      }
      r.phase.push_back(std::move(phase));
    }
    file.retrievals.push_back(std::move(r));
  }
  if (file.retrievals.empty())
    refuse(lines.size() + 1, "no retrieval (the file ends after its header)");
  return file;
}

}  // namespace clearsky::aeronet
