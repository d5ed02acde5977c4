// Keys of the samples an evaluation run compared (compared_samples.h).
#include "storage/repositories/compared_samples.h"

#include <sqlite3.h>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <stdexcept>

#include "models/core/content_hash.h"

namespace clearsky::storage {
namespace {

std::string hex_key(std::string_view joined) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(fnv1a_64(joined)));
  return text;
}

void compared_samples_key_sql(sqlite3_context* context, int, sqlite3_value** arguments) {
  const unsigned char* text = sqlite3_value_text(arguments[0]);
  const std::string key =
      hex_key(text == nullptr ? std::string_view() : reinterpret_cast<const char*>(text));
  sqlite3_result_text(context, key.c_str(), static_cast<int>(key.size()), SQLITE_TRANSIENT);
}

std::vector<std::string_view> split(std::string_view text, char separator) {
  std::vector<std::string_view> parts;
  if (text.empty()) return parts;
  for (std::size_t start = 0;;) {
    const std::size_t end = text.find(separator, start);
    parts.push_back(text.substr(start, end - start));
    if (end == std::string_view::npos) return parts;
    start = end + 1;
  }
}

}  // namespace

std::string encode_sample_handling(const std::vector<SampleHandling>& entries) {
  std::string text;
  for (const SampleHandling& e : entries) {
    if (e.indices.empty()) continue;
    if (!text.empty()) text += ';';
    text += e.handling + ' ' + e.reason + ' ';
    for (std::size_t i = 0; i < e.indices.size(); ++i)
      text += (i == 0 ? "" : ",") + std::to_string(e.indices[i]);
  }
  return text;
}

std::vector<SampleHandling> decode_sample_handling(std::string_view text) {
  std::vector<SampleHandling> entries;
  for (const std::string_view entry : split(text, ';')) {
    const std::vector<std::string_view> fields = split(entry, ' ');
    if (fields.size() != 3 || (fields[0] != "excluded" && fields[0] != "clamped"))
      throw std::runtime_error("stored sample handling is not readable: " + std::string(entry));
    SampleHandling e{std::string(fields[0]), std::string(fields[1]), {}};
    for (const std::string_view number : split(fields[2], ',')) {
      std::int32_t index = 0;
      const auto [end, error] =
          std::from_chars(number.data(), number.data() + number.size(), index);
      if (error != std::errc() || end != number.data() + number.size())
        throw std::runtime_error("stored sample handling is not readable: " + std::string(entry));
      e.indices.push_back(index);
    }
    entries.push_back(std::move(e));
  }
  return entries;
}

std::string compared_samples_key(std::vector<std::pair<std::string, std::string>> captures) {
  std::sort(captures.begin(), captures.end());
  std::string joined;
  for (std::size_t i = 0; i < captures.size(); ++i)
    joined += (i == 0 ? "" : "\n") + captures[i].first + '\t' + captures[i].second;
  return hex_key(joined);
}

void register_compared_samples_key(Database& db) {
  const int code = sqlite3_create_function(db.handle(), "compared_samples_key", 1,
                                           SQLITE_UTF8 | SQLITE_DETERMINISTIC, nullptr,
                                           compared_samples_key_sql, nullptr, nullptr);
  if (code != SQLITE_OK)
    throw SqliteError(
        code, "cannot register compared_samples_key: " + std::string(sqlite3_errmsg(db.handle())));
}

}  // namespace clearsky::storage
