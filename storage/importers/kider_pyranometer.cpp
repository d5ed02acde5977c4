// The Kider et al. 2014 pyranometer records (kider_pyranometer.h).
#include "storage/importers/kider_pyranometer.h"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace clearsky::storage {
namespace {

constexpr const char* kDayFileName = "pyranometer_full_day.txt";

// "YYYY.MM.DD.HH.MM.SS" or "YYYY-MM-DDThh:mm:ss" as local time to unix seconds.
std::optional<double> local_clock_to_utc_s(const std::string& text, int utc_offset_minutes) {
  std::tm local{};
  char a = 0, b = 0, c = 0, d = 0, e = 0;
  std::istringstream in(text);
  in >> local.tm_year >> a >> local.tm_mon >> b >> local.tm_mday >> c >> local.tm_hour >> d >>
      local.tm_min >> e >> local.tm_sec;
  const bool dotted = a == '.' && b == '.' && c == '.' && d == '.' && e == '.';
  const bool iso = a == '-' && b == '-' && c == 'T' && d == ':' && e == ':';
  if (in.fail() || !(dotted || iso) || in.peek() != std::char_traits<char>::eof()) return {};
  if (local.tm_mon < 1 || local.tm_mon > 12 || local.tm_mday < 1 || local.tm_mday > 31 ||
      local.tm_hour > 23 || local.tm_min > 59 || local.tm_sec > 59)
    return {};
  local.tm_year -= 1900;
  local.tm_mon -= 1;
  return static_cast<double>(timegm(&local)) - utc_offset_minutes * 60.0;
}

IrradianceSample sample_at(double time_utc_s, double ghi_w_m2, const KiderImportOptions& options) {
  IrradianceSample sample;
  sample.time_utc_s = time_utc_s;
  sample.utc_offset_minutes = options.utc_offset_minutes;
  sample.latitude_deg = options.site.latitude_deg;
  sample.longitude_deg = options.site.longitude_deg;
  sample.elevation_m = options.site.elevation_m;
  sample.ghi_w_m2 = ghi_w_m2;
  return sample;
}

std::invalid_argument malformed(const std::filesystem::path& file, int line,
                                const std::string& why) {
  return std::invalid_argument(file.filename().string() + ", line " + std::to_string(line) + ": " +
                               why);
}

// Rows "value  YYYY.MM.DD.HH.MM.SS" (CRLF or LF; blank lines skipped).
std::vector<IrradianceSample> read_capture_file(const std::filesystem::path& file,
                                                const KiderImportOptions& options) {
  std::ifstream in(file);
  if (!in) throw std::invalid_argument(file.filename().string() + ": cannot be read");
  std::vector<IrradianceSample> samples;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    std::istringstream row(line);
    double value = 0;
    std::string clock;
    if (!(row >> value)) {
      if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
      throw malformed(file, number, "no value");
    }
    if (!(row >> clock)) throw malformed(file, number, "no YYYY.MM.DD.HH.MM.SS clock");
    const auto time = local_clock_to_utc_s(clock, options.utc_offset_minutes);
    if (!time) throw malformed(file, number, "'" + clock + "' is not a YYYY.MM.DD.HH.MM.SS clock");
    if (!std::isfinite(value)) throw malformed(file, number, "value not finite");
    samples.push_back(sample_at(*time, value, options));
  }
  return samples;
}

struct DayRecord {
  double minutes = 0;
  double ghi_w_m2 = 0;
};

std::vector<DayRecord> read_day_file(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::invalid_argument(file.filename().string() + ": cannot be read");
  std::vector<DayRecord> records;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::istringstream row(line);
    DayRecord record;
    if (!(row >> record.minutes >> record.ghi_w_m2) || !std::isfinite(record.minutes) ||
        !std::isfinite(record.ghi_w_m2))
      throw malformed(file, number, "not an 'offset value' row");
    if (!records.empty() && record.minutes < records.back().minutes)
      throw malformed(file, number, "offset before the previous row's");
    records.push_back(record);
  }
  if (records.empty()) throw std::invalid_argument(file.filename().string() + ": no records");
  return records;
}

