// Parsing of the Kider et al. 2014 format (kider_format.h).
#include "storage/importers/kider_format.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <ctime>
#include <regex>

#include "models/core/numeric.h"

namespace clearsky::storage {
namespace {

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r\n");
  return s.substr(first, last - first + 1);
}

// The next whitespace-separated token of s, advancing s past it.
std::string_view next_token(std::string_view& s) {
  const auto begin = s.find_first_not_of(" \t");
  if (begin == std::string_view::npos) {
    s = {};
    return {};
  }
  const auto end = s.find_first_of(" \t", begin);
  const std::string_view token = s.substr(begin, end == std::string_view::npos ? s.size() - begin : end - begin);
  s = end == std::string_view::npos ? std::string_view{} : s.substr(end);
  return token;
}

std::optional<double> parse_number(std::string_view token) {
  double value = 0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (error != std::errc{} || end != token.data() + token.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

}  // namespace

KiderFormatError::KiderFormatError(const std::string& source, long line, const std::string& what)
    : std::runtime_error(source + ":" + std::to_string(line) + ": " + what), source_(source), line_(line) {}

std::optional<KiderFileName> parse_kider_file_name(std::string_view base_name) {
  static const std::regex pattern(
      R"(^((\d{4})-(\d{2})-(\d{2})___(\d{2})\.(\d{2})\.(\d{2}))_-_(\d+)____(-?\d+(?:\.\d+)?)___(-?\d+(?:\.\d+)?)\.asd\.rad\.txt$)");
  std::match_results<std::string_view::const_iterator> m;
  if (!std::regex_match(base_name.begin(), base_name.end(), m, pattern)) return std::nullopt;
  KiderFileName name;
  name.capture_label = m[1].str();
  name.year = std::stoi(m[2].str());
  name.month = std::stoi(m[3].str());
  name.day = std::stoi(m[4].str());
  name.hour = std::stoi(m[5].str());
  name.minute = std::stoi(m[6].str());
  name.second = std::stoi(m[7].str());
  name.index = std::stoi(m[8].str());
  name.azimuth_ccw_deg = std::stod(m[9].str());
  name.elevation_deg = std::stod(m[10].str());
  if (name.month < 1 || name.month > 12 || name.day < 1 || name.day > 31 || name.hour > 23 ||
      name.minute > 59 || name.second > 60 || name.elevation_deg < 0 || name.elevation_deg > 90)
    return std::nullopt;
  return name;
}

ViewDirection kider_view_direction(double azimuth_ccw_deg, double elevation_deg) {
  double clockwise_deg = std::fmod(360.0 - azimuth_ccw_deg, 360.0);
  if (clockwise_deg < 0) clockwise_deg += 360.0;
  return {(90.0 - elevation_deg) * kDegree, clockwise_deg * kDegree};
}

TabulatedSpectrum read_kider_spectrum(std::istream& in, const std::string& source) {
  std::string line;
  long line_number = 0;
  if (!std::getline(in, line)) throw KiderFormatError(source, 1, "empty file (expected a header line)");
  ++line_number;
  {
    std::string_view header = trim(line);
    std::string_view probe = header;
    if (header.empty() || parse_number(next_token(probe)))
      throw KiderFormatError(source, line_number, "expected a header line, found '" + std::string(header) + "'");
  }
  std::vector<double> wavelengths, values;
  wavelengths.reserve(2151);
  values.reserve(2151);
  long last_data_line = line_number;
  while (std::getline(in, line)) {
    ++line_number;
    std::string_view rest = trim(line);
    if (rest.empty()) continue;
    const std::string_view w_token = next_token(rest);
    const std::string_view v_token = next_token(rest);
    const auto w = parse_number(w_token);
    const auto v = v_token.empty() ? std::nullopt : parse_number(v_token);
    if (!w || !v || !next_token(rest).empty())
      throw KiderFormatError(source, line_number,
                             "expected two numbers 'wavelength_nm radiance', found '" + std::string(trim(line)) + "'");
    if (!wavelengths.empty() && !(*w > wavelengths.back()))
      throw KiderFormatError(source, line_number, "wavelength " + std::string(w_token) + " nm does not increase");
    wavelengths.push_back(*w);
    values.push_back(*v);
    last_data_line = line_number;
  }
  if (in.bad()) throw KiderFormatError(source, line_number, "read error");
  if (wavelengths.empty() || wavelengths.front() > kKiderFirstWavelengthNm ||
      wavelengths.back() < kKiderLastWavelengthNm) {
    const std::string found = wavelengths.empty()
                                  ? std::string("no data rows")
                                  : "rows cover " + std::to_string(wavelengths.front()) + ".." +
                                        std::to_string(wavelengths.back()) + " nm";
    throw KiderFormatError(source, last_data_line, "short file: " + found + ", expected 350..2500 nm");
  }
  return TabulatedSpectrum(std::move(wavelengths), std::move(values));
}

MeasuredCapture assemble_kider_capture(std::vector<KiderSampleFile> files, const KiderImportOptions& options) {
  if (files.empty()) throw std::invalid_argument("a Kider capture needs its 81 files, none given");
  const std::string label = files.front().name.capture_label;
  std::sort(files.begin(), files.end(),
            [](const KiderSampleFile& a, const KiderSampleFile& b) { return a.name.index < b.name.index; });
  for (std::size_t i = 0; i < files.size(); ++i) {
    const KiderSampleFile& f = files[i];
    if (f.name.capture_label != label)
      throw std::invalid_argument("capture " + label + ": file " + f.source + " belongs to capture " + f.name.capture_label);
    if (i > 0 && files[i - 1].name.index == f.name.index)
      throw std::invalid_argument("capture " + label + ": sample " + std::to_string(f.name.index) +
                                  " appears twice (" + files[i - 1].source + ", " + f.source + ")");
  }
  std::vector<int> missing;
  for (int index = 0; index < kKiderSampleCount; ++index) {
    if (!std::any_of(files.begin(), files.end(), [&](const KiderSampleFile& f) { return f.name.index == index; }))
      missing.push_back(index);
  }
  if (!missing.empty() || files.size() != kKiderSampleCount) {
    std::string list;
    for (std::size_t i = 0; i < missing.size() && i < 10; ++i) list += (i ? ", " : "") + std::to_string(missing[i]);
    throw std::invalid_argument("capture " + label + ": has " + std::to_string(files.size()) +
                                " sample files, expected the 81 scan indices 0..80" +
                                (missing.empty() ? std::string() : "; missing " + list));
  }

  MeasuredCapture capture;
  capture.label = label;
  capture.site = options.site;
  capture.utc_offset_minutes = options.utc_offset_minutes;
  const KiderFileName& n = files.front().name;
  std::tm local{};
  local.tm_year = n.year - 1900;
  local.tm_mon = n.month - 1;
  local.tm_mday = n.day;
  local.tm_hour = n.hour;
  local.tm_min = n.minute;
  local.tm_sec = n.second;
  capture.unix_time_utc_s = static_cast<double>(timegm(&local)) - options.utc_offset_minutes * 60.0;
  capture.samples.reserve(files.size());
  for (KiderSampleFile& f : files) {
    MeasuredSample sample;
    sample.index = f.name.index;
    sample.view = kider_view_direction(f.name.azimuth_ccw_deg, f.name.elevation_deg);
    sample.radiance = std::move(f.radiance);
    // Sample 0 (North, lowest ring) is systematically wrong in Kider's data.
    if (sample.index == 0) sample.quality_flags |= kSampleKnownDefective;
    capture.samples.push_back(std::move(sample));
  }
  return capture;
}

}  // namespace clearsky::storage
