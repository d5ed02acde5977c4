// The parts every sky query shares, parsed from Parameters into model-layer values:
//
// clang-format off
// | parameter                              | unit   | range                 | meaning                                              |
// |----------------------------------------|--------|-----------------------|------------------------------------------------------|
// | model                                  | -      | a registered id       | which model answers (404 when unknown)               |
// | sun_zenith, sun_azimuth                | degree | [0, 180], [-360, 360] | the sun given directly (azimuth clockwise from North) |
// | lat, lon, time, altitude, pressure, ... | see api/request/place_time.h | | place and time; the sun from NREL SPA     |
// | alpha, beta, g, turbidity, albedo, ... | per descriptor | per descriptor | atmosphere and model parameters the model's descriptor lists |
// | fit                                    | -      | ID, latest, latest:DATASET | a stored fit's values (api/request/sky_fit.h) |
// | wavelengths                            | nm     | list or start:stop:step | output wavelengths (default: the paper's 40 bins)  |
// clang-format on
//
// altitude is also the viewpoint when the sun is given. The sun is either given or computed,
// never both (conflicting parameters are a 400). Parameters a model's descriptor does not list
// are left unread, so reject_unused() names them.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "api/request/parameters.h"
#include "api/request/quality.h"
#include "api/request/sky_fit.h"
#include "api/service/model_provider.h"
#include "models/core/sky_model.h"

namespace clearsky::api {

// Request limits from the server configuration (413 above them).
struct Limits {
  std::size_t max_views = 10000;       // views in one radiance/rgb batch
  std::size_t max_wavelengths = 2000;  // wavelengths in one request
  int max_skydome_size = 4096;         // pixels (width of the image)
};

struct SunSpec {
  SunPosition sun;  // radians
  double zenith_deg = 0;
  double azimuth_deg = 0;
  bool from_place_and_time = false;
  // The instant (UTC, unix seconds) of a sun given by place and time; empty for one given by
  // its angles.
  std::optional<double> unix_time_utc_s;
  // The parameter to name when the model cannot answer for this sun.
  std::string parameter = "sun_zenith";
};

const ModelFactory& parse_model(Parameters& p, const ModelProvider& provider);
SunSpec parse_sun(Parameters& p);
Viewpoint parse_viewpoint(Parameters& p);
// The model's configuration and the fit that set part of it.
struct SkyConfig {
  ModelConfig config;
  std::optional<AppliedFit> fit;  // the request's fit=, expanded into config
};
// The model's configuration with the request's overrides of the parameters its descriptor
// lists (400 naming the parameter for a value out of range), a stored fit's values included
// (fit=, expanded by expand_fit through fits and then read as any parameter): every sky
// endpoint reads its model's parameters here.
SkyConfig parse_sky_config(Parameters& p, const ModelDescriptor& descriptor, const FitLookup& fits);
// validate_config (models/core/sky_model.h) with its refusals (clearsky::InvalidInput) as a 400
// naming the request parameter (from_invalid_argument).
void validate_model_config(const ModelDescriptor& descriptor, const ModelConfig& config);
// wavelengths: "400,500,600" or "start:stop:step" (stop included within rounding); absent:
// nullopt.
std::optional<std::vector<double>> parse_wavelengths(Parameters& p, const Limits& limits);

// A built model and which of its grid's wavelengths the request asked for.
struct ModelOnGrid {
  std::shared_ptr<const SkyModel> model;
  std::vector<std::size_t> indices;  // into model->wavelengths()
  std::vector<double> wavelengths_nm;
  // The quality whose tables answered (the request's, or draft while standard builds:
  // docs/quality-levels.md "Serving at once").
  QualityLevel served_quality = QualityLevel::standard;
};

// Wavelengths all on the configured grid are read from its tables; any other list selects a
// model built on exactly those wavelengths (a point grid), through the provider. Throws 422
// for a wavelength outside the model's spectral range. requester: who asks (the server limits
// the builds a client triggers). quality: the request's level (config has it applied); null for
// the server's own work, answered at config as it is.
ModelOnGrid model_on_wavelengths(const ModelProvider& provider, const ModelFactory& factory,
                                 ModelConfig config,
                                 const std::optional<std::vector<double>>& wavelengths,
                                 const ModelRequester& requester,
                                 const RequestQuality* quality = nullptr);

// 422 (or 500 for numerical_failure) naming parameter, when status is not ok.
void require_answer(SampleStatus status, const std::string& parameter, const std::string& model_id);
// The sun state (shared through the provider), with the checks of require_answer on the sun.
std::shared_ptr<const SunState> prepare_sun(const ModelProvider& provider,
                                            const std::shared_ptr<const SkyModel>& model,
                                            const SunSpec& sun);

// Applies one atmosphere parameter by its request name; false when the name is not one.
bool set_atmosphere_parameter(AtmosphereParameters& atmosphere, const std::string& name,
                              double value);

}  // namespace clearsky::api
