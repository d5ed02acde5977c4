// Request targets (query_text.h).
#include "query_text.h"

#include <httplib.h>

#include <array>
#include <charconv>
#include <system_error>

namespace clearsky::client::detail {

std::string number_text(double value) {
  std::array<char, 64> text{};
  const auto [end, error] = std::to_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc()) return std::to_string(value);
  return std::string(text.data(), end);
}

std::string number_list_text(const std::vector<double>& values) {
  std::string text;
  for (double v : values) {
    if (!text.empty()) text += ',';
    text += number_text(v);
  }
  return text;
}

std::string parameter_text(const ParameterValue& value) {
  if (const double* number = std::get_if<double>(&value)) return number_text(*number);
  return std::get<std::string>(value);
}

std::string path_segment(const std::string& text) {
  return httplib::detail::encode_query_param(text);
}

void QueryText::add(const std::string& name, const std::string& value) {
  pairs_.emplace_back(name, value);
}
void QueryText::add(const std::string& name, double value) { add(name, number_text(value)); }
void QueryText::add(const std::string& name, std::int64_t value) {
  add(name, std::to_string(value));
}
void QueryText::add(const std::string& name, bool value) {
  add(name, std::string(value ? "true" : "false"));
}

std::string QueryText::target(const std::string& path) const {
  // httplib::Params is a multimap: it would sort the parameters; the order they were added is
  // kept instead, so a target reads as the request was written.
  std::string text = path;
  char separator = '?';
  for (const auto& [name, value] : pairs_) {
    text += separator;
    text += httplib::detail::encode_query_param(name);
    text += '=';
    text += httplib::detail::encode_query_param(value);
    separator = '&';
  }
  return text;
}

void add_sky_query(QueryText& query, const SkyQuery& sky) {
  query.add("model", sky.model);
  if (sky.sun) {
    query.add("sun_zenith", sky.sun->zenith_deg);
    query.add("sun_azimuth", sky.sun->azimuth_deg);
  }
  if (sky.place_time) {
    const PlaceTime& place = *sky.place_time;
    query.add("lat", place.latitude);
    query.add("lon", place.longitude);
    query.add("time", place.time);
    query.add("pressure", place.pressure_mbar);
    query.add("temperature", place.temperature_c);
    query.add("delta_t", place.delta_t_s);
    query.add("refraction", place.refraction);
  }
  query.add("altitude", sky.altitude_m);
  query.add("quality", sky.quality);
  query.add("fit", sky.fit);
  for (const auto& [name, value] : sky.parameters) query.add(name, parameter_text(value));
}

void add_sky_patch_options(QueryText& query, const SkyPatchOptions& options) {
  query.add("scheme", options.scheme);
  if (options.mf) query.add("mf", static_cast<std::int64_t>(*options.mf));
  query.add("sun", options.sun_handling);
  query.add("output", options.output);
  query.add("ground_reflectance", options.ground_reflectance);
  if (!options.wavelengths_nm.empty())
    query.add("wavelengths", number_list_text(options.wavelengths_nm));
}

}  // namespace clearsky::client::detail
