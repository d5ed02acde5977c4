// The irradiance time series (irradiance_series.h).
#include "api/irradiance/irradiance_series.h"

#include <cmath>
#include <memory>
#include <stdexcept>

#include "api/encode/iso8601_time.h"
#include "api/fits/stored_fit_values.h"
#include "api/irradiance/ground_reflection_request.h"
#include "api/parse/iso8601_duration.h"
#include "api/parse/iso8601_time.h"
#include "models/core/invalid_input.h"
#include "models/core/numeric.h"
#include "models/solar/delta_t.h"

namespace clearsky::api {

namespace {

// Rows are encoded in blocks of this many steps (a day of hourly rows).
constexpr std::size_t kRowsPerBlock = 24;

// An instant with its offset, or a local time in tz (the zone's offset, DST included).
double parse_instant(const std::string& text, const std::string& parameter,
                     const std::optional<std::string>& tz) {
  const std::size_t t = text.find('T');
  const bool has_offset =
      t != std::string::npos && text.find_first_of("Zz+-", t) != std::string::npos;
  if (has_offset || !tz) return parse_iso8601_time(text, parameter).unix_time_utc_s;
  return parse_iso8601_local_time(text, *tz, parameter, "tz").unix_time_utc_s;
}

void check_zone(const std::string& zone) {
  try {
    (void)utc_offset_min_in_zone(0.0, zone);
  } catch (const std::exception&) {
    throw invalid_parameter("tz",
                            "must be an IANA time zone name (e.g. Europe/Paris), got " + zone);
  }
}

SolarPosition sun_at(SolarPositionInput position, bool delta_t_from_time, double unix_s) {
  position.unix_time_utc_s = unix_s;
  try {
    if (delta_t_from_time) position.delta_t_s = espenak_meeus_delta_t_at_s(unix_s);
    return solar_position(position);
  } catch (const InvalidInput& e) {
    throw invalid_parameter(
        "end", std::string("a step the sun position cannot be computed for: ") + e.what());
  }
}

bool is_night(double zenith_deg) { return zenith_deg >= 90.0; }

// One row as JSON values; a step the model cannot answer has null irradiances.
nlohmann::json row_of(const IrradianceSeriesRequest& s, const SkyModel& model,
                      const XyzWeights& xyz, const Spectrum& albedo,
                      const std::vector<std::unique_ptr<PlaneSkyIrradianceTable>>& tables,
                      std::size_t i, bool& answered) {
  const double t = s.start_unix_s + static_cast<double>(i) * static_cast<double>(s.step_s);
  nlohmann::json row = nlohmann::json::array();
  row.push_back(format_iso8601_time(t, 0, true));
  if (s.tz) row.push_back(format_iso8601_time_in_zone(t, *s.tz));
  const double zenith = s.zenith_deg[i];
  const bool night = is_night(zenith);
  row.push_back(night);
  row.push_back(finite(zenith));
  row.push_back(finite(s.azimuth_deg[i]));
  const std::size_t values = 4 + 6 * s.planes.size();
  answered = true;
  if (night) {
    for (std::size_t k = 0; k < values; ++k) row.push_back(0.0);
    return row;
  }
  try {
    const SunPosition sun{degrees_to_radians(zenith), degrees_to_radians(s.azimuth_deg[i])};
    const auto state = model.prepare_sun(sun);
    const HorizontalIrradiance h =
        horizontal_irradiance(model, *state, s.viewpoint, true, true, "start");
    const auto& indices = s.grid.indices;
    const IntegratedIrradiance ghi = integrated(h.global, model, indices, xyz);
    nlohmann::json cells = nlohmann::json::array();
    cells.push_back(finite(ghi.irradiance_w_m2));
    cells.push_back(finite(integrated(h.direct_normal, model, indices, xyz).irradiance_w_m2));
    cells.push_back(finite(integrated(h.diffuse, model, indices, xyz).irradiance_w_m2));
    cells.push_back(finite(ghi.illuminance_lx));
    for (std::size_t k = 0; k < s.planes.size(); ++k) {
      const PlaneIrradiance e =
          plane_irradiance(model, *state, s.viewpoint, s.planes[k].orientation(), h, albedo,
                           s.ground, true, "start", tables.empty() ? nullptr : tables[k].get());
      const IntegratedIrradiance global = integrated(e.global, model, indices, xyz);
      const double sky = integrated(e.sky_diffuse, model, indices, xyz).irradiance_w_m2;
      const double ground = integrated(e.ground_diffuse, model, indices, xyz).irradiance_w_m2;
      cells.push_back(finite(global.irradiance_w_m2));
      cells.push_back(finite(integrated(e.direct, model, indices, xyz).irradiance_w_m2));
      cells.push_back(finite(sky + ground));
      cells.push_back(finite(sky));
      cells.push_back(finite(ground));
      cells.push_back(finite(global.illuminance_lx));
    }
    for (auto& c : cells) row.push_back(std::move(c));
  } catch (const ApiError&) {
    answered = false;
    for (std::size_t k = 0; k < values; ++k) row.push_back(nullptr);
  }
  return row;
}

void append_csv(std::string& out, const nlohmann::json& row) {
  bool first = true;
  for (const auto& cell : row) {
    if (!first) out += ',';
    first = false;
    if (cell.is_string()) {
      out += cell.get<std::string>();
    } else if (!cell.is_null()) {
      out += cell.dump();
    }
  }
  out += '\n';
}

}  // namespace

std::vector<std::string> IrradianceSeriesRequest::columns() const {
  std::vector<std::string> out = {"time_utc"};
  if (tz) out.push_back("time_local");
  for (const char* name :
       {"night", "solar_zenith", "solar_azimuth", "ghi", "dni", "dhi", "illuminance"})
    out.emplace_back(name);
  for (const SeriesPlane& plane : planes) {
    for (const char* name : {"poa_global", "poa_direct", "poa_diffuse", "poa_sky_diffuse",
                             "poa_ground_diffuse", "poa_illuminance"})
      out.push_back(name + plane.suffix);
  }
  return out;
}

IrradianceSeriesRequest parse_irradiance_series(const ApiContext& context,
                                                const ApiRequest& request) {
  if (request.method != "GET")
    throw ApiError(405, "method_not_allowed", "", "use GET for /v1/irradiance/series");
  Parameters p = request_parameters(request);
  IrradianceSeriesRequest s;
  const ModelFactory& factory = parse_model(p, context.models);
  const ModelDescriptor& d = *factory.descriptor;
  if (p.has("time"))
    throw invalid_parameter("time", "a series takes start, end and step instead of time");
  for (const char* name : {"sun_zenith", "sun_azimuth"}) {
    if (p.has(name))
      throw invalid_parameter(name, "a series computes the sun of each step from lat and lon");
  }
  s.tz = p.text("tz");
  if (s.tz) check_zone(*s.tz);
  const std::string start_text = p.required_text("start");
  const std::string end_text = p.required_text("end");
  s.start_unix_s = parse_instant(start_text, "start", s.tz);
  const double end_unix_s = parse_instant(end_text, "end", s.tz);
  if (end_unix_s < s.start_unix_s)
    throw invalid_parameter("end",
                            "must not be before start (" + start_text + "), got " + end_text);
  if (auto step = p.text("step")) {
    s.step_text = *step;
    s.step_s = parse_iso8601_duration_s(*step, "step");
  }
  const double span_steps =
      std::floor((end_unix_s - s.start_unix_s) / static_cast<double>(s.step_s));
  if (span_steps + 1.0 > static_cast<double>(kMaxSeriesSteps)) {
    throw too_large("step", "start to end every " + s.step_text + " is " +
                                std::to_string(static_cast<long long>(span_steps) + 1) +
                                " steps, above the limit of " + std::to_string(kMaxSeriesSteps) +
                                " (a leap year every 10 minutes); ask for a longer step or a "
                                "shorter period");
  }
  s.steps = static_cast<std::size_t>(span_steps) + 1;
  const PlaceTime place = parse_place_and_time(p, s.start_unix_s);
  s.position = place.position;
  s.delta_t_from_time = place.delta_t_from_time;
  s.viewpoint = Viewpoint{s.position.elevation_m};
  SkyConfig sky = parse_sky_config(p, d, stored_fit_lookup(context));
  ModelConfig& config = sky.config;
  s.fit = std::move(sky.fit);
  s.quality = parse_quality(p, d, config, context.default_quality);
  if (auto planes = p.text("planes")) s.planes = parse_planes(*planes);
  s.ground = parse_ground_reflection(p);
  s.csv = p.choice("format", {"json", "csv"}, "json") == "csv";
  p.reject_unused();
  if (!d.capabilities.sun_irradiance || !d.capabilities.sky_irradiance) {
    throw cannot_answer("model", d.id,
                        "it does not compute both the direct sun and the sky irradiance");
  }

  s.zenith_deg.resize(s.steps);
  s.azimuth_deg.resize(s.steps);
  std::size_t day_steps = 0;
  for (std::size_t i = 0; i < s.steps; ++i) {
    const double t = s.start_unix_s + static_cast<double>(i) * static_cast<double>(s.step_s);
    const SolarPosition sun = sun_at(s.position, s.delta_t_from_time, t);
    s.zenith_deg[i] = sun.zenith_deg;
    s.azimuth_deg[i] = sun.azimuth_deg;
    if (!is_night(sun.zenith_deg)) ++day_steps;
  }
  s.tabulated_sky =
      !d.capabilities.per_sun_precomputation && day_steps > PlaneSkyIrradianceTable::kNodes;
  if (d.capabilities.per_sun_precomputation && day_steps > kMaxPerSunDaySteps) {
    throw too_large("end", "model " + d.id + " precomputes its tables for each sun position; a " +
                               "series by it takes at most " + std::to_string(kMaxPerSunDaySteps) +
                               " steps with the sun up, this one has " + std::to_string(day_steps) +
                               "; ask for a shorter period or use a model with shared tables " +
                               "(bruneton, elek, hosek, preetham)");
  }
  s.grid = model_on_wavelengths(context.models, factory, std::move(config), std::nullopt,
                                request.requester(), &s.quality);
  for (std::size_t i = 0; i < s.steps; ++i) {
    if (is_night(s.zenith_deg[i])) continue;
    const SunPosition sun{degrees_to_radians(s.zenith_deg[i]),
                          degrees_to_radians(s.azimuth_deg[i])};
    const SampleStatus status = s.grid.model->check_sun(sun);
    if (status != SampleStatus::ok) require_answer(status, "start", d.id);
  }
  return s;
}

bool write_irradiance_series(const IrradianceSeriesRequest& s, const ByteSink& sink) {
  const SkyModel& model = *s.grid.model;
  const ModelDescriptor& d = model.descriptor();
  const XyzWeights xyz(model.wavelengths());
  const Spectrum albedo = ground_albedo_spectrum(model, s.ground);
  const std::vector<std::string> columns = s.columns();
  // Long series interpolate each tilted plane's sky irradiance in a table of the model's own
  // (plane_sky_irradiance_table.h): cheaper once the daytime steps outnumber its nodes.
  std::vector<std::unique_ptr<PlaneSkyIrradianceTable>> tables;
  if (s.tabulated_sky) {
    for (const SeriesPlane& plane : s.planes) {
      tables.push_back(plane.tilt_deg == 0.0 ? nullptr
                                             : std::make_unique<PlaneSkyIrradianceTable>(
                                                   model, s.viewpoint, plane.orientation()));
    }
  }
  std::string out;
  if (s.csv) {
    for (std::size_t k = 0; k < columns.size(); ++k) out += (k ? "," : "") + columns[k];
    out += '\n';
  } else {
    nlohmann::json planes = nlohmann::json::array();
    for (const SeriesPlane& plane : s.planes)
      planes.push_back({{"tilt_deg", plane.tilt_deg},
                        {"surface_azimuth_deg", plane.surface_azimuth_deg},
                        {"suffix", plane.suffix}});
    const WavelengthGrid& grid = model.wavelengths();
    nlohmann::json head = {
        {"model", d.id},
        {"model_version", d.version},
        {"lat", s.position.latitude_deg},
        {"lon", s.position.longitude_deg},
        {"altitude_m", s.viewpoint.altitude_m},
        {"start", format_iso8601_time(s.start_unix_s, 0, true)},
        {"step", s.step_text},
        {"step_s", s.step_s},
        {"steps", s.steps},
        {"tz", s.tz ? nlohmann::json(*s.tz) : nlohmann::json(nullptr)},
        {"planes", std::move(planes)},
        {"integrated_range_nm",
         {grid.lower_edge_nm(s.grid.indices.front()), grid.upper_edge_nm(s.grid.indices.back())}},
        {"ground_reflection", ground_reflection_json(s.ground)},
        {"sky_diffuse_on_planes", s.tabulated_sky ? "table" : "per_step"},
        {"columns", columns}};
    add_quality_members(head, s.quality, s.grid.served_quality);
    add_fit_member(head, s.fit);
    out = head.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    out.pop_back();  // the closing brace: the rows follow
    out += ",\"rows\":[";
  }
  std::size_t unanswered = 0;
  for (std::size_t i = 0; i < s.steps; ++i) {
    bool answered = true;
    const nlohmann::json row = row_of(s, model, xyz, albedo, tables, i, answered);
    if (!answered) ++unanswered;
    if (s.csv) {
      append_csv(out, row);
    } else {
      if (i > 0) out += ',';
      out += row.dump();
    }
    if ((i + 1) % kRowsPerBlock == 0) {
      if (!sink(out.data(), out.size())) return false;
      out.clear();
    }
  }
  if (!s.csv) out += "],\"unanswered_steps\":" + std::to_string(unanswered) + "}";
  return out.empty() || sink(out.data(), out.size());
}

}  // namespace clearsky::api
