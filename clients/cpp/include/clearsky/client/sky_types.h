// The requests and answers of the sky endpoints (docs/http-api.md; the parameters in
// /openapi.json): the sun, the models, radiance, irradiance, RGB and the skydome. Angles are in
// degrees (zenith from the local vertical, azimuth clockwise from North), as at the API; the
// unit of every number is in its name.
//
// Model and atmosphere parameters are open-ended (each model lists its own: GET /v1/models,
// Client::models()), so they are a map from the parameter's name to a number or a text
// ("grass" for albedo); the server refuses a name the model does not take (400
// unknown_parameter naming it).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace clearsky::client {

// A parameter's value: a number, or a text where the API takes one (albedo "grass").
using ParameterValue = std::variant<double, std::string>;
using Parameters = std::map<std::string, ParameterValue>;

// The sun given directly.
struct SunAngles {
  double zenith_deg = 0;
  double azimuth_deg = 0;
};

// The sun computed by the server (NREL SPA) from a place and a time.
struct PlaceTime {
  std::string latitude;   // degrees North, decimal ("42.444") or DMS ("42d26'36\"N")
  std::string longitude;  // degrees East, decimal or DMS
  std::string time;       // ISO 8601 with a UTC offset or Z
  std::optional<double> pressure_mbar;
  std::optional<double> temperature_c;
  std::optional<double> delta_t_s;  // TT - UT1
  std::optional<bool> refraction;
};

// What every sky query shares: the model, the sun (exactly one of sun and place_time), the
// observer's altitude and the model's parameters.
struct SkyQuery {
  std::string model;  // "preetham", "hosek", ... (Client::models())
  std::optional<SunAngles> sun;
  std::optional<PlaceTime> place_time;
  std::optional<double> altitude_m;
  Parameters parameters;
  // "draft", "standard" or "reference" (docs/quality-levels.md); absent: the server's level.
  std::optional<std::string> quality;
  // A stored fit whose values set the parameters it fitted (docs/fits.md "Using a fit"): its
  // id ("12"), "latest" (the model's newest succeeded fit) or "latest:DATASET".
  std::optional<std::string> fit;
};

// The stored fit an answer was computed with (the answer's `fit` member).
struct AppliedFit {
  std::int64_t id = 0;
  std::string model;
  std::string model_version;
  std::string dataset;
  std::map<std::string, double> parameters;  // the fitted values it set
};

// A viewing direction.
struct ViewDirection {
  double zenith_deg = 0;
  double azimuth_deg = 0;
};

// GET /v1/sun.
struct SunRequest {
  PlaceTime place_time;
  std::optional<double> altitude_m;
};
struct SunPosition {
  double zenith_deg = 0;   // topocentric, refraction applied unless refraction=false
  double azimuth_deg = 0;  // clockwise from North
  // ISO 8601 in the request's UTC offset; absent in polar day or night.
  std::optional<std::string> sunrise, transit, sunset;
  std::string day;  // "normal", "polar_day", "polar_night"
};

// The sun a model was asked for.
struct SunUsed {
  double zenith_deg = 0;
  double azimuth_deg = 0;  // normalised to [0, 360)
  std::string source;      // "given" or "spa"
};

// GET /v1/models.
struct ModelParameterInfo {
  std::string name;
  std::string unit;  // empty when dimensionless
  std::string description;
  std::optional<double> default_value;
  std::optional<double> min, max;  // inclusive; absent when unbounded
  bool integer = false;
  std::string kind;  // "atmosphere" or "model"
};
// What a model can answer (models/core/model_descriptor.h).
struct ModelCapabilities {
  std::optional<double> min_altitude_m, max_altitude_m;  // absent: unbounded
  bool view_from_space = false;
  bool view_below_horizon = false;
  bool aerial_perspective = false;
  double max_sun_zenith_deg = 0;
  bool sun_below_horizon = false;
  // Beyond this sun zenith the model answers zeros at once; absent: none declared.
  std::optional<double> dark_beyond_sun_zenith_deg;
  std::optional<int> scattering_orders;  // absent: all orders
  bool per_sun_precomputation = false;
  bool sun_irradiance = false;
  bool sky_irradiance = false;
};
struct ModelInfo {
  std::string id;  // the value of SkyQuery::model
  std::string name;
  std::string version;
  std::string citation;
  std::string summary;
  std::vector<double> native_wavelengths_nm;  // empty: any wavelength in the range
  std::optional<double> min_wavelength_nm, max_wavelength_nm;
  std::vector<ModelParameterInfo> parameters;
  ModelCapabilities capabilities;
  std::string
      table_status;  // the default tables: "queued", "precomputing", "ready", "failed", "not_built"
  double table_progress = 0;  // 0..1
};

