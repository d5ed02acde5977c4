// JSON of the open broadband irradiance format (irradiance_json.h).
#include "api/datasets/irradiance_json.h"

#include <optional>
#include <string>

#include "api/datasets/irradiance_rows.h"
#include "api/error/api_error.h"
#include "api/http/json_body.h"

namespace clearsky::api {
namespace {

class JsonRowNames : public SkyRadianceRowNames {
 public:
  std::string member(std::size_t row, const std::string& name) const override {
    return where(row) + "." + name;
  }
  std::string where(std::size_t row) const override {
    return "samples[" + std::to_string(row) + "]";
  }
};

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

// An optional number: absent or null is not measured.
std::optional<double> optional_member(const nlohmann::json& object, const std::string& key,
                                      const std::string& member) {
  const auto found = object.find(key);
  if (found == object.end() || found->is_null()) return std::nullopt;
  if (!found->is_number()) throw invalid_member(member, "must be a number or null");
  return found->get<double>();
}

struct Site {
  double latitude = 0, longitude = 0, elevation_m = 0;
};

std::optional<Site> site_of(const nlohmann::json& object, const std::string& prefix) {
  const bool any =
      object.contains("latitude") || object.contains("longitude") || object.contains("elevation_m");
  if (!any) return std::nullopt;
  return Site{number_member(object, "latitude", prefix + "latitude"),
              number_member(object, "longitude", prefix + "longitude"),
              number_member(object, "elevation_m", prefix + "elevation_m")};
}

}  // namespace

std::vector<storage::IrradianceSample> parse_irradiance_json(std::string_view text) {
  nlohmann::json body;
  try {
    body = parse_client_json(text, "body");
  } catch (const ApiError& e) {
    throw ApiError(400, "invalid_body", e.parameter(), e.what());
  }
  if (!body.is_object())
    throw invalid_member("body", "must be an object with members site and samples");
  for (const auto& [key, value] : body.items())
    if (key != "site" && key != "samples")
      throw invalid_member(key, "unknown member; the members are site and samples");
  std::optional<Site> file_site;
  if (body.contains("site")) {
    const nlohmann::json& site = body["site"];
    if (!site.is_object()) throw invalid_member("site", "must be an object");
    for (const auto& [key, value] : site.items())
      if (key != "latitude" && key != "longitude" && key != "elevation_m")
        throw invalid_member("site." + key, "unknown member");
    file_site = site_of(site, "site.");
    if (!file_site) throw invalid_member("site.latitude", "missing");
  }
  if (!body.contains("samples")) throw invalid_member("samples", "missing");
  const nlohmann::json& samples = body["samples"];
  if (!samples.is_array()) throw invalid_member("samples", "must be an array");

  const JsonRowNames names;
  std::vector<IrradianceRow> rows;
  rows.reserve(samples.size());
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const nlohmann::json& sample = samples[i];
    const std::string prefix = names.where(i) + ".";
    if (!sample.is_object()) throw invalid_member(names.where(i), "must be an object");
    for (const auto& [key, value] : sample.items())
      if (key != "time" && key != "ghi" && key != "dhi" && key != "dni" && key != "averaging_s" &&
          key != "latitude" && key != "longitude" && key != "elevation_m")
        throw invalid_member(prefix + key, "unknown member");
    IrradianceRow r;
    const auto time = sample.find("time");
    if (time == sample.end()) throw invalid_member(prefix + "time", "missing");
    if (!time->is_string())
      throw invalid_member(prefix + "time", "must be an ISO 8601 time with offset (a string)");
    r.time = time->get<std::string>();
    const std::optional<Site> own_site = site_of(sample, prefix);
    if (own_site && file_site)
      throw invalid_member(prefix + "latitude",
                           "the file gives the site (member site): a sample may not give another");
    if (!own_site && !file_site)
      throw invalid_member(prefix + "latitude",
                           "missing: give the site in the file (member site) or in each sample");
    const Site site = own_site ? *own_site : *file_site;
    r.latitude_deg = site.latitude;
    r.longitude_deg = site.longitude;
    r.elevation_m = site.elevation_m;
    r.ghi_w_m2 = optional_member(sample, "ghi", prefix + "ghi");
    r.dhi_w_m2 = optional_member(sample, "dhi", prefix + "dhi");
    r.dni_w_m2 = optional_member(sample, "dni", prefix + "dni");
    r.averaging_s = optional_member(sample, "averaging_s", prefix + "averaging_s");
    rows.push_back(std::move(r));
  }
  return irradiance_samples(rows, names);
}

}  // namespace clearsky::api
