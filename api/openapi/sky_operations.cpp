// The sky operations (openapi_area.h): the sun, spectral radiance, irradiance, colour and the
// skydome image (api/handlers/*, api/skydome/skydome_render.h). Parameter ranges are those the
// handlers check (api/request/views.h, api/request/sky_request.cpp, api/parse/sun_request.h);
// the 413 limits are the defaults of Limits (api/request/sky_request.h), which the server's
// --max-views, --max-wavelengths and --max-skydome-size change. The examples are answers of a
// server started with --models preetham,hosek (the 503: with bruneton, its tables building).
#include "api/openapi/openapi_area.h"
#include "api/request/sky_request.h"
#include "api/skydome/skydome_options.h"

namespace clearsky::api::openapi {
namespace {

Json schemas() {
  Json s = parse(R"json({
  "Sun": {
    "type": "object",
    "description": "The sun from NREL SPA and the local day's sunrise, transit and sunset (ISO 8601 in the request's UTC offset; null in polar day or night).",
    "required": ["zenith", "azimuth", "sunrise", "transit", "sunset", "day", "delta_t_s", "delta_t_source"],
    "additionalProperties": false,
    "properties": {
      "zenith": {"type": "number", "minimum": 0, "maximum": 180, "description": "Topocentric zenith angle, degrees (refraction applied unless refraction=false)."},
      "azimuth": {"type": "number", "minimum": 0, "maximum": 360, "description": "Degrees clockwise from North."},
      "sunrise": {"type": "string", "nullable": true},
      "transit": {"type": "string", "nullable": true},
      "sunset": {"type": "string", "nullable": true},
      "day": {"type": "string", "enum": ["normal", "polar_day", "polar_night"]},
      "delta_t_s": {"type": "number", "description": "TT - UT1 used by SPA, seconds: the request's delta_t, or the Espenak-Meeus expression for the year and month of time (years -1999 to 3000)."},
      "delta_t_source": {"type": "string", "enum": ["espenak_meeus", "given"]}
    }
  },
  "QualityError": {
    "type": "object",
    "description": "The relative error of the served level's setting against the model's reference level, over the sample of docs/quality-levels.md (suns at zenith 20 to 85 degrees, views every 5 x 15 degrees, 440, 550 and 680 nm); null members where not measured.",
    "required": ["against", "p95_relative", "max_relative"],
    "additionalProperties": false,
    "properties": {
      "against": {"type": "string", "enum": ["reference", "finer_setting"], "description": "reference: the model's reference level; finer_setting: the reference level's own figures, its difference to a finer setting it was checked against (docs/quality-levels.md)."},
      "p95_relative": {"type": "number", "minimum": 0, "nullable": true, "description": "95th percentile of |L - L_ref| / L_ref."},
      "max_relative": {"type": "number", "minimum": 0, "nullable": true, "description": "Its maximum."}
    }
  },
  "AppliedFit": {
    "type": "object",
    "description": "The stored fit the request named (fit=) and the values it set (docs/fits.md \"Using a fit\").",
    "required": ["id", "model", "model_version", "dataset", "parameters"],
    "additionalProperties": false,
    "properties": {
      "id": {"type": "integer", "minimum": 1},
      "model": {"type": "string"},
      "model_version": {"type": "string", "description": "The model's version when it was fitted."},
      "dataset": {"type": "string", "description": "The dataset it was fitted to."},
      "parameters": {"type": "object", "additionalProperties": {"type": "number"}, "description": "The fitted values used, by parameter name."}
    }
  },
  "SunUsed": {
    "type": "object",
    "description": "The sun the model was asked for: given, or computed by SPA from lat, lon and time.",
    "required": ["zenith_deg", "azimuth_deg", "source"],
    "additionalProperties": false,
    "properties": {
      "zenith_deg": {"type": "number", "minimum": 0, "maximum": 180},
      "azimuth_deg": {"type": "number", "minimum": 0, "maximum": 360, "description": "Clockwise from North, normalised to [0, 360)."},
      "source": {"type": "string", "enum": ["given", "spa"]}
    }
  },
  "View": {
    "type": "object",
    "required": ["view_zenith", "view_azimuth"],
    "additionalProperties": false,
    "properties": {
      "view_zenith": {"type": "number", "minimum": 0, "maximum": 180, "description": "Degrees from the local vertical."},
      "view_azimuth": {"type": "number", "minimum": -360, "maximum": 360, "description": "Degrees clockwise from North."}
    }
  },
  "ViewPair": {
    "type": "array",
    "description": "[view_zenith, view_azimuth], degrees.",
    "minItems": 2,
    "maxItems": 2,
    "items": {"type": "number", "minimum": -360, "maximum": 360}
  },
  "ViewBatch": {
    "type": "array",
    "description": "Viewing directions; the batch fails as a whole on its first view the model cannot answer, naming it (views[3]). Above the server's limit (--max-views, default 10000): 413.",
    "minItems": 1,
    "items": {"oneOf": [{"$ref": "#/components/schemas/View"}, {"$ref": "#/components/schemas/ViewPair"}]}
  },
  "RadianceSample": {
    "type": "object",
    "required": ["view_zenith_deg", "view_azimuth_deg", "radiance"],
    "additionalProperties": false,
    "properties": {
      "view_zenith_deg": {"type": "number"},
      "view_azimuth_deg": {"type": "number"},
      "radiance": {"type": "array", "items": {"type": "number", "minimum": 0}, "description": "W/(m2.sr.nm), one per wavelengths_nm."}
    }
  },
  "Radiance": {
    "type": "object",
    "required": ["model", "model_version", "quality", "served_quality", "quality_setting", "quality_error", "sun", "altitude_m", "unit", "grid", "wavelengths_nm", "samples"],
    "additionalProperties": false,
    "properties": {
      "model": {"type": "string"},
      "model_version": {"type": "string"},
      "quality": {"type": "string", "enum": ["draft", "standard", "reference"], "description": "The quality level asked (quality=, else the server's --quality; docs/quality-levels.md)."},
      "served_quality": {"type": "string", "enum": ["draft", "standard", "reference"], "description": "The level whose tables answered: quality, or draft while the standard tables are being built (then Cache-Control: no-store)."},
      "quality_setting": {"type": "object", "additionalProperties": {"type": "number"}, "description": "Every option of the served level, with the value used (a request's explicit option included)."},
      "quality_error": {"type": "object", "allOf": [{"$ref": "#/components/schemas/QualityError"}], "nullable": true, "description": "The served level's measured error against the reference level; null when the request overrode one of the level's options."},
      "quality_overridden": {"type": "array", "items": {"type": "string"}, "description": "The level's options the request gave itself (present only then)."},
      "fit": {"$ref": "#/components/schemas/AppliedFit"},
      "sun": {"$ref": "#/components/schemas/SunUsed"},
      "altitude_m": {"type": "number"},
      "unit": {"type": "string", "enum": ["W/(m2.sr.nm)"]},
      "grid": {"type": "string", "enum": ["bins", "points"], "description": "bins: each value is the mean over its bin (the paper's 40 bins); points: the value at the wavelength."},
      "bin_width_nm": {"type": "number", "description": "With grid=bins."},
      "wavelengths_nm": {"type": "array", "items": {"type": "number"}},
      "samples": {"type": "array", "items": {"$ref": "#/components/schemas/RadianceSample"}}
    }
  },
  "RadianceCsv": {
    "type": "string",
    "description": "format=csv: a header line, then one row per view and wavelength: view_zenith_deg,view_azimuth_deg,wavelength_nm,radiance_w_m2_sr_nm."
  },
  "SkyPatchesCsv": {
    "type": "string",
    "description": "format=csv: a header line (patch,altitude_deg,azimuth_deg,solid_angle_sr, then L_<nm>nm per wavelength, R,G,B, or luminance_cd_m2), one row per patch from 0 (the ground) in Radiance's order, then a row named sun with the sun's disk when sun=separate and the sun is up. With start (a sky matrix): a header line (patch,altitude_deg,azimuth_deg,solid_angle_sr, then one column per step and component, named by the step's UTC time with _R, _G, _B or _<nm>nm), a row named night (1 for a night step, 0 otherwise), then one row per patch from 0."
  },
  "SkyPatchMatrix": {
    "type": "object",
    "description": "GET /v1/skypatches with start: a sky matrix (docs/building-energy.md \"Sky matrices\"), one sky vector (as SkyPatches) per step from start to end, the matrix a daylight-coefficient calculation multiplies by its coefficients. matrix: one row per patch in Radiance's order (patch 0 the ground), one value per step (a number for luminance, an array for rgb and spectral). Night steps (sun zenith >= 90 degrees) are columns of zeros with night true. With sun=separate the matrix holds the sky alone and each step's sun is in times[].sun_source.",
    "required": ["model", "model_version", "quality", "served_quality", "quality_setting", "quality_error", "lat", "lon", "altitude_m", "start", "step", "step_s", "steps", "tz", "scheme", "mf", "patch_count", "sun_handling", "output", "unit", "ground_reflectance", "integrated_range_nm", "patches", "times", "matrix", "unanswered_steps"],
    "additionalProperties": false,
    "properties": {
      "model": {"type": "string"},
      "model_version": {"type": "string"},
      "quality": {"type": "string", "enum": ["draft", "standard", "reference"]},
      "served_quality": {"type": "string", "enum": ["draft", "standard", "reference"]},
      "quality_setting": {"type": "object", "additionalProperties": {"type": "number"}},
      "quality_error": {"type": "object", "allOf": [{"$ref": "#/components/schemas/QualityError"}], "nullable": true},
      "quality_overridden": {"type": "array", "items": {"type": "string"}},
      "fit": {"$ref": "#/components/schemas/AppliedFit"},
      "scheme": {"type": "string", "enum": ["tregenza", "reinhart"]},
      "mf": {"type": "integer", "minimum": 1, "maximum": 6},
      "patch_count": {"type": "integer"},
      "sun_handling": {"type": "string", "enum": ["separate", "patch"]},
      "output": {"type": "string", "enum": ["spectral", "rgb", "luminance"]},
      "unit": {"type": "string"},
      "ground_reflectance": {"type": "number"},
      "integrated_range_nm": {"type": "array", "minItems": 2, "maxItems": 2, "items": {"type": "number"}},
      "wavelengths_nm": {"type": "array", "items": {"type": "number"}, "description": "output=spectral."},
      "gamut_clipped_values": {"type": "integer", "description": "output=rgb: values with a negative component clipped to 0."},
      "gamut_mapping": {"type": "string"},
      "patches": {"type": "array", "items": {"type": "object", "required": ["patch", "altitude_deg", "azimuth_deg", "solid_angle_sr"], "additionalProperties": false, "properties": {"patch": {"type": "integer"}, "altitude_deg": {"type": "number"}, "azimuth_deg": {"type": "number"}, "solid_angle_sr": {"type": "number"}}}},
      "times": {"type": "array", "description": "One per step (column).", "items": {"type": "object", "required": ["time_utc", "night", "answered", "sun_zenith_deg", "sun_azimuth_deg", "sun_patch", "sun_source"], "additionalProperties": false, "properties": {
        "time_utc": {"type": "string"},
        "time_local": {"type": "string", "description": "With tz."},
        "night": {"type": "boolean"},
        "answered": {"type": "boolean", "description": "false: the model could not answer this step (its column is zeros; counted in unanswered_steps)."},
        "sun_zenith_deg": {"type": "number"},
        "sun_azimuth_deg": {"type": "number"},
        "sun_patch": {"type": "integer", "minimum": 0, "description": "The patch holding the sun's centre; 0 at night."},
        "sun_source": {"type": "object", "nullable": true, "description": "sun=separate with the sun up: its direction (Radiance's frame: x East, y North, z up), the solid angle of its disk and its radiance in the output.", "required": ["direction", "solid_angle_sr", "value"], "additionalProperties": false, "properties": {"direction": {"type": "array", "minItems": 3, "maxItems": 3, "items": {"type": "number"}}, "solid_angle_sr": {"type": "number"}, "value": {"oneOf": [{"type": "number"}, {"type": "array", "items": {"type": "number"}}]}}}
      }}},
      "matrix": {"type": "array", "description": "One row per patch, one value per step.", "items": {"type": "array", "items": {"oneOf": [{"type": "number", "minimum": 0}, {"type": "array", "items": {"type": "number", "minimum": 0}}]}}},
      "unanswered_steps": {"type": "integer", "minimum": 0}
    }
  },
  "SkyPatchesAnswer": {
    "description": "GET /v1/skypatches: one sky vector, or with start a sky matrix.",
    "oneOf": [{"$ref": "#/components/schemas/SkyPatches"}, {"$ref": "#/components/schemas/SkyPatchMatrix"}]
  },
  "SkyPatchMatrixText": {
    "type": "string",
    "description": "format=radiance with start: Radiance's matrix format as gendaymtx writes it (#?RADIANCE, NROWS=patches, NCOLS=steps, NCOMP=components, FORMAT=ascii, a blank line, then each patch's values step by step, components separated by tabs), for dctimestep and rmtxop."
  },
  "RgbSample": {
    "type": "object",
    "required": ["view_zenith_deg", "view_azimuth_deg", "rgb", "gamut_clipped", "luminance_cd_m2"],
    "additionalProperties": false,
    "properties": {
      "view_zenith_deg": {"type": "number"},
      "view_azimuth_deg": {"type": "number"},
      "rgb": {"type": "array", "minItems": 3, "maxItems": 3, "items": {"type": "number", "minimum": 0}, "description": "Linear sRGB (D65), radiometric: XYZ with Y in W/(m2.sr). Never negative: a colour outside the sRGB gamut has its negative components clipped to 0 (gamut_clipped)."},
      "gamut_clipped": {"type": "boolean", "description": "true when the colour was outside the sRGB gamut and a negative component of rgb was clipped to 0 (the other components and the luminance are the colour's own)."},
      "luminance_cd_m2": {"type": "number", "minimum": 0, "description": "683 Y of the colour before any clipping."}
    }
  },
  "Rgb": {
    "type": "object",
    "required": ["model", "model_version", "quality", "served_quality", "quality_setting", "quality_error", "method", "sun", "altitude_m", "colour_space", "gamut_mapping", "gamut_clipped_samples", "samples"],
    "additionalProperties": false,
    "properties": {
      "model": {"type": "string"},
      "model_version": {"type": "string"},
      "quality": {"type": "string", "enum": ["draft", "standard", "reference"], "description": "The quality level asked (quality=, else the server's --quality; docs/quality-levels.md)."},
      "served_quality": {"type": "string", "enum": ["draft", "standard", "reference"], "description": "The level whose tables answered: quality, or draft while the standard tables are being built (then Cache-Control: no-store)."},
      "quality_setting": {"type": "object", "additionalProperties": {"type": "number"}, "description": "Every option of the served level, with the value used (a request's explicit option included)."},
      "quality_error": {"type": "object", "allOf": [{"$ref": "#/components/schemas/QualityError"}], "nullable": true, "description": "The served level's measured error against the reference level; null when the request overrode one of the level's options."},
      "quality_overridden": {"type": "array", "items": {"type": "string"}, "description": "The level's options the request gave itself (present only then)."},
      "fit": {"$ref": "#/components/schemas/AppliedFit"},
      "method": {"type": "string", "enum": ["spectral", "three"]},
      "sun": {"$ref": "#/components/schemas/SunUsed"},
      "altitude_m": {"type": "number"},
      "colour_space": {"type": "string"},
      "gamut_mapping": {"type": "string", "enum": ["negative components clipped to 0"], "description": "How colours outside the sRGB gamut are sent: each negative linear component is set to 0, the others are kept."},
      "gamut_clipped_samples": {"type": "integer", "minimum": 0, "description": "How many samples have gamut_clipped true."},
      "integrated_range_nm": {"type": "array", "minItems": 2, "maxItems": 2, "items": {"type": "number"}, "description": "method=spectral: the wavelengths the CIE integral covers."},
      "warning": {"type": "string", "description": "When the model answers only part of the grid (e.g. Hosek up to 720 nm): the missing light counts as zero."},
      "colour_wavelengths_nm": {"type": "array", "items": {"type": "number"}, "description": "quality=draft, method=spectral only: the wavelengths the colour was computed on (docs/quality-levels.md \"Colour wavelengths\")."},
      "colour_error": {"type": "object", "nullable": true, "properties": {"against": {"type": "string"}, "measure": {"type": "string"}, "median": {"type": "number"}, "p95": {"type": "number"}, "max": {"type": "number"}}, "description": "quality=draft, method=spectral only: the draft colour's measured CIE Delta E 2000 against 40 wavelengths over the skydome; null when the request overrode one of the level's options."},
      "samples": {"type": "array", "items": {"$ref": "#/components/schemas/RgbSample"}}
    }
  },
  "IrradianceComponent": {
    "type": "object",
    "required": ["model_range_irradiance_w_m2", "irradiance_w_m2", "broadband_irradiance_w_m2", "illuminance_lx"],
    "additionalProperties": false,
    "properties": {
      "model_range_irradiance_w_m2": {"type": "number", "minimum": 0, "description": "Sum over the answered grid (integrated_range_nm), at 1 au, without molecular absorption: the model's own figure, not the solar irradiance a pyranometer measures."},
      "irradiance_w_m2": {"type": "number", "minimum": 0, "deprecated": true, "description": "Deprecated alias of model_range_irradiance_w_m2 (the same number); use model_range_irradiance_w_m2, or broadband_irradiance_w_m2 for the whole solar spectrum."},
      "broadband_irradiance_w_m2": {"type": "number", "nullable": true, "minimum": 0, "description": "300..4000 nm, absorbed by water vapour, ozone and mixed gases (Bird and Riordan 1986) and at the date's Earth-Sun distance when time is given (docs/http-api.md \"Broadband irradiance\"); null when the model cannot go broadband (broadband_unavailable says why). On a horizontal plane: DNI (direct_normal), DHI (diffuse), GHI (global)."},
      "illuminance_lx": {"type": "number", "minimum": 0},
      "spectral_w_m2_nm": {"type": "array", "items": {"type": "number", "minimum": 0}, "description": "With spectral=true, one per wavelengths_nm."}
    }
  },
  "Irradiance": {
    "type": "object",
    "description": "direct = direct normal x max(0, cos incidence), 0 with the sun below the horizon; diffuse = the model's sky irradiance on the plane; ground_diffuse = albedo x global horizontal x (1 - cos tilt) / 2 (an isotropic Lambertian ground; the albedo is ground_albedo, otherwise the model's ground albedo spectrum); global = direct + diffuse + ground_diffuse. The components present follow component= and ground_reflection=.",
    "required": ["model", "model_version", "quality", "served_quality", "quality_setting", "quality_error", "sun", "altitude_m", "plane", "integrated_range_nm", "ground_reflection"],
    "additionalProperties": false,
    "properties": {
      "model": {"type": "string"},
      "model_version": {"type": "string"},
      "quality": {"type": "string", "enum": ["draft", "standard", "reference"], "description": "The quality level asked (quality=, else the server's --quality; docs/quality-levels.md)."},
      "served_quality": {"type": "string", "enum": ["draft", "standard", "reference"], "description": "The level whose tables answered: quality, or draft while the standard tables are being built (then Cache-Control: no-store)."},
      "quality_setting": {"type": "object", "additionalProperties": {"type": "number"}, "description": "Every option of the served level, with the value used (a request's explicit option included)."},
      "quality_error": {"type": "object", "allOf": [{"$ref": "#/components/schemas/QualityError"}], "nullable": true, "description": "The served level's measured error against the reference level; null when the request overrode one of the level's options."},
      "quality_overridden": {"type": "array", "items": {"type": "string"}, "description": "The level's options the request gave itself (present only then)."},
      "fit": {"$ref": "#/components/schemas/AppliedFit"},
      "sun": {"$ref": "#/components/schemas/SunUsed"},
      "altitude_m": {"type": "number"},
      "plane": {
        "type": "object",
        "required": ["tilt_deg", "surface_azimuth_deg"],
        "additionalProperties": false,
        "properties": {"tilt_deg": {"type": "number"}, "surface_azimuth_deg": {"type": "number"}}
      },
      "integrated_range_nm": {"type": "array", "minItems": 2, "maxItems": 2, "items": {"type": "number"}},
      "ground_reflection": {"$ref": "#/components/schemas/GroundReflection"},
      "broadband": {
        "type": "object",
        "nullable": true,
        "description": "How the broadband figures were computed; null when the model cannot go broadband.",
        "required": ["range_nm", "precipitable_water_cm", "ozone_atm_cm", "earth_sun_distance_factor", "method"],
        "additionalProperties": false,
        "properties": {
          "range_nm": {"type": "array", "minItems": 2, "maxItems": 2, "items": {"type": "number"}},
          "precipitable_water_cm": {"type": "number"},
          "ozone_atm_cm": {"type": "number"},
          "earth_sun_distance_factor": {"type": "number", "description": "(1 au / r)^2 of the date (Spencer 1971); 1 for a sun given by its angles."},
          "method": {"type": "string"}
        }
      },
      "broadband_unavailable": {"type": "string", "description": "Why the model's answer cannot be extended to 300..4000 nm (broadband is null)."},
      "wavelengths_nm": {"type": "array", "items": {"type": "number"}, "description": "With spectral=true."},
      "direct_normal": {"$ref": "#/components/schemas/IrradianceComponent"},
      "direct": {"$ref": "#/components/schemas/IrradianceComponent"},
      "diffuse": {"$ref": "#/components/schemas/IrradianceComponent"},
      "ground_diffuse": {"$ref": "#/components/schemas/IrradianceComponent"},
      "global": {"$ref": "#/components/schemas/IrradianceComponent"}
    }
  },
  "GroundReflection": {
    "type": "object",
    "description": "How the ground's reflection enters tilted planes: model isotropic (albedo x global horizontal x (1 - cos tilt) / 2) with the albedo of ground_albedo (albedo_source ground_albedo) or the model's own ground albedo spectrum, the one its lit ground uses (albedo_source model: the atmosphere parameter albedo, grass by default); or excluded (ground_reflection=exclude).",
    "required": ["model"],
    "additionalProperties": false,
    "properties": {
      "model": {"type": "string", "enum": ["isotropic", "excluded"]},
      "albedo": {"type": "number", "minimum": 0, "maximum": 1},
      "albedo_source": {"type": "string", "enum": ["ground_albedo", "model"]}
    }
  },
  "IrradianceSeries": {
    "type": "object",
    "description": "One row per step from start to end (both included), the values in the order of columns: time_utc, time_local (with tz), night, solar_zenith and solar_azimuth (apparent, degrees), ghi, dni, dhi (broadband, 300..4000 nm, W/m2: the figures of GET /v1/irradiance's broadband_irradiance_w_m2), illuminance (global horizontal, lx), model_range_ghi, model_range_dni, model_range_dhi (W/m2 over integrated_range_nm), then per plane poa_global, poa_direct, poa_diffuse (sky + ground, as pvlib), poa_sky_diffuse, poa_ground_diffuse (broadband, W/m2), poa_illuminance (lx) and model_range_poa_global, model_range_poa_direct, model_range_poa_diffuse, model_range_poa_sky_diffuse, model_range_poa_ground_diffuse (W/m2 over integrated_range_nm), each suffixed _<tilt>_<azimuth> as the plane was written. For a model that cannot go broadband (broadband null) the broadband columns are null in every row and broadband_unavailable says why. Night rows (sun zenith >= 90 degrees) hold zeros; a step the model could not answer holds nulls and is counted in unanswered_steps.",
    "required": ["model", "model_version", "quality", "served_quality", "quality_setting", "quality_error", "lat", "lon", "altitude_m", "start", "step", "step_s", "steps", "tz", "planes", "integrated_range_nm", "ground_reflection", "broadband", "broadband_integration", "sky_diffuse_on_planes", "columns", "rows", "unanswered_steps"],
    "additionalProperties": false,
    "properties": {
      "model": {"type": "string"},
      "model_version": {"type": "string"},
      "quality": {"type": "string", "enum": ["draft", "standard", "reference"], "description": "As Irradiance."},
      "served_quality": {"type": "string", "enum": ["draft", "standard", "reference"], "description": "As Irradiance."},
      "quality_setting": {"type": "object", "additionalProperties": {"type": "number"}},
      "quality_error": {"type": "object", "allOf": [{"$ref": "#/components/schemas/QualityError"}], "nullable": true},
      "quality_overridden": {"type": "array", "items": {"type": "string"}},
      "fit": {"$ref": "#/components/schemas/AppliedFit"},
      "planes": {"type": "array", "items": {"type": "object", "required": ["tilt_deg", "surface_azimuth_deg", "suffix"], "additionalProperties": false, "properties": {"tilt_deg": {"type": "number"}, "surface_azimuth_deg": {"type": "number"}, "suffix": {"type": "string"}}}},
      "integrated_range_nm": {"type": "array", "minItems": 2, "maxItems": 2, "items": {"type": "number"}},
      "ground_reflection": {"$ref": "#/components/schemas/GroundReflection"},
      "broadband": {
        "type": "object",
        "nullable": true,
        "description": "How the broadband columns were computed (as GET /v1/irradiance, at each step's sun and date: the Earth-Sun distance of Spencer 1971); null when the model cannot go broadband.",
        "required": ["range_nm", "precipitable_water_cm", "ozone_atm_cm", "method"],
        "additionalProperties": false,
        "properties": {
          "range_nm": {"type": "array", "minItems": 2, "maxItems": 2, "items": {"type": "number"}},
          "precipitable_water_cm": {"type": "number"},
          "ozone_atm_cm": {"type": "number"},
          "method": {"type": "string"}
        }
      },
      "broadband_unavailable": {"type": "string", "description": "Why the model's answer cannot be extended to 300..4000 nm: ghi, dni, dhi and the poa_* columns are then null in every row."},
      "broadband_integration": {"type": "string", "nullable": true, "enum": ["per_step", "table"], "description": "per_step: the broadband integrals of SPCTRAL2 computed at each step's sun, as GET /v1/irradiance; table: interpolated (linearly) in a table over the sun zenith every 0.5 degrees built for the request when it has more daytime steps than the table has nodes (181). null when the model cannot go broadband."},
      "sky_diffuse_on_planes": {"type": "string", "enum": ["per_step", "table"], "description": "per_step: the model's sky irradiance on each tilted plane at each step; table: interpolated (bilinear) in a table of the model's own values over the sun zenith (every 2 degrees) and its azimuth relative to the plane (every 10 degrees), built for the request when it has more daytime steps than the table has nodes (874)."},
      "columns": {"type": "array", "items": {"type": "string"}},
      "rows": {"type": "array", "items": {"type": "array", "items": {"description": "A cell: a time (text), night (boolean), a number, or null for a value the model could not answer."}}},
      "unanswered_steps": {"type": "integer", "minimum": 0}
    }
  },
  "IrradianceSeriesCsv": {
    "type": "string",
    "description": "A header line with the columns of IrradianceSeries, then one line per step; null values are empty (the broadband columns of a model that cannot go broadband: the header Clearsky-Broadband-Unavailable says why)."
  },
  "SkyPatches": {
    "type": "object",
    "description": "A sky vector in Radiance's patch order (docs/building-energy.md): patch 0 the ground (rho x global horizontal / pi), then the Tregenza or Reinhart patches from the horizon band up, each band from North (azimuth 0) clockwise, the zenith cap last. value: the radiance averaged over the patch's solid angle (a Gauss-Legendre quadrature over the patch): W/(m2.sr.nm) per wavelength (spectral), Radiance RGB in W/(m2.sr) (rgb), or cd/m2 (luminance).",
    "required": ["model", "model_version", "quality", "served_quality", "quality_setting", "quality_error", "sun", "altitude_m", "scheme", "mf", "patch_count", "sun_handling", "sun_patch", "output", "unit", "ground_reflectance", "integrated_range_nm", "diffuse_horizontal_w_m2", "quadrature", "patches", "sun_source"],
    "additionalProperties": false,
    "properties": {
      "model": {"type": "string"},
      "model_version": {"type": "string"},
      "quality": {"type": "string", "enum": ["draft", "standard", "reference"], "description": "The quality level asked (quality=, else the server's --quality; docs/quality-levels.md)."},
      "served_quality": {"type": "string", "enum": ["draft", "standard", "reference"], "description": "The level whose tables answered: quality, or draft while the standard tables are being built (then Cache-Control: no-store)."},
      "quality_setting": {"type": "object", "additionalProperties": {"type": "number"}, "description": "Every option of the served level, with the value used (a request's explicit option included)."},
      "quality_error": {"type": "object", "allOf": [{"$ref": "#/components/schemas/QualityError"}], "nullable": true, "description": "The served level's measured error against the reference level; null when the request overrode one of the level's options."},
      "quality_overridden": {"type": "array", "items": {"type": "string"}, "description": "The level's options the request gave itself (present only then)."},
      "fit": {"$ref": "#/components/schemas/AppliedFit"},
      "sun": {"$ref": "#/components/schemas/SunUsed"},
      "altitude_m": {"type": "number"},
      "scheme": {"type": "string", "enum": ["tregenza", "reinhart"]},
      "mf": {"type": "integer", "minimum": 1, "maximum": 6},
      "patch_count": {"type": "integer", "description": "Patches with the ground: 146 (Tregenza, MF 1), 578, 1298, 2306, 3602, 5186."},
      "sun_handling": {"type": "string", "enum": ["separate", "patch"]},
      "sun_patch": {"type": "integer", "minimum": 0, "description": "The patch holding the sun's centre; 0 with the sun below the horizon."},
      "output": {"type": "string", "enum": ["spectral", "rgb", "luminance"]},
      "unit": {"type": "string"},
      "ground_reflectance": {"type": "number"},
      "integrated_range_nm": {"type": "array", "minItems": 2, "maxItems": 2, "items": {"type": "number"}},
      "diffuse_horizontal_w_m2": {"type": "number", "description": "The horizontal irradiance of the vector's sky, each patch uniform at its value: value x projected solid angle summed over the sky patches, integrated over integrated_range_nm; the sun excluded."},
      "quadrature": {
        "type": "object",
        "required": ["nodes_per_side", "near_sun_nodes_per_side", "near_sun_deg", "directions"],
        "additionalProperties": false,
        "properties": {"nodes_per_side": {"type": "integer"}, "near_sun_nodes_per_side": {"type": "integer"}, "near_sun_deg": {"type": "number"}, "directions": {"type": "integer"}}
      },
      "wavelengths_nm": {"type": "array", "items": {"type": "number"}, "description": "output=spectral."},
      "gamut_clipped_values": {"type": "integer", "description": "output=rgb: values with a negative component clipped to 0."},
      "gamut_mapping": {"type": "string"},
      "patches": {
        "type": "array",
        "items": {
          "type": "object",
          "required": ["patch", "altitude_deg", "azimuth_deg", "solid_angle_sr", "value"],
          "additionalProperties": false,
          "properties": {
            "patch": {"type": "integer", "minimum": 0},
            "altitude_deg": {"type": "number", "description": "Centre altitude; the ground: -90."},
            "azimuth_deg": {"type": "number", "description": "Centre azimuth, clockwise from North."},
            "solid_angle_sr": {"type": "number"},
            "value": {"oneOf": [{"type": "number"}, {"type": "array", "items": {"type": "number"}}]}
          }
        }
      },
      "sun_source": {
        "type": "object",
        "nullable": true,
        "description": "sun=separate with the sun above the horizon: the sun's disk as a source (direction in Radiance's frame: x East, y North, z up); null otherwise.",
        "required": ["altitude_deg", "azimuth_deg", "direction", "solid_angle_sr", "value"],
        "additionalProperties": false,
        "properties": {
          "altitude_deg": {"type": "number"},
          "azimuth_deg": {"type": "number"},
          "direction": {"type": "array", "minItems": 3, "maxItems": 3, "items": {"type": "number"}},
          "solid_angle_sr": {"type": "number"},
          "value": {"oneOf": [{"type": "number"}, {"type": "array", "items": {"type": "number"}}]}
        }
      }
    }
  },
  "SkydomeImage": {
    "type": "string",
    "format": "binary",
    "description": "A scan-line OpenEXR file (uncompressed, or zip or piz with a zero offset table that OpenEXR's readers rebuild), streamed (chunked) as it is computed: channels R, G, B (rgb), Y (luminance) or S0.<nm>nm (spectral, Fichet et al. 2021), and A, 1 where the image has a value (the sky, the ground of ground=albedo or model) and 0 where it has none (colour 0). Header attributes: sunDirection (OpenEXR's environment-map frame: +y up, +z North, +x West), sunAngularRadiusDeg, sunIlluminanceLx, and for rgb sunIrradianceRGB, sunRadianceRGB, sunColour, clearskyUnits and whiteLuminance. R, G and B are never negative: out of gamut colours have their negative components clipped to 0, as the header attribute clearskyGamutMapping says."
  },
  "SkydomePng": {
    "type": "string",
    "format": "binary",
    "description": "format=png: an 8-bit RGBA PNG (sRGB chunk), streamed (chunked) row by row as it is computed. R, G and B are the rgb image exposed, tone-mapped and sRGB-encoded; A is 255 where the model answered and 0 where it did not. tEXt chunks give the model, projection, sun angles, exposure and tone curve."
  }
})json");
  // The place and instants of a time series (api/request/time_steps.h), the same members in the
  // irradiance series and the sky matrix.
  const Json series_head = parse(R"json({
      "lat": {"type": "number"},
      "lon": {"type": "number"},
      "altitude_m": {"type": "number"},
      "start": {"type": "string", "description": "The first step, UTC."},
      "step": {"type": "string"},
      "step_s": {"type": "integer"},
      "steps": {"type": "integer"},
      "tz": {"type": "string", "nullable": true}
  })json");
  for (const char* name : {"IrradianceSeries", "SkyPatchMatrix"})
    s[name]["properties"].update(series_head);
  const Json sky = sky_body_properties();
  const auto batch = [&](const char* description, const Json& specific) {
    Json body = {{"type", "object"},
                 {"description", description},
                 {"required", {"model", "views"}},
                 {"additionalProperties", false},
                 {"properties", sky}};
    for (const auto& [name, schema] : specific.items()) body["properties"][name] = schema;
    body["properties"]["views"] = ref("schemas", "ViewBatch");
    return body;
  };
  s["RadianceBatchRequest"] = batch(
      "The parameters of GET /v1/radiance as members (numbers or strings; view_zenith and "
      "view_azimuth replaced by views).",
      parse(R"json({
        "wavelengths": {"type": "string", "description": "As the query parameter of GET /v1/radiance."},
        "format": {"type": "string", "enum": ["json", "csv"], "default": "json"}
      })json"));
  s["RgbBatchRequest"] = batch(
      "The parameters of GET /v1/rgb as members (numbers or strings; view_zenith and "
      "view_azimuth replaced by views).",
      parse(R"json({
        "method": {"type": "string", "enum": ["spectral", "three"], "default": "spectral"}
      })json"));
  return s;
}

