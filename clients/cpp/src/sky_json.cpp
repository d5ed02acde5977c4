// The sky endpoints' JSON (sky_json.h).
#include "sky_json.h"

#include <cmath>

#include "json_fields.h"
#include "query_text.h"

namespace clearsky::client::detail {

namespace {

nlohmann::json sky_query_json(const SkyQuery& sky) {
  nlohmann::json body = parameters_json(sky.parameters);
  body["model"] = sky.model;
  if (sky.sun) {
    body["sun_zenith"] = sky.sun->zenith_deg;
    body["sun_azimuth"] = sky.sun->azimuth_deg;
  }
  if (sky.place_time) {
    const PlaceTime& place = *sky.place_time;
    body["lat"] = place.latitude;
    body["lon"] = place.longitude;
    body["time"] = place.time;
    if (place.pressure_mbar) body["pressure"] = *place.pressure_mbar;
    if (place.temperature_c) body["temperature"] = *place.temperature_c;
    if (place.delta_t_s) body["delta_t"] = *place.delta_t_s;
    if (place.refraction) body["refraction"] = *place.refraction;
  }
  if (sky.altitude_m) body["altitude"] = *sky.altitude_m;
  if (sky.quality) body["quality"] = *sky.quality;
  if (sky.fit) body["fit"] = *sky.fit;
  return body;
}

// The answer's `fit` member, absent when no stored fit was used.
std::optional<AppliedFit> applied_fit_of(const nlohmann::json& json) {
  const auto fit = optional_member<nlohmann::json>(json, "fit");
  if (!fit) return std::nullopt;
  AppliedFit applied;
  applied.id = member<std::int64_t>(*fit, "id");
  applied.model = member<std::string>(*fit, "model");
  applied.model_version = member<std::string>(*fit, "model_version");
  applied.dataset = member<std::string>(*fit, "dataset");
  applied.parameters = member<std::map<std::string, double>>(*fit, "parameters");
  return applied;
}

nlohmann::json views_json(const std::vector<ViewDirection>& views) {
  nlohmann::json pairs = nlohmann::json::array();
  for (const ViewDirection& v : views) pairs.push_back({v.zenith_deg, v.azimuth_deg});
  return pairs;
}

SunUsed sun_used_of(const nlohmann::json& json) {
  const nlohmann::json sun = member<nlohmann::json>(json, "sun");
  SunUsed used;
  used.zenith_deg = member<double>(sun, "zenith_deg");
  used.azimuth_deg = member<double>(sun, "azimuth_deg");
  used.source = member<std::string>(sun, "source");
  return used;
}

ViewDirection view_of(const nlohmann::json& sample) {
  return {member<double>(sample, "view_zenith_deg"), member<double>(sample, "view_azimuth_deg")};
}

std::array<double, 2> range_of(const nlohmann::json& json, const char* name) {
  const auto values = member<std::vector<double>>(json, name);
  if (values.size() != 2)
    throw Error(0, "invalid_answer", std::string(name) + " is not a [min, max] pair");
  return {values[0], values[1]};
}

std::optional<IrradianceComponent> component_of(const nlohmann::json& json, const char* name) {
  const auto part = optional_member<nlohmann::json>(json, name);
  if (!part) return std::nullopt;
  IrradianceComponent component;
  component.irradiance_w_m2 = member<double>(*part, "irradiance_w_m2");
  component.model_range_irradiance_w_m2 =
      optional_member<double>(*part, "model_range_irradiance_w_m2")
          .value_or(component.irradiance_w_m2);
  component.broadband_irradiance_w_m2 = optional_member<double>(*part, "broadband_irradiance_w_m2");
  component.illuminance_lx = member<double>(*part, "illuminance_lx");
  component.spectral_w_m2_nm = optional_member<std::vector<double>>(*part, "spectral_w_m2_nm")
                                   .value_or(std::vector<double>{});
  return component;
}

ModelCapabilities capabilities_of(const nlohmann::json& json) {
  ModelCapabilities capabilities;
  const nlohmann::json altitudes = member<nlohmann::json>(json, "altitude_range_m");
  if (altitudes.is_array() && altitudes.size() == 2) {
    if (altitudes[0].is_number()) capabilities.min_altitude_m = altitudes[0].get<double>();
    if (altitudes[1].is_number()) capabilities.max_altitude_m = altitudes[1].get<double>();
  }
  capabilities.view_from_space = member<bool>(json, "view_from_space");
  capabilities.view_below_horizon = member<bool>(json, "view_below_horizon");
  capabilities.aerial_perspective = member<bool>(json, "aerial_perspective");
  capabilities.max_sun_zenith_deg = member<double>(json, "max_sun_zenith_deg");
  capabilities.sun_below_horizon = member<bool>(json, "sun_below_horizon");
  capabilities.dark_beyond_sun_zenith_deg =
      optional_member<double>(json, "dark_beyond_sun_zenith_deg");
  // A number of orders, or "all".
  if (member<nlohmann::json>(json, "scattering_orders").is_number())
    capabilities.scattering_orders = member<int>(json, "scattering_orders");
  capabilities.per_sun_precomputation = member<bool>(json, "per_sun_precomputation");
  capabilities.sun_irradiance = member<bool>(json, "sun_irradiance");
  capabilities.sky_irradiance = member<bool>(json, "sky_irradiance");
  return capabilities;
}

}  // namespace

nlohmann::json radiance_batch_json(const RadianceBatchRequest& request) {
  nlohmann::json body = sky_query_json(request);
  body["views"] = views_json(request.views);
  if (!request.wavelengths_nm.empty())
    body["wavelengths"] = number_list_text(request.wavelengths_nm);
  return body;
}

nlohmann::json rgb_batch_json(const RgbBatchRequest& request) {
  nlohmann::json body = sky_query_json(request);
  body["views"] = views_json(request.views);
  if (request.method) body["method"] = *request.method;
  return body;
}

SunPosition sun_position_of(const nlohmann::json& json) {
  SunPosition sun;
  sun.zenith_deg = member<double>(json, "zenith");
  sun.azimuth_deg = member<double>(json, "azimuth");
  sun.sunrise = optional_member<std::string>(json, "sunrise");
  sun.transit = optional_member<std::string>(json, "transit");
  sun.sunset = optional_member<std::string>(json, "sunset");
  sun.day = member<std::string>(json, "day");
  return sun;
}

std::vector<ModelInfo> models_of(const nlohmann::json& json) {
  std::vector<ModelInfo> models;
  for (const nlohmann::json& m : member<nlohmann::json>(json, "models")) {
    ModelInfo info;
    info.id = member<std::string>(m, "id");
    info.name = member<std::string>(m, "name");
    info.version = member<std::string>(m, "version");
    info.citation = member<std::string>(m, "citation");
    info.summary = member<std::string>(m, "summary");
    info.native_wavelengths_nm = member<std::vector<double>>(m, "native_wavelengths_nm");
    const nlohmann::json range = member<nlohmann::json>(m, "wavelength_range_nm");
    if (range.is_array() && range.size() == 2) {
      if (range[0].is_number()) info.min_wavelength_nm = range[0].get<double>();
      if (range[1].is_number()) info.max_wavelength_nm = range[1].get<double>();
    }
    for (const nlohmann::json& p : member<nlohmann::json>(m, "parameters")) {
      ModelParameterInfo parameter;
      parameter.name = member<std::string>(p, "name");
      parameter.unit = member<std::string>(p, "unit");
      parameter.description = member<std::string>(p, "description");
      parameter.default_value = optional_member<double>(p, "default");
      parameter.min = optional_member<double>(p, "min");
      parameter.max = optional_member<double>(p, "max");
      parameter.integer = member<bool>(p, "integer");
      parameter.kind = member<std::string>(p, "kind");
      info.parameters.push_back(std::move(parameter));
    }
    info.capabilities = capabilities_of(member<nlohmann::json>(m, "capabilities"));
    const nlohmann::json state = member<nlohmann::json>(m, "state");
    info.table_status = member<std::string>(state, "status");
    info.table_progress = member<double>(state, "progress");
    models.push_back(std::move(info));
  }
  return models;
}

RadianceResult radiance_of(const nlohmann::json& json) {
  RadianceResult result;
  result.model = member<std::string>(json, "model");
  result.model_version = member<std::string>(json, "model_version");
  result.quality = optional_member<std::string>(json, "quality").value_or("");
  result.served_quality = optional_member<std::string>(json, "served_quality").value_or("");
  result.sun = sun_used_of(json);
  result.altitude_m = member<double>(json, "altitude_m");
  result.unit = member<std::string>(json, "unit");
  result.grid = member<std::string>(json, "grid");
  result.bin_width_nm = optional_member<double>(json, "bin_width_nm");
  result.wavelengths_nm = member<std::vector<double>>(json, "wavelengths_nm");
  for (const nlohmann::json& s : member<nlohmann::json>(json, "samples")) {
    RadianceSample sample;
    sample.view = view_of(s);
    sample.radiance_w_m2_sr_nm = member<std::vector<double>>(s, "radiance");
    if (sample.radiance_w_m2_sr_nm.size() != result.wavelengths_nm.size())
      throw Error(0, "invalid_answer", "a sample's radiance does not match wavelengths_nm");
    result.samples.push_back(std::move(sample));
  }
  result.fit = applied_fit_of(json);
  return result;
}

IrradianceResult irradiance_of(const nlohmann::json& json) {
  IrradianceResult result;
  result.model = member<std::string>(json, "model");
  result.model_version = member<std::string>(json, "model_version");
  result.quality = optional_member<std::string>(json, "quality").value_or("");
  result.served_quality = optional_member<std::string>(json, "served_quality").value_or("");
  result.sun = sun_used_of(json);
  result.altitude_m = member<double>(json, "altitude_m");
  const nlohmann::json plane = member<nlohmann::json>(json, "plane");
  result.tilt_deg = member<double>(plane, "tilt_deg");
  result.surface_azimuth_deg = member<double>(plane, "surface_azimuth_deg");
  result.integrated_range_nm = range_of(json, "integrated_range_nm");
  result.wavelengths_nm =
      optional_member<std::vector<double>>(json, "wavelengths_nm").value_or(std::vector<double>{});
  result.direct_normal = component_of(json, "direct_normal");
  result.direct = component_of(json, "direct");
  result.diffuse = component_of(json, "diffuse");
  result.ground_diffuse = component_of(json, "ground_diffuse");
  result.global = component_of(json, "global");
  result.broadband_unavailable = optional_member<std::string>(json, "broadband_unavailable");
  result.fit = applied_fit_of(json);
  return result;
}

IrradianceSeriesResult irradiance_series_of(const nlohmann::json& json) {
  IrradianceSeriesResult result;
  result.model = member<std::string>(json, "model");
  result.columns = member<std::vector<std::string>>(json, "columns");
  result.unanswered_steps = member<std::int64_t>(json, "unanswered_steps");
  const nlohmann::json rows = member<nlohmann::json>(json, "rows");
  for (const nlohmann::json& row : rows) {
    if (!row.is_array() || row.size() != result.columns.size())
      throw Error(0, "invalid_answer", "a row of the series does not match its columns");
    for (std::size_t k = 0; k < result.columns.size(); ++k) {
      const std::string& name = result.columns[k];
      const nlohmann::json& cell = row[k];
      try {
        if (name == "time_utc") {
          result.time_utc.push_back(cell.get<std::string>());
        } else if (name == "time_local") {
          result.time_local.push_back(cell.get<std::string>());
        } else if (name == "night") {
          result.night.push_back(cell.get<bool>());
        } else {
          result.values[name].push_back(cell.is_null() ? std::nan("") : cell.get<double>());
        }
      } catch (const nlohmann::json::exception& e) {
        throw Error(0, "invalid_answer", "column " + name + ": " + e.what());
      }
    }
  }
  result.fit = applied_fit_of(json);
  return result;
}

RgbResult rgb_of(const nlohmann::json& json) {
  RgbResult result;
  result.model = member<std::string>(json, "model");
  result.model_version = member<std::string>(json, "model_version");
  result.quality = optional_member<std::string>(json, "quality").value_or("");
  result.served_quality = optional_member<std::string>(json, "served_quality").value_or("");
  result.method = member<std::string>(json, "method");
  result.sun = sun_used_of(json);
  result.altitude_m = member<double>(json, "altitude_m");
  result.colour_space = member<std::string>(json, "colour_space");
  result.gamut_mapping = member<std::string>(json, "gamut_mapping");
  result.gamut_clipped_samples = member<std::int64_t>(json, "gamut_clipped_samples");
  if (json.contains("integrated_range_nm"))
    result.integrated_range_nm = range_of(json, "integrated_range_nm");
  result.warning = optional_member<std::string>(json, "warning");
  for (const nlohmann::json& s : member<nlohmann::json>(json, "samples")) {
    RgbSample sample;
    sample.view = view_of(s);
    const auto rgb = member<std::vector<double>>(s, "rgb");
    if (rgb.size() != 3) throw Error(0, "invalid_answer", "a sample's rgb is not 3 numbers");
    sample.rgb = {rgb[0], rgb[1], rgb[2]};
    sample.gamut_clipped = member<bool>(s, "gamut_clipped");
    sample.luminance_cd_m2 = member<double>(s, "luminance_cd_m2");
    result.samples.push_back(std::move(sample));
  }
  result.fit = applied_fit_of(json);
  return result;
}

namespace {

// A patch's or the sun's value: an array (spectral, rgb) or one number (luminance).
std::vector<double> patch_value_of(const nlohmann::json& object) {
  const nlohmann::json value = member<nlohmann::json>(object, "value");
  if (value.is_number()) return {value.get<double>()};
  return member<std::vector<double>>(object, "value");
}

}  // namespace

SkyPatchesResult sky_patches_of(const nlohmann::json& json) {
  SkyPatchesResult out;
  out.model = member<std::string>(json, "model");
  out.scheme = member<std::string>(json, "scheme");
  out.mf = member<int>(json, "mf");
  out.output = member<std::string>(json, "output");
  if (const auto wavelengths = optional_member<std::vector<double>>(json, "wavelengths_nm"))
    out.wavelengths_nm = *wavelengths;
  for (const nlohmann::json& p : member<nlohmann::json>(json, "patches")) {
    out.patches.push_back({member<int>(p, "patch"), member<double>(p, "altitude_deg"),
                           member<double>(p, "azimuth_deg"), member<double>(p, "solid_angle_sr"),
                           patch_value_of(p)});
  }
  if (const auto sun = optional_member<nlohmann::json>(json, "sun_source")) {
    out.sun_source =
        SkyPatch{-1, member<double>(*sun, "altitude_deg"), member<double>(*sun, "azimuth_deg"),
                 member<double>(*sun, "solid_angle_sr"), patch_value_of(*sun)};
  }
  out.fit = applied_fit_of(json);
  return out;
}

SkyMatrixResult sky_matrix_of(const nlohmann::json& json) {
  SkyMatrixResult out;
  out.model = member<std::string>(json, "model");
  out.model_version = member<std::string>(json, "model_version");
  out.quality = optional_member<std::string>(json, "quality").value_or("");
  out.served_quality = optional_member<std::string>(json, "served_quality").value_or("");
  out.scheme = member<std::string>(json, "scheme");
  out.mf = member<int>(json, "mf");
  out.output = member<std::string>(json, "output");
  out.unit = member<std::string>(json, "unit");
  if (const auto wavelengths = optional_member<std::vector<double>>(json, "wavelengths_nm"))
    out.wavelengths_nm = *wavelengths;
  out.components =
      out.output == "luminance" ? 1 : (out.output == "rgb" ? 3 : out.wavelengths_nm.size());
  for (const nlohmann::json& p : member<nlohmann::json>(json, "patches")) {
    out.patches.push_back({member<int>(p, "patch"),
                           member<double>(p, "altitude_deg"),
                           member<double>(p, "azimuth_deg"),
                           member<double>(p, "solid_angle_sr"),
                           {}});
  }
  for (const nlohmann::json& t : member<nlohmann::json>(json, "times")) {
    SkyMatrixStep step;
    step.time_utc = member<std::string>(t, "time_utc");
    step.time_local = optional_member<std::string>(t, "time_local");
    step.night = member<bool>(t, "night");
    step.answered = member<bool>(t, "answered");
    step.sun_zenith_deg = member<double>(t, "sun_zenith_deg");
    step.sun_azimuth_deg = member<double>(t, "sun_azimuth_deg");
    if (const auto sun = optional_member<nlohmann::json>(t, "sun_source"))
      step.sun_value = patch_value_of(*sun);
    out.steps.push_back(std::move(step));
  }
  // One row per patch, one entry per step: a number (one component) or an array.
  const nlohmann::json rows = member<nlohmann::json>(json, "matrix");
  if (!rows.is_array() || rows.size() != out.patches.size())
    throw Error(0, "invalid_answer", "the matrix does not have one row per patch");
  out.values.reserve(out.patches.size() * out.steps.size() * out.components);
  for (const nlohmann::json& row : rows) {
    if (!row.is_array() || row.size() != out.steps.size())
      throw Error(0, "invalid_answer", "a row of the matrix does not have one value per step");
    for (const nlohmann::json& cell : row) {
      std::vector<double> value;
      try {
        value = cell.is_number() ? std::vector<double>{cell.get<double>()}
                                 : cell.get<std::vector<double>>();
      } catch (const nlohmann::json::exception& e) {
        throw Error(0, "invalid_answer", std::string("a value of the matrix: ") + e.what());
      }
      if (value.size() != out.components)
        throw Error(0, "invalid_answer", "a value of the matrix does not have its components");
      out.values.insert(out.values.end(), value.begin(), value.end());
    }
  }
  out.unanswered_steps = member<std::int64_t>(json, "unanswered_steps");
  out.fit = applied_fit_of(json);
  return out;
}

}  // namespace clearsky::client::detail
