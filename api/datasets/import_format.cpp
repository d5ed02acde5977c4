// The format of an import (import_format.h).
#include "api/datasets/import_format.h"

#include <algorithm>
#include <array>
#include <cctype>

#include "api/error/api_error.h"

namespace clearsky::api {
namespace {

// The media type without parameters (";charset=utf-8"), trimmed, in lower case.
std::string media_type_of(std::string_view header) {
  header = header.substr(0, header.find(';'));
  std::string type;
  for (char c : header)
    if (c != ' ' && c != '\t')
      type += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return type;
}

// The format a media type names; empty for one that names none.
std::string_view format_of_media_type(const std::string& type) {
  if (type == "text/csv") return kSkyRadianceCsvFormat;
  if (type == "application/json") return kSkyRadianceJsonFormat;
  constexpr std::array<std::string_view, 9> kArchiveTypes = {
      "application/octet-stream", "application/x-7z-compressed",
      "application/zip",          "application/x-tar",
      "application/gzip",         "application/x-gzip",
      "application/x-xz",         "application/x-bzip2",
      "application/zstd"};
  if (std::find(kArchiveTypes.begin(), kArchiveTypes.end(), type) != kArchiveTypes.end())
    return kKiderImportFormat;
  return {};
}

}  // namespace

bool is_sky_radiance_format(std::string_view format) {
  return format == kSkyRadianceCsvFormat || format == kSkyRadianceJsonFormat;
}

bool is_irradiance_format(std::string_view format) {
  return format == kIrradianceCsvFormat || format == kIrradianceJsonFormat;
}

std::string import_format_of(const std::optional<std::string>& format,
                             std::optional<std::string_view> content_type) {
  if (format && *format != kKiderImportFormat && !is_sky_radiance_format(*format) &&
      !is_irradiance_format(*format))
    throw invalid_parameter("format", "'" + *format +
                                          "' is not an import format (known: kider, "
                                          "sky-radiance-csv, sky-radiance-json, irradiance-csv, "
                                          "irradiance-json)");
  const std::string type = content_type ? media_type_of(*content_type) : std::string();
  if (type.empty() || type == "application/x-www-form-urlencoded")
    return format.value_or(std::string(kKiderImportFormat));
  const std::string_view named = format_of_media_type(type);
  if (named.empty())
    throw ApiError(415, "unsupported_media_type", "Content-Type",
                   "Content-Type: '" + type +
                       "' is not an import's media type (text/csv, application/json, "
                       "application/octet-stream or an archive type)");
  // The irradiance formats share the open format's media types.
  if (format && *format == kIrradianceCsvFormat && named == kSkyRadianceCsvFormat) return *format;
  if (format && *format == kIrradianceJsonFormat && named == kSkyRadianceJsonFormat) return *format;
  if (format && *format != named)
    throw ApiError(415, "unsupported_media_type", "Content-Type",
                   "Content-Type: '" + type + "' is not of format " + *format);
  return std::string(named);
}

}  // namespace clearsky::api
