// The irradiance time series (irradiance_series.h).
#include "api/irradiance/irradiance_series.h"

#include <cmath>
#include <memory>

#include "api/encode/iso8601_time.h"
#include "api/fits/stored_fit_values.h"
#include "api/irradiance/broadband_plane_irradiance.h"
#include "api/irradiance/broadband_request.h"
#include "api/irradiance/broadband_zenith_table.h"
#include "api/irradiance/ground_reflection_request.h"
#include "models/atmosphere/spctral2.h"
#include "models/core/numeric.h"

namespace clearsky::api {

namespace {

// Rows are encoded in blocks of this many steps (a day of hourly rows).
constexpr std::size_t kRowsPerBlock = 24;

// The broadband horizontal and plane columns of a row, and the model-range ones.
constexpr std::size_t kHorizontalValues = 7;  // ghi, dni, dhi, illuminance, model_range_* x 3
constexpr std::size_t kPlaneValues = 11;      // poa_* x 6, model_range_poa_* x 5

nlohmann::json optional_value(const std::optional<double>& x) {
  return x ? nlohmann::json(finite(*x)) : nlohmann::json(nullptr);
}

// One row as JSON values; a step the model cannot answer has null irradiances. The broadband
// figures (broadband_plane_irradiance.h) are those of GET /v1/irradiance at the step's sun and
// date; null for a model that cannot go broadband.
nlohmann::json row_of(const IrradianceSeriesRequest& s, const SkyModel& model,
                      const XyzWeights& xyz, const Spectrum& albedo,
                      const std::vector<std::unique_ptr<PlaneSkyIrradianceTable>>& tables,
                      const BroadbandZenithTable* broadband_table, std::size_t i, bool& answered) {
  const TimeSteps& times = s.times;
  const double t = times.unix_time_s(i);
  nlohmann::json row = nlohmann::json::array();
  row.push_back(format_iso8601_time(t, 0, true));
  if (times.tz) row.push_back(format_iso8601_time_in_zone(t, *times.tz));
  const bool night = times.night(i);
  row.push_back(night);
  row.push_back(finite(times.zenith_deg[i]));
  row.push_back(finite(times.azimuth_deg[i]));
  answered = true;
  const bool broadband = !s.broadband_unavailable;
  if (night) {
    // The broadband columns lead each group: 3 of the horizontal's, 5 of each plane's.
    const auto zeros = [&](std::size_t broadband_values, std::size_t others) {
      for (std::size_t k = 0; k < broadband_values; ++k)
        row.push_back(broadband ? nlohmann::json(0.0) : nlohmann::json(nullptr));
      for (std::size_t k = 0; k < others; ++k) row.push_back(0.0);
    };
    zeros(3, kHorizontalValues - 3);
    for (std::size_t k = 0; k < s.planes.size(); ++k) zeros(5, kPlaneValues - 5);
    return row;
  }
  try {
    const SunPosition sun = times.sun(i);
    const auto state = model.prepare_sun(sun);
    const HorizontalIrradiance h =
        horizontal_irradiance(model, *state, s.viewpoint, true, true, "start");
    const auto& indices = s.grid.indices;
    std::optional<BroadbandExtension> extension;
    BroadbandHorizontalIrradiance bb_h;
    if (broadband) {
      const BroadbandConditions conditions{
          .sun_zenith_rad = sun.zenith_rad,
          .altitude_m = s.viewpoint.altitude_m,
          .atmosphere = s.absorbers,
          .earth_sun_distance_factor = spctral2::earth_sun_distance_factor(day_of_year_utc(t))};
      if (broadband_table != nullptr) {
        extension.emplace(model.wavelengths(), indices, conditions,
                          broadband_table->at(sun.zenith_rad));
      } else {
        extension.emplace(model.wavelengths(), indices, conditions);
      }
      bb_h = broadband_horizontal_irradiance(*extension, h);
    }
    const IntegratedIrradiance ghi = integrated(h.global, model, indices, xyz);
    nlohmann::json cells = nlohmann::json::array();
    cells.push_back(optional_value(bb_h.global_w_m2));
    cells.push_back(optional_value(bb_h.direct_normal_w_m2));
    cells.push_back(optional_value(bb_h.diffuse_w_m2));
    cells.push_back(finite(ghi.illuminance_lx));
    cells.push_back(finite(ghi.irradiance_w_m2));
    cells.push_back(finite(integrated(h.direct_normal, model, indices, xyz).irradiance_w_m2));
    cells.push_back(finite(integrated(h.diffuse, model, indices, xyz).irradiance_w_m2));
    for (std::size_t k = 0; k < s.planes.size(); ++k) {
      const PlaneIrradiance e =
          plane_irradiance(model, *state, s.viewpoint, s.planes[k].orientation(), h, albedo,
                           s.ground, true, "start", tables.empty() ? nullptr : tables[k].get());
      BroadbandPlaneIrradiance bb;
      if (extension) bb = broadband_plane_irradiance(*extension, h, bb_h, e);
      const std::optional<double> bb_diffuse =
          bb.sky_diffuse_w_m2
              ? std::optional<double>(*bb.sky_diffuse_w_m2 + bb.ground_diffuse_w_m2.value_or(0.0))
              : std::nullopt;
      cells.push_back(optional_value(bb.global_w_m2));
      cells.push_back(optional_value(bb.direct_w_m2));
      cells.push_back(optional_value(bb_diffuse));
      cells.push_back(optional_value(bb.sky_diffuse_w_m2));
      cells.push_back(optional_value(broadband ? bb.ground_diffuse_w_m2.value_or(0.0)
                                               : std::optional<double>()));
      const IntegratedIrradiance global = integrated(e.global, model, indices, xyz);
      const double sky = model_range_w_m2(e.sky_diffuse, model.wavelengths(), indices);
      const double ground = model_range_w_m2(e.ground_diffuse, model.wavelengths(), indices);
      cells.push_back(finite(global.illuminance_lx));
      cells.push_back(finite(global.irradiance_w_m2));
      cells.push_back(finite(model_range_w_m2(e.direct, model.wavelengths(), indices)));
      cells.push_back(finite(sky + ground));
      cells.push_back(finite(sky));
      cells.push_back(finite(ground));
    }
    for (auto& c : cells) row.push_back(std::move(c));
  } catch (const ApiError&) {
    answered = false;
    const std::size_t values = kHorizontalValues + kPlaneValues * s.planes.size();
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
  if (times.tz) out.push_back("time_local");
  for (const char* name : {"night", "solar_zenith", "solar_azimuth", "ghi", "dni", "dhi",
                           "illuminance", "model_range_ghi", "model_range_dni", "model_range_dhi"})
    out.emplace_back(name);
  for (const SeriesPlane& plane : planes) {
    for (const char* name : {"poa_global", "poa_direct", "poa_diffuse", "poa_sky_diffuse",
                             "poa_ground_diffuse", "poa_illuminance", "model_range_poa_global",
                             "model_range_poa_direct", "model_range_poa_diffuse",
                             "model_range_poa_sky_diffuse", "model_range_poa_ground_diffuse"})
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
  s.times = parse_time_steps(p);
  s.viewpoint = Viewpoint{s.times.position.elevation_m};
  SkyConfig sky = parse_sky_config(p, d, stored_fit_lookup(context));
  ModelConfig& config = sky.config;
  s.fit = std::move(sky.fit);
  s.quality = parse_quality(p, d, config, context.default_quality);
  if (auto planes = p.text("planes")) s.planes = parse_planes(*planes);
  s.ground = parse_ground_reflection(p);
  s.absorbers = parse_broadband_absorbers(p, config.atmosphere);
  s.broadband_unavailable = broadband_unavailable_reason(d);
  s.csv = p.choice("format", {"json", "csv"}, "json") == "csv";
  p.reject_unused();
  if (!d.capabilities.sun_irradiance || !d.capabilities.sky_irradiance) {
    throw cannot_answer("model", d.id,
                        "it does not compute both the direct sun and the sky irradiance");
  }

  s.tabulated_sky =
      !d.capabilities.per_sun_precomputation && s.times.day_steps > PlaneSkyIrradianceTable::kNodes;
  s.tabulated_broadband =
      !s.broadband_unavailable && s.times.day_steps > BroadbandZenithTable::kNodes;
  require_per_sun_day_steps(s.times, d);
  s.grid = model_on_wavelengths(context.models, factory, std::move(config), std::nullopt,
                                request.requester(), &s.quality);
  require_answerable_suns(s.times, *s.grid.model);
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
  // Long series interpolate the broadband integrals over the sun zenith (cheaper once the
  // daytime steps outnumber the table's nodes).
  std::unique_ptr<BroadbandZenithTable> broadband_table;
  if (s.tabulated_broadband) {
    broadband_table = std::make_unique<BroadbandZenithTable>(
        model.wavelengths(), s.grid.indices,
        BroadbandConditions{.altitude_m = s.viewpoint.altitude_m, .atmosphere = s.absorbers});
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
        {"lat", s.times.position.latitude_deg},
        {"lon", s.times.position.longitude_deg},
        {"altitude_m", s.viewpoint.altitude_m},
        {"start", format_iso8601_time(s.times.start_unix_s, 0, true)},
        {"step", s.times.step_text},
        {"step_s", s.times.step_s},
        {"steps", s.times.steps},
        {"tz", s.times.tz ? nlohmann::json(*s.times.tz) : nlohmann::json(nullptr)},
        {"planes", std::move(planes)},
        {"integrated_range_nm",
         {grid.lower_edge_nm(s.grid.indices.front()), grid.upper_edge_nm(s.grid.indices.back())}},
        {"ground_reflection", ground_reflection_json(s.ground)},
        {"broadband", broadband_json(s.broadband_unavailable, s.absorbers)},
        {"broadband_integration",
         s.broadband_unavailable ? nlohmann::json(nullptr)
                                 : nlohmann::json(s.tabulated_broadband ? "table" : "per_step")},
        {"sky_diffuse_on_planes", s.tabulated_sky ? "table" : "per_step"},
        {"columns", columns}};
    if (s.broadband_unavailable) head["broadband_unavailable"] = *s.broadband_unavailable;
    add_quality_members(head, s.quality, s.grid.served_quality);
    add_fit_member(head, s.fit);
    out = head.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    out.pop_back();  // the closing brace: the rows follow
    out += ",\"rows\":[";
  }
  std::size_t unanswered = 0;
  for (std::size_t i = 0; i < s.times.steps; ++i) {
    bool answered = true;
    const nlohmann::json row =
        row_of(s, model, xyz, albedo, tables, broadband_table.get(), i, answered);
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
