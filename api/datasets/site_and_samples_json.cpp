// The site-and-samples body of the open formats' JSON (site_and_samples_json.h).
#include "api/datasets/site_and_samples_json.h"

#include <algorithm>
#include <utility>

#include "api/error/api_error.h"
#include "api/http/json_body.h"

namespace clearsky::api {
namespace {

ApiError invalid_member(const std::string& member, const std::string& why) {
  return ApiError(400, "invalid_body", member, member + ": " + why);
}

double number_member(const nlohmann::json& object, const std::string& key,
                     const std::string& member) {
  const auto found = object.find(key);
  if (found == object.end()) throw invalid_member(member, "missing");
  if (!found->is_number()) throw invalid_member(member, "must be a number");
  return found->get<double>();
}

bool is_site_member(std::string_view key) {
  return key == "latitude" || key == "longitude" || key == "elevation_m";
}

}  // namespace

double JsonSample::number(const std::string& key) const {
  return number_member(*object_, key, prefix_ + key);
}

std::optional<double> JsonSample::optional_number(const std::string& key) const {
  const auto found = object_->find(key);
  if (found == object_->end() || found->is_null()) return std::nullopt;
  if (!found->is_number()) throw invalid_member(prefix_ + key, "must be a number or null");
  return found->get<double>();
}

// The site members of an object: all three, or none (nullopt).
std::optional<SiteAndSamplesJson::Site> SiteAndSamplesJson::site_of(const nlohmann::json& object,
                                                                    const std::string& prefix) {
  const bool any =
      object.contains("latitude") || object.contains("longitude") || object.contains("elevation_m");
  if (!any) return std::nullopt;
  return Site{number_member(object, "latitude", prefix + "latitude"),
              number_member(object, "longitude", prefix + "longitude"),
              number_member(object, "elevation_m", prefix + "elevation_m")};
}

SiteAndSamplesJson::SiteAndSamplesJson(std::string_view text,
                                       std::vector<std::string_view> own_members)
    : own_members_(std::move(own_members)) {
  try {
    body_ = parse_client_json(text, "body");
  } catch (const ApiError& e) {
    throw ApiError(400, "invalid_body", e.parameter(), e.what());
  }
  if (!body_.is_object())
    throw invalid_member("body", "must be an object with members site and samples");
  for (const auto& [key, value] : body_.items())
    if (key != "site" && key != "samples")
      throw invalid_member(key, "unknown member; the members are site and samples");
  if (body_.contains("site")) {
    const nlohmann::json& site = body_["site"];
    if (!site.is_object()) throw invalid_member("site", "must be an object");
    for (const auto& [key, value] : site.items())
      if (!is_site_member(key)) throw invalid_member("site." + key, "unknown member");
    file_site_ = site_of(site, "site.");
    if (!file_site_) throw invalid_member("site.latitude", "missing");
  }
  if (!body_.contains("samples")) throw invalid_member("samples", "missing");
  if (!body_["samples"].is_array()) throw invalid_member("samples", "must be an array");
}

JsonSample SiteAndSamplesJson::sample(std::size_t i) const {
  const nlohmann::json& object = body_["samples"][i];
  const std::string prefix = names_.where(i) + ".";
  if (!object.is_object()) throw invalid_member(names_.where(i), "must be an object");
  for (const auto& [key, value] : object.items())
    if (key != "time" && !is_site_member(key) &&
        std::find(own_members_.begin(), own_members_.end(), key) == own_members_.end())
      throw invalid_member(prefix + key, "unknown member");
  JsonSample sample(object, prefix);
  const auto time = object.find("time");
  if (time == object.end()) throw invalid_member(prefix + "time", "missing");
  if (!time->is_string())
    throw invalid_member(prefix + "time", "must be an ISO 8601 time with offset (a string)");
  sample.time = time->get<std::string>();
  const std::optional<Site> own_site = site_of(object, prefix);
  if (own_site && file_site_)
    throw invalid_member(prefix + "latitude",
                         "the file gives the site (member site): a sample may not give another");
  if (!own_site && !file_site_)
    throw invalid_member(prefix + "latitude",
                         "missing: give the site in the file (member site) or in each sample");
  const Site site = own_site ? *own_site : *file_site_;
  sample.latitude_deg = site.latitude;
  sample.longitude_deg = site.longitude;
  sample.elevation_m = site.elevation_m;
  return sample;
}

}  // namespace clearsky::api