bool is_capture_file_name(const std::filesystem::path& file) {
  return file.extension() == ".txt" && local_clock_to_utc_s(file.stem().string(), 0).has_value();
}

void collect(const std::filesystem::path& path, std::vector<std::filesystem::path>& capture_files,
             std::vector<std::filesystem::path>& day_files) {
  if (std::filesystem::is_directory(path)) {
    std::vector<std::filesystem::path> entries;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(path))
      if (entry.is_regular_file()) entries.push_back(entry.path());
    std::sort(entries.begin(), entries.end());
    for (const auto& entry : entries) {
      if (entry.filename() == kDayFileName)
        day_files.push_back(entry);
      else if (is_capture_file_name(entry))
        capture_files.push_back(entry);
    }
    return;
  }
  if (path.filename() == kDayFileName)
    day_files.push_back(path);
  else
    capture_files.push_back(path);
}

}  // namespace

KiderPyranometerRead read_kider_pyranometer(const std::vector<std::filesystem::path>& paths,
                                            const KiderImportOptions& options,
                                            const std::optional<std::string>& first_record_local) {
  std::vector<std::filesystem::path> capture_files, day_files;
  for (const auto& path : paths) collect(path, capture_files, day_files);
  if (capture_files.empty() && day_files.empty())
    throw std::invalid_argument("no pyranometer file (YYYY.MM.DD.HH.MM.SS.txt or " +
                                std::string(kDayFileName) + ")");
  if (day_files.size() > 1)
    throw std::invalid_argument("more than one " + std::string(kDayFileName));

  KiderPyranometerRead read;
  std::vector<IrradianceSample> capture_samples;
  for (const auto& file : capture_files) {
    auto samples = read_capture_file(file, options);
    capture_samples.insert(capture_samples.end(), samples.begin(), samples.end());
  }
  std::stable_sort(capture_samples.begin(), capture_samples.end(),
                   [](const auto& a, const auto& b) { return a.time_utc_s < b.time_utc_s; });
  read.notes.push_back(std::to_string(capture_files.size()) + " per-capture files, " +
                       std::to_string(capture_samples.size()) + " records");
  if (day_files.empty()) {
    read.samples = std::move(capture_samples);
    return read;
  }

  const std::vector<DayRecord> day = read_day_file(day_files.front());
  double first_utc_s = 0;
  if (first_record_local) {
    const auto parsed = local_clock_to_utc_s(*first_record_local, options.utc_offset_minutes);
    if (!parsed)
      throw std::invalid_argument("first record's clock '" + *first_record_local +
                                  "' is neither YYYY.MM.DD.HH.MM.SS nor YYYY-MM-DDThh:mm:ss");
    first_utc_s = *parsed;
    read.notes.push_back("day file's first record at the clock given");
  } else if (!capture_samples.empty()) {
    // The day file starts with the first capture's records: the same values, 4 s apart.
    const IrradianceSample& first = capture_samples.front();
    if (*first.ghi_w_m2 != day.front().ghi_w_m2)
      throw std::invalid_argument(
          std::string(kDayFileName) + ": its first record (" +
          std::to_string(day.front().ghi_w_m2) + " W/m2) is not the earliest per-capture record (" +
          std::to_string(*first.ghi_w_m2) + " W/m2): give the first record's clock");
    first_utc_s = first.time_utc_s;
    read.notes.push_back("day file's first record at the earliest per-capture record's clock");
  } else {
    throw std::invalid_argument(std::string(kDayFileName) +
                                " gives no clock: give its first record's local time, or the "
                                "per-capture files with it");
  }
  for (const DayRecord& record : day)
    read.samples.push_back(
        sample_at(first_utc_s + record.minutes * 60.0, record.ghi_w_m2, options));
  read.notes.push_back(std::to_string(day.size()) + " day-file records over " +
                       std::to_string(day.back().minutes) + " minutes");
  return read;
}

}  // namespace clearsky::storage
