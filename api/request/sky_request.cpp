// Parsing of the shared sky-query parameters and the capability checks around them.
#include "api/request/sky_request.h"

#include <cmath>
#include <sstream>

#include "api/error/api_error.h"
#include "api/request/aerosols_option.h"
#include "api/request/place_time.h"
#include "models/atmosphere/atmosphere_parameter_table.h"
#include "models/core/numeric.h"

namespace clearsky::api {

const ModelFactory& parse_model(Parameters& p, const ModelProvider& provider) {
  const std::string id = p.required_text("model");
  std::string available;
  for (const ModelFactory& f : provider.factories()) {
    if (f.descriptor->id == id) return f;
    available += (available.empty() ? "" : ", ") + f.descriptor->id;
  }
  throw unknown_model(id, available);
}

SunSpec parse_sun(Parameters& p) {
  SunSpec spec;
  const bool given = p.has_any({"sun_zenith", "sun_azimuth"});
  if (given) {
    for (const char* name : {"lat", "lon", "time"}) {
      if (p.has(name)) throw conflicting_parameters(name, "sun_zenith/sun_azimuth");
    }
    spec.zenith_deg = p.required_number("sun_zenith", 0.0, 180.0);
    spec.azimuth_deg = p.required_number("sun_azimuth", -360.0, 360.0);
    spec.azimuth_deg = std::fmod(spec.azimuth_deg + 360.0, 360.0);
  } else {
    if (!p.has_any({"lat", "lon", "time"})) {
      throw missing_parameter("sun_zenith",
                              "give sun_zenith and sun_azimuth, or lat, lon and time");
    }
    const SolarPositionInput input = parse_place_and_time(p, std::nullopt).position;
    const SolarPosition position = solar_position_checked(input);
    spec.unix_time_utc_s = input.unix_time_utc_s;
    spec.zenith_deg = position.zenith_deg;
    spec.azimuth_deg = position.azimuth_deg;
    spec.from_place_and_time = true;
    spec.parameter = "time";
  }
  spec.sun = {degrees_to_radians(spec.zenith_deg), degrees_to_radians(spec.azimuth_deg)};
  return spec;
}

Viewpoint parse_viewpoint(Parameters& p) { return {parse_altitude_m(p)}; }

bool set_atmosphere_parameter(AtmosphereParameters& a, const std::string& name, double value) {
  return clearsky::set_atmosphere_parameter(a, name, value);
}

namespace {

ModelConfig parse_config(Parameters& p, const ModelDescriptor& descriptor) {
  ModelConfig config;
  for (const ParameterSpec& spec : descriptor.parameters) {
    if (!p.has(spec.name)) continue;
    if (spec.atmosphere && spec.name == "albedo" && p.has("albedo")) {
      // "grass" selects the spectral albedo of grass (the study's default).
      const std::string text = *p.text("albedo");
      if (text == "grass") {
        config.atmosphere.ground_albedo.reset();
        continue;
      }
      const double value = number_value("albedo", text);
      if (!(value >= spec.min_value && value <= spec.max_value)) {
        throw invalid_parameter("albedo", "must be 'grass' or a number in [0, 1]");
      }
      config.atmosphere.ground_albedo = value;
      continue;
    }
    const double value = *p.number(spec.name, spec.min_value, spec.max_value);
    if (spec.integer && value != std::floor(value))
      throw invalid_parameter(spec.name, "must be an integer");
    check_aerosols_option(spec.name, value);
    if (spec.atmosphere) {
      if (!set_atmosphere_parameter(config.atmosphere, spec.name, value)) {
        throw std::logic_error("descriptor of " + descriptor.id +
                               " lists unknown atmosphere parameter " + spec.name);
      }
    } else {
      config.options[spec.name] = value;
    }
  }
  // Each value is within its descriptor range, which lies within the atmosphere table's; the
  // configuration as a whole is validated once, by the model provider (the server's TableStore
  // before it queues a build) and once per build (models/core/model_factory.h).
  return config;
}

}  // namespace

SkyConfig parse_sky_config(Parameters& p, const ModelDescriptor& descriptor,
                           const FitLookup& fits) {
  SkyConfig out;
  out.fit = expand_fit(p, descriptor, fits);
  try {
    out.config = parse_config(p, descriptor);
  } catch (const ApiError& e) {
    if (!out.fit) throw;
    for (const auto& [name, value] : out.fit->values) {
      // A fitted value the descriptor's range no longer holds: say where it came from.
      if (name == e.parameter()) {
        throw ApiError(
            e.status(), e.code(), e.parameter(),
            std::string(e.what()) + " (the value of fit " + std::to_string(out.fit->id) + ")");
      }
    }
    throw;
  }
  return out;
}

void validate_model_config(const ModelDescriptor& descriptor, const ModelConfig& config) {
  try {
    validate_config(descriptor, config);
  } catch (const std::invalid_argument& e) {
    throw from_invalid_argument(e);
  }
}

std::optional<std::vector<double>> parse_wavelengths(Parameters& p, const Limits& limits) {
  const auto text = p.text("wavelengths");
  if (!text) return std::nullopt;
  std::vector<double> nm;
  if (text->find(':') != std::string::npos) {
    std::vector<double> parts;
    std::size_t begin = 0;
    while (true) {
      const std::size_t end = text->find(':', begin);
      parts.push_back(
          number_value("wavelengths", std::string_view(*text).substr(begin, end - begin)));
      if (end == std::string::npos) break;
      begin = end + 1;
    }
    if (parts.size() != 3) throw invalid_parameter("wavelengths", "a range is start:stop:step");
    const double start = parts[0], stop = parts[1], step = parts[2];
    if (!(step > 0.0)) throw invalid_parameter("wavelengths", "the step must be positive");
    if (!(stop >= start)) throw invalid_parameter("wavelengths", "stop must not be below start");
    const double count = std::floor((stop - start) / step + 1e-9) + 1.0;
    if (count > static_cast<double>(limits.max_wavelengths)) {
      throw too_large("wavelengths",
                      "at most " + std::to_string(limits.max_wavelengths) + " wavelengths");
    }
    for (long i = 0; i < static_cast<long>(count); ++i)
      nm.push_back(start + step * static_cast<double>(i));
  } else {
    std::size_t begin = 0;
    while (true) {
      const std::size_t end = text->find(',', begin);
      nm.push_back(number_value("wavelengths", std::string_view(*text).substr(begin, end - begin)));
      if (nm.size() > limits.max_wavelengths) {
        throw too_large("wavelengths",
                        "at most " + std::to_string(limits.max_wavelengths) + " wavelengths");
      }
      if (end == std::string::npos) break;
      begin = end + 1;
    }
  }
  for (std::size_t i = 0; i < nm.size(); ++i) {
    if (!(nm[i] > 0.0 && nm[i] <= 1e5))
      throw invalid_parameter("wavelengths", "each must be in (0, 100000] nm");
    if (i > 0 && !(nm[i] > nm[i - 1]))
      throw invalid_parameter("wavelengths", "must be strictly increasing");
  }
  return nm;
}

ModelOnGrid model_on_wavelengths(const ModelProvider& provider, const ModelFactory& factory,
                                 ModelConfig config,
                                 const std::optional<std::vector<double>>& wavelengths,
                                 const ModelRequester& requester, const RequestQuality* quality) {
  ModelOnGrid out;
  if (quality != nullptr) out.served_quality = quality->level;
  const ModelDescriptor& d = *factory.descriptor;
  if (wavelengths) {
    for (double w : *wavelengths) {
      if (w < d.min_wavelength_nm - 1e-9 || w > d.max_wavelength_nm + 1e-9) {
        std::ostringstream reason;
        reason << w << " nm is outside its spectral range [" << d.min_wavelength_nm << ", "
               << d.max_wavelength_nm << "] nm";
        throw cannot_answer("wavelengths", d.id, reason.str());
      }
    }
    bool on_grid = true;
    for (double w : *wavelengths)
      on_grid = on_grid && config.wavelengths.index_of(w) < config.wavelengths.size();
    if (!on_grid) config.wavelengths = WavelengthGrid::points(*wavelengths);
  }
  // A standard request of its level's own setting may be answered from the draft tables while
  // the standard ones are being built (docs/quality-levels.md "Serving at once"); reference
  // waits like any build. The draft's configuration is made only when the provider needs it.
  struct DraftInputs {
    const ModelConfig* config;
    const RequestQuality* quality;
    const ModelDescriptor* descriptor;
  } const inputs{&config, quality, &d};
  ModelProvider::FallbackConfig draft;
  if (quality != nullptr && quality->level == QualityLevel::standard &&
      quality->overridden.empty()) {
    // One pointer captured: std::function keeps it without allocating.
    draft = [in = &inputs]() -> std::optional<ModelConfig> {
      ModelConfig draft_config = *in->config;
      for (const auto& [name, value] : in->quality->table_row->options)
        draft_config.options.erase(name);
      apply_quality_level(*in->descriptor, quality_setting(in->descriptor->id, QualityLevel::draft),
                          draft_config.options);
      // Only the options differ between the two (a structural comparison: building both
      // canonical strings cost a third of a radiance answer's instructions under callgrind).
      if (draft_config.options == in->config->options) return std::nullopt;
      return draft_config;
    };
  }
  ModelProvider::ServedModel served;
  try {
    served = provider.model_or_fallback(factory, config, draft, requester);
  } catch (const ApiError& e) {
    // A build still under way: say which level it is (docs/quality-levels.md).
    if (e.status() != 503 || e.code() != "model_not_ready" || quality == nullptr) throw;
    throw ApiError(
        503, e.code(), e.parameter(),
        std::string(e.what()) + " (quality " + std::string(to_string(quality->level)) + ")",
        e.retry_after_s());
  }
  out.model = served.model;
  if (served.fallback) out.served_quality = QualityLevel::draft;
  const WavelengthGrid& grid = out.model->wavelengths();
  // Reserved once: grown one push at a time, the two lists were 14 allocations a request.
  out.indices.reserve(wavelengths ? wavelengths->size() : grid.size());
  if (wavelengths) {
    for (double w : *wavelengths) out.indices.push_back(grid.index_of(w));
  } else {
    const SkyModel::WavelengthRange answered = out.model->answered_wavelengths();
    for (std::size_t i = answered.first; i < answered.end; ++i) out.indices.push_back(i);
  }
  if (out.indices.empty())
    throw cannot_answer("wavelengths", d.id, "no wavelength of the grid is in its spectral range");
  out.wavelengths_nm.reserve(out.indices.size());
  for (std::size_t i : out.indices) out.wavelengths_nm.push_back(grid[i]);
  return out;
}

void require_answer(SampleStatus status, const std::string& parameter,
                    const std::string& model_id) {
  if (status == SampleStatus::ok) return;
  if (status == SampleStatus::numerical_failure) {
    throw ApiError(500, "numerical_failure", parameter,
                   "model " + model_id + ": " + std::string(describe(status)));
  }
  throw cannot_answer(parameter, model_id, std::string(describe(status)));
}

std::shared_ptr<const SunState> prepare_sun(const ModelProvider& provider,
                                            const std::shared_ptr<const SkyModel>& model,
                                            const SunSpec& sun) {
  require_answer(model->check_sun(sun.sun), sun.parameter, model->descriptor().id);
  return provider.sun_state(model, sun.sun);
}

}  // namespace clearsky::api
