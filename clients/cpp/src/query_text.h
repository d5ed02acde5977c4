// Request targets: a path with its query parameters percent-encoded (RFC 3986 section 3.4, by
// cpp-httplib), numbers written in their shortest exact form, and the parameters every sky query
// shares (docs/http-api.md; /openapi.json lists them).
//
// Not thread-safe: a QueryText is built and read by one request.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "clearsky/client/sky_types.h"

namespace clearsky::client::detail {

// The shortest decimal text that reads back as the same double.
std::string number_text(double value);
// "450,550,650" (the list form of the wavelengths parameter).
std::string number_list_text(const std::vector<double>& values);
// A parameter's value as query text.
std::string parameter_text(const ParameterValue& value);
// One URL path segment, percent-encoded ("/" included).
std::string path_segment(const std::string& text);

class QueryText {
 public:
  void add(const std::string& name, const std::string& value);
  void add(const std::string& name, double value);
  void add(const std::string& name, std::int64_t value);
  void add(const std::string& name, bool value);
  template <typename T>
  void add(const std::string& name, const std::optional<T>& value) {
    if (value) add(name, *value);
  }
  // path?name=value&... (path alone when there is no parameter).
  std::string target(const std::string& path) const;

 private:
  std::vector<std::pair<std::string, std::string>> pairs_;
};

// The model, the sun (given or by place and time), the altitude, the quality, the fit and the
// model's parameters.
void add_sky_query(QueryText& query, const SkyQuery& sky);
// The patch scheme, the sun's handling, the output and its wavelengths of GET /v1/skypatches.
void add_sky_patch_options(QueryText& query, const SkyPatchOptions& options);

}  // namespace clearsky::client::detail