// GET /v1/radiance (one view) and POST /v1/radiance (a batch).
struct RadianceRequest : SkyQuery {
  ViewDirection view;
  std::vector<double> wavelengths_nm;  // empty: the model's default grid
};
struct RadianceBatchRequest : SkyQuery {
  std::vector<ViewDirection> views;
  std::vector<double> wavelengths_nm;
};
struct RadianceSample {
  ViewDirection view;
  std::vector<double> radiance_w_m2_sr_nm;  // one per RadianceResult::wavelengths_nm
};
struct RadianceResult {
  std::string model;
  std::string model_version;
  // The quality level asked and the one whose tables answered (draft while standard builds);
  // empty from a server without quality levels.
  std::string quality, served_quality;
  SunUsed sun;
  double altitude_m = 0;
  std::string unit;  // "W/(m2.sr.nm)"
  std::string grid;  // "bins" (each value the mean over its bin) or "points"
  std::optional<double> bin_width_nm;
  std::vector<double> wavelengths_nm;
  std::vector<RadianceSample> samples;  // in the order of the request's views
  std::optional<AppliedFit> fit;        // with SkyQuery::fit
};

// GET /v1/irradiance on a plane.
struct IrradianceRequest : SkyQuery {
  std::optional<double> tilt_deg;
  std::optional<double> surface_azimuth_deg;
  // "all" (default), "direct", "diffuse", "ground_diffuse", "global"
  std::optional<std::string> component;
  bool spectral = false;  // add each component's spectrum
  // "include" (default) or "exclude": the isotropic ground's reflection on the plane.
  std::optional<std::string> ground_reflection;
  // The ground's albedo in [0, 1]; absent: the model's ground albedo spectrum.
  std::optional<double> ground_albedo;
  // The absorbers of the broadband figures (server defaults: 1.42 cm, 0.34 atm-cm).
  std::optional<double> precipitable_water_cm;
  std::optional<double> ozone_atm_cm;
};
struct IrradianceComponent {
  double irradiance_w_m2 = 0;              // deprecated alias of model_range_irradiance_w_m2
  double model_range_irradiance_w_m2 = 0;  // over integrated_range_nm
  // 300..4000 nm with molecular absorption; empty when the model cannot go broadband
  // (IrradianceResult::broadband_unavailable says why).
  std::optional<double> broadband_irradiance_w_m2;
  double illuminance_lx = 0;
  std::vector<double> spectral_w_m2_nm;  // with spectral=true
};
struct IrradianceResult {
  std::string model;
  std::string model_version;
  std::string quality, served_quality;  // as RadianceResult's
  SunUsed sun;
  double altitude_m = 0;
  double tilt_deg = 0;
  double surface_azimuth_deg = 0;
  std::array<double, 2> integrated_range_nm{};
  std::vector<double> wavelengths_nm;  // with spectral=true
  // The components present follow IrradianceRequest::component.
  // ground_diffuse: albedo x global horizontal x (1 - cos tilt) / 2; global includes it.
  std::optional<IrradianceComponent> direct_normal, direct, diffuse, ground_diffuse, global;
  // Why there are no broadband figures (empty when there are).
  std::optional<std::string> broadband_unavailable;
  std::optional<AppliedFit> fit;  // with SkyQuery::fit
};

// GET /v1/irradiance/series: a place from start to end every step, on the horizontal and on
// planes (docs/building-energy.md "Irradiance time series").
struct IrradianceSeriesRequest {
  std::string model;
  std::string latitude;   // degrees North, decimal or DMS
  std::string longitude;  // degrees East, decimal or DMS
  std::string start;      // ISO 8601 with an offset or Z, or a local time in tz
  std::string end;
  std::optional<std::string> tz;    // IANA zone ("Europe/Paris")
  std::optional<std::string> step;  // ISO 8601 duration, "PT1H" (default), "PT10M"
  struct Plane {
    double tilt_deg = 0;
    double surface_azimuth_deg = 180;
  };
  std::vector<Plane> planes;
  std::optional<double> altitude_m;
  std::optional<std::string> ground_reflection;  // "include" (default) or "exclude"
  std::optional<double> ground_albedo;
  Parameters parameters;               // the model's
  std::optional<std::string> quality;  // as SkyQuery's
  std::optional<std::string> fit;      // as SkyQuery's
};
// One column per name of `columns` (pvlib's: ghi, dni, dhi, poa_global_30_180, ...): the
// times as text, night as 0/1 in `values`, a value the model could not answer as NaN.
struct IrradianceSeriesResult {
  std::string model;
  std::vector<std::string> columns;
  std::vector<std::string> time_utc;
  std::vector<std::string> time_local;  // with tz
  std::vector<bool> night;
  // Every numeric column by name (solar_zenith, ghi, poa_global_30_180, ...).
  std::map<std::string, std::vector<double>> values;
  std::int64_t unanswered_steps = 0;
  std::optional<AppliedFit> fit;
};