Json endpoint_parameters() {
  const Limits limits;
  Json p = parse(R"json({
  "view_zenith": {
    "name": "view_zenith", "in": "query", "required": true,
    "description": "View zenith angle, degrees from the local vertical.",
    "schema": {"type": "number", "minimum": 0, "maximum": 180},
    "example": 45
  },
  "view_azimuth": {
    "name": "view_azimuth", "in": "query", "required": true,
    "description": "View azimuth, degrees clockwise from North.",
    "schema": {"type": "number", "minimum": -360, "maximum": 360},
    "example": 0
  },
  "wavelengths": {
    "name": "wavelengths", "in": "query", "required": false,
    "description": "",
    "schema": {"type": "string"},
    "example": "450,550,650"
  }
})json");
  // Appended piece by piece: GCC 12 reports a false -Warray-bounds on the one-expression
  // concatenation once this function is inlined.
  std::string description =
      "Wavelengths, nm, each in (0, 100000] and increasing: a list (450,550,650) or "
      "start:stop:step (stop included). Absent: the model's default grid (the paper's 40 bins "
      "of 11.75 nm from 360 nm, those in the model's range). Values all on that grid are read "
      "from its tables; any other list builds tables on exactly those points (503 while they "
      "are built). At most ";
  description += std::to_string(limits.max_wavelengths);
  description += " (--max-wavelengths; above: 413); outside the model's spectral range: 422.";
  p["wavelengths"]["description"] = std::move(description);
  return p;
}

