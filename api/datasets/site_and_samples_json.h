// The body the JSON forms of the open measurement formats share (docs/measurement-formats.md):
//   {"site": {"latitude", "longitude", "elevation_m"},            (optional: the file's site)
//    "samples": [{"time", "latitude", "longitude", "elevation_m", ...}, ...]}
// where a sample gives the site when the file has none, and only then; the other members of a
// sample are the format's own (sky_radiance_json.h, irradiance_json.h), which read them through
// JsonSample. Refusals are 400 invalid_body naming the member (samples[11].radiance,
// site.latitude), through the one client JSON parser (api/http/json_body.h).
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "api/datasets/sky_radiance_rows.h"

namespace clearsky::api {

// How refusals name a JSON sample's member: "samples[11].radiance".
class JsonSampleNames : public SkyRadianceRowNames {
 public:
  std::string member(std::size_t row, const std::string& name) const override {
    return where(row) + "." + name;
  }
  std::string where(std::size_t row) const override {
    return "samples[" + std::to_string(row) + "]";
  }
};

// One sample of the body: its time and site, checked, and its format's own members.
class JsonSample {
 public:
  JsonSample(const nlohmann::json& object, std::string prefix) noexcept
      : object_(&object), prefix_(std::move(prefix)) {}

  std::string time;  // as written (api/parse/iso8601_time.h checks it)
  double latitude_deg = 0;
  double longitude_deg = 0;
  double elevation_m = 0;

  // A required number member (400 naming samples[i].key when missing or not a number).
  double number(const std::string& key) const;
  // An optional number member: absent or null is nothing (400 when another type).
  std::optional<double> optional_number(const std::string& key) const;

 private:
  const nlohmann::json* object_;
  std::string prefix_;  // "samples[11]."
};

// The parsed body. Checks on construction the body (an object of members site and samples), the
// site (all three members or refused) and that samples is an array.
class SiteAndSamplesJson {
 public:
  // own_members: the members of a sample besides time and the site, for the refusal of an
  // unknown one.
  SiteAndSamplesJson(std::string_view text, std::vector<std::string_view> own_members);

  std::size_t size() const { return body_["samples"].size(); }
  // Sample i: an object whose members are known, with a time string and exactly one site (its
  // own or the file's). Its own members are read through the JsonSample.
  JsonSample sample(std::size_t i) const;
  const JsonSampleNames& names() const { return names_; }

 private:
  struct Site {
    double latitude = 0, longitude = 0, elevation_m = 0;
  };
  static std::optional<Site> site_of(const nlohmann::json& object, const std::string& prefix);

  nlohmann::json body_;
  std::vector<std::string_view> own_members_;
  std::optional<Site> file_site_;
  JsonSampleNames names_;
};

}  // namespace clearsky::api
