// Which format an import reads (docs/data-api.md "Import formats"): the `format` parameter, or
// the upload's Content-Type when format is absent.
//   kider              Kider et al. 2014 captures in an archive (or a folder, path= only);
//                      media types application/octet-stream and the archive types
//   sky-radiance-csv   the open format's CSV (docs/measurement-formats.md); text/csv
//   sky-radiance-json  the open format's JSON; application/json
//   irradiance-csv     the open broadband irradiance format's CSV; no media type of its own
//                      (text/csv names sky-radiance-csv): give format= with text/csv
//   irradiance-json    its JSON; format= with application/json
// No Content-Type, or application/x-www-form-urlencoded (what curl --data-binary sends
// unasked), leaves the choice to format, kider by default. Refusals: an unknown format is 400
// naming format; any other media type, or one that contradicts format, is 415 naming
// Content-Type.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace clearsky::api {

inline constexpr std::string_view kKiderImportFormat = "kider";
inline constexpr std::string_view kSkyRadianceCsvFormat = "sky-radiance-csv";
inline constexpr std::string_view kSkyRadianceJsonFormat = "sky-radiance-json";
inline constexpr std::string_view kIrradianceCsvFormat = "irradiance-csv";
inline constexpr std::string_view kIrradianceJsonFormat = "irradiance-json";

// The format of an import; content_type is the upload's header (absent for a path import).
std::string import_format_of(const std::optional<std::string>& format,
                             std::optional<std::string_view> content_type);

// Whether a format is the open sky-radiance format (CSV or JSON).
bool is_sky_radiance_format(std::string_view format);

// Whether a format is the open broadband irradiance format (CSV or JSON).
bool is_irradiance_format(std::string_view format);

}  // namespace clearsky::api