// The responses every sky computation shares.
void add_sky_errors(Json& operation, bool get) {
  Json& r = operation["responses"];
  r["400"] = error_response(
      "An invalid, unknown, unused, duplicate or conflicting parameter, or a bad body (codes "
      "invalid_parameter, unknown_parameter, missing_parameter, conflicting_parameters, "
      "invalid_body); error.parameter names it.");
  r["400"]["content"]["application/json"]["example"] = parse(
      R"json({"error": {"code": "invalid_parameter", "message": "turbidity: must be in [2, 10]", "parameter": "turbidity"}})json");
  r["404"] = error_response(
      "No served model has this id (code unknown_model), or no stored fit matches fit= (code "
      "unknown_fit), or fit= on a server without a database (code no_database, parameter "
      "fit), or aerosols= of measured_aerosols names no stored inversion (code "
      "unknown_aerosols, parameter aerosols; on a query replica every id but 0).");
  r["404"]["content"]["application/json"]["example"] = parse(
      R"json({"error": {"code": "unknown_model", "message": "model: no model 'nope' (available: preetham, hosek)", "parameter": "model"}})json");
  r["409"] = error_response(
      "The fit named by fit= is not succeeded (code fit_not_succeeded: queued, running, failed "
      "or interrupted) or is a fit of another model (code fit_model_mismatch); error.parameter "
      "is fit.");
  r["409"]["content"]["application/json"]["example"] = parse(
      R"json({"error": {"code": "fit_model_mismatch", "message": "fit: fit 3 is a fit of hosek, not of preetham", "parameter": "fit"}})json");
  r["413"] = error_response(
      "Above a configured limit: views, wavelengths, image size, the request body, or tables "
      "that never fit in the server's table memory beside the tables it keeps for good "
      "(--table-memory; error.parameter table_memory) (code too_large); error.parameter names "
      "it.");
  r["413"]["content"]["application/json"]["example"] = parse(
      R"json({"error": {"code": "too_large", "message": "wavelengths: at most 2000 wavelengths", "parameter": "wavelengths"}})json");
  r["422"] = error_response(
      "The model cannot answer this request (code model_cannot_answer): the sun below the "
      "horizon for a model that needs it above, a view below the horizon, an altitude or "
      "wavelength outside the model's range, a fitted model outside its domain "
      "(outside_fit_domain; clamp_negative_fit=1 answers 0 there). The message says why; "
      "error.parameter names the parameter or the view (views[3]).");
  r["422"]["content"]["application/json"]["example"] = parse(
      R"json({"error": {"code": "model_cannot_answer", "message": "model preetham cannot answer: the model does not answer for a sun this far below the zenith (see its max_sun_zenith_deg)", "parameter": "sun_zenith"}})json");
  r["429"] = retry_later_response(
      "This client (by network address) started more table builds within the server's window "
      "than it may (--build-rate per --build-rate-window-s; code too_many_builds, parameter "
      "build_rate): nothing was built; configurations already built are still answered. "
      "Retry after Retry-After seconds.");
  r["429"]["content"]["application/json"]["example"] = parse(
      R"json({"error": {"code": "too_many_builds", "message": "build_rate: 127.0.0.1 started 30 table builds within 60 s, the most one client may; ask for a configuration already built (the defaults) or try again later", "parameter": "build_rate"}})json");
  r["503"] = retry_later_response(
      "The tables this request needs are being built (code model_not_ready), or a new "
      "configuration's tables would not fit the server's table memory (code busy, parameter "
      "table_memory): retry after Retry-After seconds.");
  r["503"]["content"]["application/json"]["example"] = parse(
      R"json({"error": {"code": "model_not_ready", "message": "model bruneton: its tables for this configuration are being built (in progress, 0% done)", "parameter": "model"}})json");
  if (get && operation["operationId"] == "getSkydome") {
    // The answer memory budget (api/http/answer_memory_budget.h, server/README.md).
    r["503"]["description"] =
        "The tables this request needs are being built (code model_not_ready), or the image's "
        "band of rows does not fit in the answer memory budget that images being sent hold "
        "(--answer-memory; code busy, error.parameter answer_memory): retry after Retry-After "
        "seconds.";
    r["413"]["description"] =
        "Above a configured limit: wavelengths, image size, or an image whose band of rows alone "
        "is above the answer memory budget (--answer-memory; error.parameter answer_memory) "
        "(code too_large); error.parameter names it; also tables that "
        "never fit in the table memory (--table-memory; error.parameter table_memory).";
    // Streamed: no tag, since the body is not known before it is sent.
    r["200"]["headers"]["Cache-Control"] = ref("headers", "Cache-Control");
  } else {
    const std::string id = operation["operationId"].get<std::string>();
    if (id == "getRadiance" || id == "postRadiance" || id == "getRgb" || id == "postRgb") {
      // Batch answers in the answer memory budget (api/http/batch_answer_bytes.h).
      r["503"]["description"] =
          "The tables this request needs are being built (code model_not_ready), or the "
          "answer's estimated memory (from its views and wavelengths; answers below 64 KiB are "
          "not counted) does not fit in the answer memory budget that answers being sent hold "
          "(--answer-memory; code busy, error.parameter answer_memory): retry after "
          "Retry-After seconds.";
      r["413"]["description"] =
          "Above a configured limit: views, wavelengths, the request body, or an answer whose "
          "estimated memory alone is above the answer memory budget (--answer-memory; "
          "error.parameter answer_memory) (code too_large); error.parameter names it; also tables "
          "that "
          "never fit in the table memory (--table-memory; error.parameter table_memory).";
    }
    if (get) add_revalidation(operation);
  }
  add_common_errors(operation, !get);
}

