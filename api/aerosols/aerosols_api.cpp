// Users' AERONET inversions over HTTP (aerosols_api.h).
#include "api/aerosols/aerosols_api.h"

#include <algorithm>
#include <cctype>

#include "api/error/api_error.h"
#include "api/http/api_types.h"
#include "models/core/content_hash.h"
#include "models/core/invalid_input.h"
#include "storage/repositories/aerosol_inversion_repository.h"

namespace clearsky::api {

namespace {

constexpr std::size_t kMaxNameBytes = 100;

void check_name(const std::string& name) {
  if (name.empty()) throw missing_parameter("name", "the inversion's label");
  if (name.size() > kMaxNameBytes)
    throw invalid_parameter("name", "longer than " + std::to_string(kMaxNameBytes) + " bytes");
  for (unsigned char c : name)
    if (c < 0x20 || c == 0x7f) throw invalid_parameter("name", "holds a control character");
}

aeronet::PhaseFunctionFile parse_body(std::string_view body) {
  try {
    return aeronet::parse_phase_function_file(body);
  } catch (const InvalidInput& e) {
    throw ApiError::about(400, "invalid_inversion", "body",
                          "not an AERONET phase-function inversion: " + e.reason());
  }
}

nlohmann::ordered_json summary_json(const storage::AerosolInversionSummary& s) {
  nlohmann::ordered_json j;
  j["id"] = s.id;
  j["name"] = s.inversion.name;
  j["content_hash"] = s.inversion.content_hash;
  j["site"] = s.inversion.site;
  j["latitude_deg"] = finite(s.inversion.latitude_deg);
  j["longitude_deg"] = finite(s.inversion.longitude_deg);
  j["first_day"] = s.inversion.first_day;
  j["last_day"] = s.inversion.last_day;
  j["retrieval_count"] = s.inversion.retrieval_count;
  j["size_bytes"] = s.size_bytes;
  j["created_utc"] = s.created_utc;
  j["location"] = aerosols_location(s.id);
  return j;
}

}  // namespace

void check_aerosol_media_type(std::optional<std::string_view> content_type) {
  if (!content_type) return;
  std::string type(content_type->substr(0, content_type->find(';')));
  type.erase(std::remove_if(type.begin(), type.end(),
                            [](unsigned char c) { return std::isspace(c) != 0; }),
             type.end());
  std::transform(type.begin(), type.end(), type.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (type.empty() || type == "text/plain" || type == "text/csv" ||
      type == "application/octet-stream")
    return;
  throw ApiError(415, "unsupported_media_type", "Content-Type",
                 "Content-Type: '" + std::string(*content_type) +
                     "' is not an inversion file's media type (text/plain, text/csv or "
                     "application/octet-stream)");
}

std::int64_t store_aerosol_inversion(storage::Database& db, const std::string& name,
                                     std::string_view body) {
  check_name(name);
  if (body.empty()) throw missing_parameter("body", "the AERONET inversion file (.pfn)");
  if (body.size() > kMaxAerosolFileBytes)
    throw too_large(
        "body", "an inversion file is at most " + std::to_string(kMaxAerosolFileBytes) + " bytes");
  const aeronet::PhaseFunctionFile file = parse_body(body);
  storage::NewAerosolInversion row;
  row.name = name;
  row.content_hash = hex64(file.content_hash);
  row.site = file.site;
  row.latitude_deg = file.latitude_deg;
  row.longitude_deg = file.longitude_deg;
  row.first_day = file.first_day;
  row.last_day = file.last_day;
  row.retrieval_count = static_cast<std::int64_t>(file.retrievals.size());
  return storage::AerosolInversionRepository(db).create(row, body);
}

ListPage list_aerosol_inversions(storage::Database& db, Parameters query) {
  const PageRequest page = parse_page_request(query);
  query.reject_unused();
  const auto rows = storage::AerosolInversionRepository(db).list_page(
      page.limit, page.cursor ? id_from_cursor(*page.cursor) : 0);
  ListPage out;
  out.limit = page.limit;
  for (const auto& row : rows.rows) out.items.push_back(summary_json(row));
  if (rows.more) out.next_cursor = id_cursor(rows.rows.back().id);
  return out;
}

aeronet::PhaseFunctionFile load_aerosol_inversion(storage::Database& db, std::int64_t id,
                                                  const std::string& parameter) {
  const auto content = storage::AerosolInversionRepository(db).content(id);
  if (!content)
    throw ApiError::about(404, "unknown_aerosols", parameter,
                          "no stored aerosol inversion " + std::to_string(id));
  // Accepted by the same reader when it was stored.
  return aeronet::parse_phase_function_file(*content);
}

nlohmann::ordered_json show_aerosol_inversion(storage::Database& db, std::int64_t id,
                                              const std::string& parameter) {
  const auto summary = storage::AerosolInversionRepository(db).find(id);
  if (!summary)
    throw ApiError::about(404, "unknown_aerosols", parameter,
                          "no stored aerosol inversion " + std::to_string(id));
  const aeronet::PhaseFunctionFile file = load_aerosol_inversion(db, id, parameter);
  nlohmann::ordered_json j = summary_json(*summary);
  j["level"] = file.level;
  j["wavelengths_nm"] = file.wavelengths_nm;
  j["angle_count"] = file.angles_deg.size();
  nlohmann::ordered_json retrievals = nlohmann::ordered_json::array();
  for (const aeronet::PhaseFunctionRetrieval& r : file.retrievals) {
    nlohmann::ordered_json one;
    one["date"] = r.date;
    one["time_utc"] = r.time;
    one["time_utc_h"] = finite(r.time_utc_h);
    one["aod_440"] = finite(r.aod_440);
    one["angstrom_440_870"] = finite(r.angstrom_440_870);
    nlohmann::ordered_json aod = nlohmann::ordered_json::array();
    for (double wavelength_nm : file.wavelengths_nm)
      aod.push_back(nlohmann::ordered_json(finite(r.aod_at(wavelength_nm))));
    one["aod"] = std::move(aod);
    retrievals.push_back(std::move(one));
  }
  j["retrievals"] = std::move(retrievals);
  return j;
}

std::string aerosols_location(std::int64_t id) { return "/v1/aerosols/" + std::to_string(id); }

}  // namespace clearsky::api