// GET /v1/rgb (one view) and POST /v1/rgb (a batch): linear sRGB, radiometric
// (docs/http-api.md "RGB").
struct RgbRequest : SkyQuery {
  ViewDirection view;
  std::optional<std::string> method;  // "spectral" (default) or "three"
};
struct RgbBatchRequest : SkyQuery {
  std::vector<ViewDirection> views;
  std::optional<std::string> method;
};
struct RgbSample {
  ViewDirection view;
  std::array<double, 3> rgb{};  // never negative: see gamut_clipped
  bool gamut_clipped = false;
  double luminance_cd_m2 = 0;  // 683 Y before any clipping
};
struct RgbResult {
  std::string model;
  std::string model_version;
  std::string quality, served_quality;  // as RadianceResult's
  std::string method;
  SunUsed sun;
  double altitude_m = 0;
  std::string colour_space;
  std::string gamut_mapping;
  std::int64_t gamut_clipped_samples = 0;
  std::optional<std::array<double, 2>> integrated_range_nm;  // method=spectral
  std::optional<std::string> warning;
  std::vector<RgbSample> samples;
  std::optional<AppliedFit> fit;  // with SkyQuery::fit
};

// GET /v1/skydome: an OpenEXR image, streamed.
struct SkydomeRequest : SkyQuery {
  std::optional<std::string> projection;  // "fisheye" (default), "latlong", "cubemap"
  std::optional<int> size_px;             // image width (even for latlong)
  std::optional<std::string> channels;    // "rgb" (default), "luminance", "spectral"
  std::optional<std::string> pixel_type;  // "half" or "float"
  std::optional<std::string> method;      // channels=rgb: "spectral" or "three"
  std::vector<double> wavelengths_nm;     // channels=spectral
};
struct SkydomeDownload {
  std::string content_type;  // "image/x-exr"
  std::uint64_t bytes = 0;   // written to the stream or file
};

// The patches of GET /v1/skypatches, for one vector and for a matrix alike.
struct SkyPatchOptions {
  std::optional<std::string> scheme;         // "tregenza" (default) or "reinhart"
  std::optional<int> mf;                     // Reinhart subdivision, 1..6
  std::optional<std::string> sun_handling;   // the query's sun: "separate" (default) or "patch"
  std::optional<std::string> output;         // "spectral" (default), "rgb" or "luminance"
  std::optional<double> ground_reflectance;  // the ground patch's Lambertian reflectance
  std::vector<double> wavelengths_nm;        // spectral output; empty: the model's grid
};

// GET /v1/skypatches: the sky vector of Radiance's daylight-coefficient tools
// (docs/building-energy.md "Sky-patch vectors"), in Radiance's patch order.
struct SkyPatchesRequest : SkyQuery, SkyPatchOptions {};
// One patch (patch 0 is the ground) or the separate sun: its value is the radiance averaged
// over its solid angle, W/(m2.sr.nm) per wavelength (spectral), Radiance's RGB (3 values) or
// the luminance in cd/m2 (1 value).
struct SkyPatch {
  int patch = 0;  // -1 for the separate sun
  double altitude_deg = 0;
  double azimuth_deg = 0;  // clockwise from North
  double solid_angle_sr = 0;
  std::vector<double> value;
};
struct SkyPatchesResult {
  std::string model;
  std::string scheme;
  int mf = 1;
  std::string output;
  std::vector<double> wavelengths_nm;  // spectral output
  std::vector<SkyPatch> patches;
  std::optional<SkyPatch> sun_source;  // with sun_handling "separate" and the sun up
  std::optional<AppliedFit> fit;
};

// GET /v1/skypatches with start: a sky matrix (docs/building-energy.md "Sky matrices"), one sky
// vector per step from start to end at a place, the instants as IrradianceSeriesRequest's.
struct SkyMatrixRequest : SkyPatchOptions {
  std::string model;
  std::string latitude;   // degrees North, decimal or DMS
  std::string longitude;  // degrees East, decimal or DMS
  std::string start;      // ISO 8601 with an offset or Z, or a local time in tz
  std::string end;
  std::optional<std::string> tz;    // IANA zone
  std::optional<std::string> step;  // ISO 8601 duration, "PT1H" (default)
  std::optional<double> altitude_m;
  Parameters parameters;  // the model's
  std::optional<std::string> quality;
  std::optional<std::string> fit;
};
// One step (a column of the matrix).
struct SkyMatrixStep {
  std::string time_utc;
  std::optional<std::string> time_local;  // with tz
  bool night = false;                     // a column of zeros
  bool answered = true;                   // false: the model could not answer this sun
  double sun_zenith_deg = 0;
  double sun_azimuth_deg = 0;
  // With sun_handling "separate" and the sun up: the sun as its own source.
  std::optional<std::vector<double>> sun_value;
};
struct SkyMatrixResult {
  std::string model;
  std::string model_version;
  std::string quality, served_quality;
  std::string scheme;
  int mf = 1;
  std::string output;
  std::string unit;
  std::vector<double> wavelengths_nm;  // spectral output
  std::vector<SkyPatch> patches;       // their geometry (value empty), patch 0 the ground
  std::vector<SkyMatrixStep> steps;
  std::size_t components = 1;  // 1 (luminance), 3 (rgb) or the wavelengths (spectral)
  // Patch-major: the value of (patch, step, component) is
  // values[(patch * steps.size() + step) * components + component].
  std::vector<double> values;
  std::int64_t unanswered_steps = 0;
  std::optional<AppliedFit> fit;

  double value(std::size_t patch, std::size_t step, std::size_t component = 0) const {
    return values.at((patch * steps.size() + step) * components + component);
  }
};

}  // namespace clearsky::client