Json operations() {
  Json ops = parse(R"json({
  "getSun": {
    "operationId": "getSun",
    "tags": ["sun"],
    "summary": "Sun position, sunrise, transit and sunset",
    "description": "The sun's topocentric zenith and azimuth at a place and time (NREL SPA) and the local day's sunrise, transit and sunset (the same query as `clearsky sun`).",
    "parameters": [
      {"name": "lat", "in": "query", "required": true, "description": "Latitude, degrees North in [-90, 90]: decimal or DMS (42d26'36\"N).", "schema": {"type": "string"}, "example": "42.444"},
      {"name": "lon", "in": "query", "required": true, "description": "Longitude, degrees East in [-180, 180]: decimal or DMS.", "schema": {"type": "string"}, "example": "-76.5"},
      {"name": "time", "in": "query", "required": false, "description": "ISO 8601 with a UTC offset or Z (years 0000 to 6000); absent: now. The answer's times are in this offset.", "schema": {"type": "string", "format": "date-time"}, "example": "2013-05-27T11:45:00-04:00"},
      {"name": "altitude", "in": "query", "required": false, "description": "Observer elevation above sea level, m.", "schema": {"type": "number", "minimum": -6500000, "default": 0}},
      {"name": "pressure", "in": "query", "required": false, "description": "Annual mean pressure for refraction, mbar.", "schema": {"type": "number", "minimum": 0, "maximum": 5000, "default": 1013.25}},
      {"name": "temperature", "in": "query", "required": false, "description": "Annual mean temperature for refraction, degrees Celsius, above -273.", "schema": {"type": "number", "minimum": -273, "exclusiveMinimum": true, "maximum": 6000, "default": 15}},
      {"name": "delta_t", "in": "query", "required": false, "description": "TT - UT1, seconds; absent: Delta T of the year and month of time by the Espenak-Meeus expressions (years -1999 to 3000; later years need delta_t).", "schema": {"type": "number", "minimum": -8000, "maximum": 8000}},
      {"name": "delta_ut1", "in": "query", "required": false, "description": "UT1 - UTC, seconds.", "schema": {"type": "number", "minimum": -1, "exclusiveMinimum": true, "maximum": 1, "exclusiveMaximum": true, "default": 0}},
      {"name": "refraction", "in": "query", "required": false, "description": "Apply atmospheric refraction (true/false or 1/0).", "schema": {"type": "boolean", "default": true}}
    ],
    "responses": {
      "200": {
        "description": "The sun.",
        "content": {"application/json": {
          "schema": {"$ref": "#/components/schemas/Sun"},
          "example": {"zenith": 26.652537342158503, "azimuth": 136.04644213319017, "sunrise": "2013-05-27T05:34:08-04:00", "transit": "2013-05-27T13:03:10-04:00", "sunset": "2013-05-27T20:32:40-04:00", "day": "normal", "delta_t_s": 68.228843453125, "delta_t_source": "espenak_meeus"}
        }}
      },
      "400": {
        "description": "A missing, invalid or unknown parameter (code invalid_parameter); error.parameter names it.",
        "content": {"application/json": {
          "schema": {"$ref": "#/components/schemas/Error"},
          "example": {"error": {"code": "invalid_parameter", "message": "lon: is required", "parameter": "lon"}}
        }}
      }
    }
  },
  "getRadiance": {
    "operationId": "getRadiance",
    "tags": ["sky"],
    "summary": "Spectral sky radiance for one view",
    "description": "The model's spectral radiance, W/(m2.sr.nm), seen in one direction, at the model's default wavelengths or those asked for.",
    "parameters": [],
    "responses": {
      "200": {
        "description": "Spectral radiance.",
        "content": {
          "application/json": {
            "schema": {"$ref": "#/components/schemas/Radiance"},
            "example": {"altitude_m": 0.0, "grid": "points", "model": "preetham", "model_version": "2", "quality": "standard", "quality_error": {"against": "reference", "max_relative": 0.0, "p95_relative": 0.0}, "quality_setting": {}, "served_quality": "standard", "samples": [{"radiance": [0.16657478187859961, 0.07732172727214033, 0.03455196147970835], "view_azimuth_deg": 0.0, "view_zenith_deg": 45.0}], "sun": {"azimuth_deg": 135.0, "source": "given", "zenith_deg": 30.0}, "unit": "W/(m2.sr.nm)", "wavelengths_nm": [450.0, 550.0, 650.0]}
          },
          "text/csv": {
            "schema": {"$ref": "#/components/schemas/RadianceCsv"},
            "example": "view_zenith_deg,view_azimuth_deg,wavelength_nm,radiance_w_m2_sr_nm\n45,0,450,0.166574782\n45,0,550,0.0773217273\n45,0,650,0.0345519615\n"
          }
        }
      }
    }
  },
  "postRadiance": {
    "operationId": "postRadiance",
    "tags": ["sky"],
    "summary": "Spectral sky radiance for a batch of views",
    "description": "As GET /v1/radiance for many views at once: the parameters and the views in a JSON body (at most --payload-max-bytes, default 8 MiB).",
    "requestBody": {
      "required": true,
      "content": {"application/json": {
        "schema": {"$ref": "#/components/schemas/RadianceBatchRequest"},
        "example": {"model": "preetham", "sun_zenith": 30, "sun_azimuth": 135, "wavelengths": "450,550,650", "views": [[45, 0], {"view_zenith": 60, "view_azimuth": 90}]}
      }}
    },
    "responses": {
      "200": {
        "description": "Spectral radiance, one sample per view, in the order given.",
        "content": {
          "application/json": {
            "schema": {"$ref": "#/components/schemas/Radiance"},
            "example": {"altitude_m": 0.0, "grid": "points", "model": "preetham", "model_version": "2", "quality": "standard", "quality_error": {"against": "reference", "max_relative": 0.0, "p95_relative": 0.0}, "quality_setting": {}, "served_quality": "standard", "samples": [{"radiance": [0.16657478187859961, 0.07732172727214033, 0.03455196147970835], "view_azimuth_deg": 0.0, "view_zenith_deg": 45.0}, {"radiance": [0.27521367017693504, 0.14807347448705338, 0.08606376978831415], "view_azimuth_deg": 90.0, "view_zenith_deg": 60.0}], "sun": {"azimuth_deg": 135.0, "source": "given", "zenith_deg": 30.0}, "unit": "W/(m2.sr.nm)", "wavelengths_nm": [450.0, 550.0, 650.0]}
          },
          "text/csv": {"schema": {"$ref": "#/components/schemas/RadianceCsv"}}
        }
      }
    }
  },
  "getIrradiance": {
    "operationId": "getIrradiance",
    "tags": ["sky"],
    "summary": "Irradiance on a plane",
    "description": "Direct sun, diffuse sky, ground-reflected (isotropic ground) and global irradiance on a horizontal or tilted plane: W/m2 over the model's answered grid, illuminance in lx, and spectra in W/(m2.nm) with spectral=true.",
    "parameters": [
      {"name": "tilt", "in": "query", "required": false, "description": "Plane tilt from horizontal, degrees.", "schema": {"type": "number", "minimum": 0, "maximum": 180, "default": 0}},
      {"name": "surface_azimuth", "in": "query", "required": false, "description": "Azimuth of the plane's normal, degrees clockwise from North.", "schema": {"type": "number", "minimum": -360, "maximum": 360, "default": 180}},
      {"name": "component", "in": "query", "required": false, "description": "Which components to answer (a model without sun or sky irradiance answers 422 for the components it lacks; ground_diffuse needs both, the ground being lit by the global horizontal).", "schema": {"type": "string", "enum": ["all", "direct", "diffuse", "ground_diffuse", "global"], "default": "all"}},
      {"name": "ground_reflection", "in": "query", "required": false, "description": "include: add the isotropic ground's reflection (ground_diffuse) to global; exclude: leave it out.", "schema": {"type": "string", "enum": ["include", "exclude"], "default": "include"}},
      {"name": "ground_albedo", "in": "query", "required": false, "description": "The ground's albedo for ground_diffuse; absent: the model's ground albedo spectrum (the atmosphere parameter albedo, grass by default). Not with ground_reflection=exclude.", "schema": {"type": "number", "minimum": 0, "maximum": 1}},
      {"name": "spectral", "in": "query", "required": false, "description": "Add each component's spectrum and the wavelengths.", "schema": {"type": "boolean", "default": false}},
      {"name": "precipitable_water_cm", "in": "query", "required": false, "description": "Precipitable water of the vertical column, cm: the water vapour absorption of the broadband figures (default: ASTM G-173's reference atmosphere).", "schema": {"type": "number", "minimum": 0, "maximum": 10, "default": 1.42}},
      {"name": "ozone_atm_cm", "in": "query", "required": false, "description": "Ozone column, atm-cm (1 atm-cm = 1000 DU): the ozone absorption of the broadband figures (default: ASTM G-173's reference atmosphere).", "schema": {"type": "number", "minimum": 0, "maximum": 1, "default": 0.34}}
    ],
    "responses": {
      "200": {
        "description": "Irradiance.",
        "content": {"application/json": {
          "schema": {"$ref": "#/components/schemas/Irradiance"},
          "example": {"altitude_m": 0.0, "diffuse": {"model_range_irradiance_w_m2": 180.52086377322016, "irradiance_w_m2": 180.52086377322016, "broadband_irradiance_w_m2": null, "illuminance_lx": 28493.223923522513}, "direct": {"model_range_irradiance_w_m2": 479.46653007527397, "irradiance_w_m2": 479.46653007527397, "broadband_irradiance_w_m2": null, "illuminance_lx": 88658.85993633908}, "direct_normal": {"model_range_irradiance_w_m2": 517.348496685935, "irradiance_w_m2": 517.348496685935, "broadband_irradiance_w_m2": null, "illuminance_lx": 95663.66999330047}, "global": {"model_range_irradiance_w_m2": 659.987393848494, "irradiance_w_m2": 659.987393848494, "broadband_irradiance_w_m2": null, "illuminance_lx": 117152.08385986158}, "ground_diffuse": {"model_range_irradiance_w_m2": 0.0, "irradiance_w_m2": 0.0, "broadband_irradiance_w_m2": null, "illuminance_lx": 0.0}, "ground_reflection": {"albedo_source": "model", "model": "isotropic"}, "integrated_range_nm": [360.0, 830.0], "model": "preetham", "model_version": "1", "quality": "standard", "quality_error": {"against": "reference", "max_relative": 0.0, "p95_relative": 0.0}, "quality_setting": {}, "served_quality": "standard", "plane": {"surface_azimuth_deg": 180.0, "tilt_deg": 30.0}, "sun": {"azimuth_deg": 135.0, "source": "given", "zenith_deg": 30.0}, "broadband": null, "broadband_unavailable": "preetham is a fit over the visible range whose atmosphere is a turbidity, not an extinction the 300..4000 nm extension can continue (docs/http-api.md \"Broadband irradiance\")"}
        }}
      }
    }
  },
  "getIrradianceSeries": {
    "operationId": "getIrradianceSeries",
    "tags": ["sky"],
    "summary": "Irradiance time series on several planes",
    "description": "The irradiance of one place from start to end every step (docs/building-energy.md): the sun of each step by NREL SPA, the horizontal ghi, dni, dhi and illuminance and, per plane, pvlib's poa_global, poa_direct, poa_diffuse (sky + ground), poa_sky_diffuse (the model's own anisotropic sky), poa_ground_diffuse (isotropic ground) and poa_illuminance. Night steps are rows of zeros with night true. Checked completely before the first byte, then streamed (chunked) as computed. At most 52704 steps (a leap year every 10 minutes; above: 413 naming step); models that prepare each sun (Haber, Nishita96) at most 96 daytime steps (413 naming end).",
    "parameters": [
      {"name": "start", "in": "query", "required": true, "description": "First instant, ISO 8601 with an offset or Z, or a local time in tz.", "schema": {"type": "string"}, "example": "2024-01-01T00:00:00"},
      {"name": "end", "in": "query", "required": true, "description": "Last instant (included when a whole number of steps from start), as start.", "schema": {"type": "string"}, "example": "2024-12-31T23:00:00"},
      {"name": "tz", "in": "query", "required": false, "description": "IANA time zone of start and end without offset (daylight saving time included) and of the time_local column.", "schema": {"type": "string"}, "example": "Europe/Paris"},
      {"name": "step", "in": "query", "required": false, "description": "ISO 8601 duration between steps: days, hours, minutes, seconds (PT10M, PT1H, P1D).", "schema": {"type": "string", "default": "PT1H"}},
      {"name": "planes", "in": "query", "required": false, "description": "Planes besides the horizontal: tilt:azimuth pairs in degrees separated by commas (tilt in [0, 180] from horizontal, azimuth of the normal clockwise from North), at most 16.", "schema": {"type": "string"}, "example": "30:180,90:180,90:90"},
      {"name": "ground_reflection", "in": "query", "required": false, "description": "include: the isotropic ground's reflection on the planes (poa_ground_diffuse); exclude: 0.", "schema": {"type": "string", "enum": ["include", "exclude"], "default": "include"}},
      {"name": "ground_albedo", "in": "query", "required": false, "description": "The ground's albedo; absent: the model's ground albedo spectrum.", "schema": {"type": "number", "minimum": 0, "maximum": 1}},
      {"name": "precipitable_water_cm", "in": "query", "required": false, "description": "Precipitable water of the vertical column, cm: the water vapour absorption of the broadband columns (default: ASTM G-173's reference atmosphere).", "schema": {"type": "number", "minimum": 0, "maximum": 10, "default": 1.42}},
      {"name": "ozone_atm_cm", "in": "query", "required": false, "description": "Ozone column, atm-cm (1 atm-cm = 1000 DU): the ozone absorption of the broadband columns (default: ASTM G-173's reference atmosphere).", "schema": {"type": "number", "minimum": 0, "maximum": 1, "default": 0.34}},
      {"name": "format", "in": "query", "required": false, "description": "json, or csv (a header line, then one line per step).", "schema": {"type": "string", "enum": ["json", "csv"], "default": "json"}}
    ],
    "responses": {
      "200": {
        "description": "The series.",
        "headers": {
          "Clearsky-Broadband-Unavailable": {"description": "format=csv with a model that cannot go broadband: why its ghi, dni, dhi and poa_* columns are empty.", "schema": {"type": "string"}}
        },
        "content": {
          "application/json": {"schema": {"$ref": "#/components/schemas/IrradianceSeries"}},
          "text/csv": {"schema": {"$ref": "#/components/schemas/IrradianceSeriesCsv"}}
        }
      }
    }
  },
  "getRgb": {
    "operationId": "getRgb",
    "tags": ["sky"],
    "summary": "Colour and luminance for one view",
    "description": "Linear sRGB (D65, radiometric: Y in W/(m2.sr)) and luminance (cd/m2): method=spectral integrates the model's 40-bin spectrum against the CIE 1931 functions; method=three is the paper's 3-wavelength method (the model built on 440, 550 and 680 nm). No component is negative: a colour outside the sRGB gamut (the saturated sky of a low sun) has its negative components clipped to 0, and its sample says so (gamut_clipped; gamut_clipped_samples counts them).",
    "parameters": [
      {"name": "method", "in": "query", "required": false, "description": "spectral (CIE 1931 over the 40 bins) or three (the paper's 3-wavelength method).", "schema": {"type": "string", "enum": ["spectral", "three"], "default": "spectral"}}
    ],
    "responses": {
      "200": {
        "description": "Colour.",
        "content": {"application/json": {
          "schema": {"$ref": "#/components/schemas/Rgb"},
          "example": {"altitude_m": 0.0, "colour_space": "linear sRGB (D65), radiometric: Y in W/(m2.sr)", "gamut_clipped_samples": 0, "gamut_mapping": "negative components clipped to 0", "integrated_range_nm": [360.0, 830.0], "method": "spectral", "model": "preetham", "model_version": "1", "quality": "standard", "quality_error": {"against": "reference", "max_relative": 0.0, "p95_relative": 0.0}, "quality_setting": {}, "served_quality": "standard", "samples": [{"gamut_clipped": false, "luminance_cd_m2": 5404.272403652347, "rgb": [4.374940149346866, 8.14954111417067, 15.988335948967407], "view_azimuth_deg": 0.0, "view_zenith_deg": 45.0}], "sun": {"azimuth_deg": 135.0, "source": "given", "zenith_deg": 30.0}}
        }}
      }
    }
  },
  "postRgb": {
    "operationId": "postRgb",
    "tags": ["sky"],
    "summary": "Colour and luminance for a batch of views",
    "description": "As GET /v1/rgb for many views at once: the parameters and the views in a JSON body (at most --payload-max-bytes, default 8 MiB).",
    "requestBody": {
      "required": true,
      "content": {"application/json": {
        "schema": {"$ref": "#/components/schemas/RgbBatchRequest"},
        "example": {"model": "hosek", "lat": 42.444, "lon": "-76.5", "time": "2013-05-27T11:45:00-04:00", "views": [[45, 0], {"view_zenith": 60, "view_azimuth": 90}]}
      }}
    },
    "responses": {
      "200": {
        "description": "Colour, one sample per view, in the order given.",
        "content": {"application/json": {
          "schema": {"$ref": "#/components/schemas/Rgb"},
          "example": {"altitude_m": 0.0, "colour_space": "linear sRGB (D65), radiometric: Y in W/(m2.sr)", "gamut_clipped_samples": 0, "gamut_mapping": "negative components clipped to 0", "integrated_range_nm": [360.0, 724.25], "method": "spectral", "model": "hosek", "model_version": "1", "quality": "standard", "quality_error": {"against": "reference", "max_relative": 0.0, "p95_relative": 0.0}, "quality_setting": {}, "served_quality": "standard", "samples": [{"gamut_clipped": false, "luminance_cd_m2": 3125.214328653716, "rgb": [2.618930817129737, 4.657793717117717, 9.528364421411645], "view_azimuth_deg": 0.0, "view_zenith_deg": 45.0}, {"gamut_clipped": false, "luminance_cd_m2": 5483.929524803734, "rgb": [5.293662459038357, 8.191446310734195, 14.481891990482866], "view_azimuth_deg": 90.0, "view_zenith_deg": 60.0}], "sun": {"azimuth_deg": 136.0464246389158, "source": "spa", "zenith_deg": 26.652540765126872}, "warning": "the model answers only part of the grid; the CIE integral covers [360.000000, 724.250000] nm (missing light counts as zero)"}
        }}
      }
    }
  },
  "getSkyPatches": {
    "operationId": "getSkyPatches",
    "tags": ["sky"],
    "summary": "A sky vector over Tregenza or Reinhart patches",
    "description": "The model's sky averaged over each patch of Radiance's Tregenza (145 + ground) or Reinhart (MF 1 to 6) subdivision, in the order of reinhart.cal and gendaymtx, for multiplication with daylight coefficients (rfluxmtx, dctimestep; docs/building-energy.md). The sun is its own source (sun=separate) or folded into the patch holding it (sun=patch). JSON, or CSV with one row per patch. With start, end and step (and lat, lon), a sky matrix: one vector per step, one column per step, night steps explicit (zeros, night true), as JSON, CSV or Radiance's matrix format.",
    "parameters": [
      {"name": "scheme", "in": "query", "required": false, "description": "tregenza (145 patches and the ground) or reinhart (with mf).", "schema": {"type": "string", "enum": ["tregenza", "reinhart"], "default": "tregenza"}},
      {"name": "mf", "in": "query", "required": false, "description": "scheme=reinhart only: Reinhart's subdivision of each Tregenza patch into mf x mf.", "schema": {"type": "integer", "minimum": 1, "maximum": 6, "default": 1}},
      {"name": "sun", "in": "query", "required": false, "description": "separate: the sun's disk as its own source (sun_source); patch: its direct normal irradiance divided by the solid angle of the patch holding it, added to that patch.", "schema": {"type": "string", "enum": ["separate", "patch"], "default": "separate"}},
      {"name": "output", "in": "query", "required": false, "description": "spectral: W/(m2.sr.nm) per wavelength; rgb: Radiance's RGB, W/(m2.sr); luminance: cd/m2.", "schema": {"type": "string", "enum": ["spectral", "rgb", "luminance"], "default": "spectral"}},
      {"name": "wavelengths", "in": "query", "required": false, "description": "output=spectral only: as GET /v1/radiance; at most 1,000,000 values per vector (patches x wavelengths; above: 413).", "schema": {"type": "string"}},
      {"name": "ground_reflectance", "in": "query", "required": false, "description": "Reflectance of the Lambertian ground of patch 0 (gendaymtx's -g).", "schema": {"type": "number", "minimum": 0, "maximum": 1, "default": 0.2}},
      {"name": "format", "in": "query", "required": false, "description": "json, or csv: patch,altitude_deg,azimuth_deg,solid_angle_sr and the values, one row per patch from 0, then a row named sun when sun=separate and the sun is up; radiance (with start only): Radiance's matrix format.", "schema": {"type": "string", "enum": ["json", "csv", "radiance"], "default": "json"}},
      {"name": "start", "in": "query", "required": false, "description": "A sky matrix instead of one vector: its first instant, ISO 8601 with an offset or Z, or a local time in tz (then lat and lon instead of time or the sun's angles, as GET /v1/irradiance/series). At most 4,000,000 values (steps x patches x components; above: 413 naming step).", "schema": {"type": "string"}, "example": "2024-01-01T00:00:00"},
      {"name": "end", "in": "query", "required": false, "description": "With start: the last instant (included when a whole number of steps from start).", "schema": {"type": "string"}},
      {"name": "step", "in": "query", "required": false, "description": "With start: ISO 8601 duration between steps (PT10M, PT1H, P1D).", "schema": {"type": "string", "default": "PT1H"}},
      {"name": "tz", "in": "query", "required": false, "description": "With start: IANA time zone of start and end without offset and of times[].time_local.", "schema": {"type": "string"}}
    ],
    "responses": {
      "200": {
        "description": "The sky vector, or with start the sky matrix.",
        "content": {
          "application/json": {"schema": {"$ref": "#/components/schemas/SkyPatchesAnswer"}},
          "text/csv": {"schema": {"$ref": "#/components/schemas/SkyPatchesCsv"}},
          "text/plain": {"schema": {"$ref": "#/components/schemas/SkyPatchMatrixText"}}
        }
      }
    }
  },
  "getSkydome": {
    "operationId": "getSkydome",
    "tags": ["sky"],
    "summary": "An OpenEXR (or tone-mapped PNG) image of the sky",
    "description": "The whole sky as an image: fisheye (size x size, equidistant, North up, East left), latlong (size x size/2) or cubemap (size x 6 size), OpenEXR envmap conventions. Everything is checked before the first byte; then the image is computed in bands of rows (16, fewer for wide images with many channels: at most about 2 MiB of samples) and streamed (chunked).",
    "parameters": [
      {"name": "projection", "in": "query", "required": false, "description": "Image projection.", "schema": {"type": "string", "enum": ["fisheye", "latlong", "cubemap"], "default": "fisheye"}},
      {"name": "size", "in": "query", "required": false, "description": "", "schema": {"type": "integer", "minimum": 8, "default": 512}},
      {"name": "channels", "in": "query", "required": false, "description": "rgb: R, G, B linear sRGB; luminance: Y in cd/m2; spectral: one channel per wavelength, W/(m2.sr.nm). Every image also has A.", "schema": {"type": "string", "enum": ["rgb", "luminance", "spectral"], "default": "rgb"}},
      {"name": "pixel_type", "in": "query", "required": false, "description": "Sample type; absent: half for rgb with sun=none and units=radiometric, float otherwise (half with sun=disc or units=photometric: 400).", "schema": {"type": "string", "enum": ["half", "float"]}},
      {"name": "method", "in": "query", "required": false, "description": "channels=rgb only: as GET /v1/rgb.", "schema": {"type": "string", "enum": ["spectral", "three"], "default": "spectral"}},
      {"name": "wavelengths", "in": "query", "required": false, "description": "channels=spectral only: as GET /v1/radiance.", "schema": {"type": "string"}},
      {"name": "format", "in": "query", "required": false, "description": "exr: the radiometric OpenEXR image; png: an 8-bit sRGB display image of the rgb channels (exposure, then tone_map, then the IEC 61966-2-1 sRGB transfer function; alpha 0 where the model did not answer). png takes channels=rgb only and no pixel_type.", "schema": {"type": "string", "enum": ["exr", "png"], "default": "exr"}},
      {"name": "exposure", "in": "query", "required": false, "description": "format=png only: the camera exposure in EV100; the luminance 1.2 x 2^exposure cd/m2 maps to 1 before the tone curve (ISO 12232 saturation-based sensitivity). 14 exposes a clear day's sky; lower it for twilight.", "schema": {"type": "number", "minimum": -10, "maximum": 24, "default": 14}},
      {"name": "tone_map", "in": "query", "required": false, "description": "format=png only: the tone curve applied to each exposed component: aces (Narkowicz 2016's fit of the ACES filmic curve) or reinhard (x / (1 + x), Reinhard et al. 2002).", "schema": {"type": "string", "enum": ["aces", "reinhard"], "default": "aces"}}
    ],
    "responses": {
      "200": {
        "description": "The image.",
        "headers": {
          "Content-Disposition": {"description": "inline; filename=\"sky.exr\" (sky.png for format=png)", "schema": {"type": "string"}}
        },
        "content": {
          "image/x-exr": {"schema": {"$ref": "#/components/schemas/SkydomeImage"}},
          "image/png": {"schema": {"$ref": "#/components/schemas/SkydomePng"}}
        }
      }
    }
  }
})json");
  const Limits limits;
  Json& size = ops["getSkydome"]["parameters"][1];
  size["schema"]["maximum"] = limits.max_skydome_size;
  size["description"] = "Image width in pixels (even for latlong); at most " +
                        std::to_string(limits.max_skydome_size) +
                        " (--max-skydome-size; above: 413).";
  const auto with_sky = [&](Json& operation, std::initializer_list<const char*> before, bool get) {
    Json parameters = sky_parameter_refs();
    for (const char* name : before) parameters.push_back(ref("parameters", name));
    const Json own = operation.value("parameters", Json::array());
    for (const auto& p : own) parameters.push_back(p);
    if (get) {
      operation["parameters"] = std::move(parameters);
    } else {
      operation.erase("parameters");
    }
    add_sky_errors(operation, get);
  };
  with_sky(ops["getRadiance"], {"view_zenith", "view_azimuth", "wavelengths"}, true);
  ops["getRadiance"]["parameters"].push_back(
      {{"name", "format"},
       {"in", "query"},
       {"required", false},
       {"description", "json, or csv (one row per view and wavelength)."},
       {"schema", {{"type", "string"}, {"enum", {"json", "csv"}}, {"default", "json"}}}});
  with_sky(ops["postRadiance"], {}, false);
  with_sky(ops["getIrradiance"], {}, true);
  {
    // The series: the model, the place (time excluded: start, end, step) and the model's
    // parameters, then its own.
    Json& series = ops["getIrradianceSeries"];
    Json parameters = Json::array();
    const Json components = sky_parameter_components();
    for (const auto& [key, parameter] : components.items()) {
      if (key != "time" && key != "sun_zenith" && key != "sun_azimuth")
        parameters.push_back(ref("parameters", key));
    }
    for (const auto& own : series["parameters"]) parameters.push_back(own);
    series["parameters"] = std::move(parameters);
    add_sky_errors(series, true);
  }
  with_sky(ops["getRgb"], {"view_zenith", "view_azimuth"}, true);
  with_sky(ops["postRgb"], {}, false);
  with_sky(ops["getSkydome"], {}, true);
  // The renderer options, from their one table (api/skydome/skydome_options.h).
  for (const SkydomeOptionSpec& option : skydome_option_table()) {
    Json values = Json::array();
    for (std::string_view v : option.values) values.push_back(std::string(v));
    Json schema = {{"type", "string"}, {"enum", std::move(values)}};
    if (option.name != "ground") schema["default"] = std::string(option.default_text);
    ops["getSkydome"]["parameters"].push_back(
        {{"name", std::string(option.name)},
         {"in", "query"},
         {"required", false},
         {"description",
          std::string(option.meaning) + (option.name == "ground"
                                             ? " Absent: " + std::string(option.default_text) + "."
                                             : std::string())},
         {"schema", std::move(schema)}});
  }
  with_sky(ops["getSkyPatches"], {}, true);
  // The sun query has no model, tables or limits: 400 only. Without time its answer is the
  // current sun, which no cache may keep (Cache-Control: no-store).
  add_revalidation(ops["getSun"]);
  add_common_errors(ops["getSun"], false);
  for (auto& [id, operation] : ops.items()) operation["security"] = Json::array();
  return ops;
}

}  // namespace

Area sky_area() {
  Area area;
  area.operations = operations();
  area.components["schemas"] = schemas();
  area.components["parameters"] = sky_parameter_components();
  const Json endpoint = endpoint_parameters();
  for (const auto& [name, parameter] : endpoint.items())
    area.components["parameters"][name] = parameter;
  return area;
}

}  // namespace clearsky::api::openapi
