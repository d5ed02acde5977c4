// Operations of the service itself (openapi_area.h): liveness, readiness, metrics, this document
// and the model list (server/http/http_server.cpp, api/handlers/models_handler.cpp). The examples
// are answers of a server started with --models preetham,hosek (the 503: preetham,bruneton on an
// empty cache, while Bruneton's tables were built).
#include "api/openapi/openapi_area.h"

namespace clearsky::api::openapi {

Area service_area() {
  Area area;
  area.components = parse(R"json({
  "schemas": {
    "Health": {
      "type": "object",
      "required": ["status"],
      "properties": {"status": {"type": "string", "enum": ["ok"]}}
    },
    "TableStatus": {
      "type": "string",
      "description": "State of a model's default tables; not_built when neither built at start nor asked for (measured_aerosols' until its first standard request, or a default left out of serve --prebuild).",
      "enum": ["queued", "precomputing", "ready", "failed", "not_built"]
    },
    "ModelReadiness": {
      "type": "object",
      "description": "Each served model's default tables, by model id, and the tables of each quality level (docs/quality-levels.md).",
      "additionalProperties": {
        "type": "object",
        "required": ["status", "progress", "levels"],
        "properties": {
          "status": {"$ref": "#/components/schemas/TableStatus"},
          "progress": {"type": "number", "minimum": 0, "maximum": 1},
          "levels": {
            "type": "object",
            "description": "draft, standard and reference: the state of the level's tables (on the default atmosphere and grid); not_built when neither built at start nor asked for.",
            "additionalProperties": {
              "type": "object",
              "required": ["status", "progress"],
              "properties": {
                "status": {"type": "string", "enum": ["queued", "precomputing", "ready", "failed", "not_built"]},
                "progress": {"type": "number", "minimum": 0, "maximum": 1}
              }
            }
          },
          "day_sun_states": {
            "type": "object",
            "description": "Only for a model with per-sun states in sun buckets (Haber; Nishita96's draft) among the configurations built at start: the background pass over every bucket from zenith 0 to the model's dark threshold, lowest first, each stored in the disk table cache; readiness does not wait for it (docs/tables-and-memory.md).",
            "required": ["built", "total"],
            "properties": {
              "built": {"type": "integer", "minimum": 0},
              "total": {"type": "integer", "minimum": 0}
            }
          }
        }
      }
    },
    "Readiness": {
      "type": "object",
      "required": ["status", "models"],
      "properties": {
        "status": {"type": "string", "enum": ["ready"]},
        "models": {"$ref": "#/components/schemas/ModelReadiness"}
      }
    },
    "NotReady": {
      "type": "object",
      "description": "The error body (code not_ready) with the state of every model's tables.",
      "required": ["error", "models"],
      "properties": {
        "error": {"$ref": "#/components/schemas/ErrorDetail"},
        "models": {"$ref": "#/components/schemas/ModelReadiness"}
      }
    },
    "ModelList": {
      "type": "object",
      "required": ["models"],
      "properties": {
        "models": {"type": "array", "items": {"$ref": "#/components/schemas/Model"}}
      }
    },
    "Model": {
      "type": "object",
      "description": "A model's descriptor (models/core/model_descriptor.h) with the state of its default tables.",
      "required": ["id", "name", "version", "citation", "summary", "native_wavelengths_nm", "wavelength_range_nm", "parameters", "capabilities", "state"],
      "properties": {
        "id": {"type": "string", "description": "The value of the model parameter of the sky endpoints."},
        "name": {"type": "string"},
        "version": {"type": "string", "description": "Bumped when the model's numbers change."},
        "citation": {"type": "string"},
        "summary": {"type": "string"},
        "native_wavelengths_nm": {"type": "array", "items": {"type": "number"}, "description": "Empty: any wavelength in the range."},
        "wavelength_range_nm": {
          "type": "array", "minItems": 2, "maxItems": 2,
          "items": {"type": "number", "nullable": true},
          "description": "[min, max] answered, nm; null for an unbounded end."
        },
        "parameters": {"type": "array", "items": {"$ref": "#/components/schemas/ModelParameter"}},
        "capabilities": {"$ref": "#/components/schemas/ModelCapabilities"},
        "state": {"$ref": "#/components/schemas/ModelState"}
      }
    },
    "ModelParameter": {
      "type": "object",
      "description": "A parameter the model takes (as a query parameter of the sky endpoints, or in evaluation parameters).",
      "required": ["name", "unit", "description", "default", "min", "max", "integer", "kind"],
      "properties": {
        "name": {"type": "string"},
        "unit": {"type": "string", "description": "Empty when dimensionless."},
        "description": {"type": "string"},
        "default": {"type": "number", "nullable": true},
        "min": {"type": "number", "nullable": true, "description": "Inclusive; null when unbounded."},
        "max": {"type": "number", "nullable": true, "description": "Inclusive; null when unbounded."},
        "integer": {"type": "boolean"},
        "kind": {"type": "string", "enum": ["atmosphere", "model"], "description": "atmosphere: one of the shared atmosphere parameters; model: an option of this model."}
      }
    },
    "ModelCapabilities": {
      "type": "object",
      "required": ["altitude_range_m", "view_from_space", "view_below_horizon", "aerial_perspective", "max_sun_zenith_deg", "sun_below_horizon", "scattering_orders", "per_sun_precomputation", "sun_irradiance", "sky_irradiance"],
      "properties": {
        "altitude_range_m": {
          "type": "array", "minItems": 2, "maxItems": 2,
          "items": {"type": "number", "nullable": true},
          "description": "Observer altitudes answered, m; null: unbounded."
        },
        "view_from_space": {"type": "boolean"},
        "view_below_horizon": {"type": "boolean"},
        "aerial_perspective": {"type": "boolean"},
        "max_sun_zenith_deg": {"type": "number"},
        "sun_below_horizon": {"type": "boolean"},
        "dark_beyond_sun_zenith_deg": {"type": "number", "nullable": true, "description": "Beyond this sun zenith (degrees) the model's sky is exactly dark (the sun below the horizon of the top of its atmosphere everywhere the model integrates): radiance, colour and irradiance are zeros, answered at once without any per-sun precomputation. null: the model declares none."},
        "scattering_orders": {
          "oneOf": [{"type": "integer", "minimum": 1}, {"type": "string", "enum": ["all"]}]
        },
        "per_sun_precomputation": {"type": "boolean"},
        "sun_irradiance": {"type": "boolean"},
        "sky_irradiance": {"type": "boolean"}
      }
    },
    "ModelState": {
      "type": "object",
      "description": "The default tables: precompute time, cache use and memory once ready, the error when failed.",
      "required": ["status", "progress", "stage"],
      "properties": {
        "status": {"$ref": "#/components/schemas/TableStatus"},
        "progress": {"type": "number", "minimum": 0, "maximum": 1},
        "stage": {"type": "string"},
        "precompute_seconds": {"type": "number", "minimum": 0},
        "table_bytes": {"type": "integer", "minimum": 0},
        "loaded_from_cache": {"type": "boolean"},
        "error": {"type": "string"}
      }
    },
    "OpenApiDocument": {
      "type": "object",
      "description": "An OpenAPI 3.0 document.",
      "required": ["openapi", "info", "paths"],
      "properties": {
        "openapi": {"type": "string"},
        "info": {"type": "object"},
        "paths": {"type": "object"}
      }
    },
    "PrometheusText": {
      "type": "string",
      "description": "Prometheus text exposition format 0.0.4."
    }
  }
})json");

  area.operations = parse(R"json({
  "healthz": {
    "operationId": "healthz",
    "tags": ["operations"],
    "summary": "Liveness",
    "description": "200 as soon as the process serves requests, whatever the state of the tables.",
    "responses": {
      "200": {
        "description": "Alive.",
        "content": {"application/json": {
          "schema": {"$ref": "#/components/schemas/Health"},
          "example": {"status": "ok"}
        }}
      }
    }
  },
  "readyz": {
    "operationId": "readyz",
    "tags": ["operations"],
    "summary": "Readiness",
    "description": "200 when the tables built at start are ready (each served model's draft, then its standard but measured_aerosols', built on its first use, or serve --prebuild's list: docs/quality-levels.md); 503 while some are built (Bruneton's take minutes on a first start), with each model's state, and 503 (code draining) once the server drains before it stops (SIGTERM; docs/deploy.md).",
    "responses": {
      "200": {
        "description": "Every model is ready.",
        "content": {"application/json": {
          "schema": {"$ref": "#/components/schemas/Readiness"},
          "example": {"models": {"hosek": {"progress": 1.0, "status": "ready", "levels": {"draft": {"progress": 1.0, "status": "ready"}, "standard": {"progress": 1.0, "status": "ready"}, "reference": {"progress": 1.0, "status": "ready"}}}, "preetham": {"progress": 1.0, "status": "ready", "levels": {"draft": {"progress": 1.0, "status": "ready"}, "standard": {"progress": 1.0, "status": "ready"}, "reference": {"progress": 1.0, "status": "ready"}}}}, "status": "ready"}
        }}
      },
      "503": {
        "description": "Some default tables are still being built (code not_ready), or the server is draining (code draining, without models).",
        "headers": {"Retry-After": {"$ref": "#/components/headers/Retry-After"}},
        "content": {"application/json": {
          "schema": {"$ref": "#/components/schemas/NotReady"},
          "example": {"error": {"code": "not_ready", "message": "the default tables of some models are being built", "parameter": null}, "models": {"bruneton": {"progress": 0.0042955326460481094, "status": "precomputing", "levels": {"draft": {"progress": 1.0, "status": "ready"}, "standard": {"progress": 0.0042955326460481094, "status": "precomputing"}, "reference": {"progress": 0.0, "status": "not_built"}}}, "preetham": {"progress": 1.0, "status": "ready", "levels": {"draft": {"progress": 1.0, "status": "ready"}, "standard": {"progress": 1.0, "status": "ready"}, "reference": {"progress": 1.0, "status": "ready"}}}}}
        }}
      }
    }
  },
  "metrics": {
    "operationId": "metrics",
    "tags": ["operations"],
    "summary": "Prometheus metrics",
    "description": "Requests and latency per endpoint, model and status, table memory, cache lookups.",
    "responses": {
      "200": {
        "description": "Prometheus text format.",
        "content": {"text/plain": {
          "schema": {"$ref": "#/components/schemas/PrometheusText"},
          "example": "# HELP clearsky_http_requests_total HTTP requests by endpoint, model and status\n# TYPE clearsky_http_requests_total counter\nclearsky_http_requests_total{endpoint=\"/readyz\",model=\"none\",status=\"200\"} 1\n"
        }}
      }
    }
  },
  "openapi": {
    "operationId": "openapi",
    "tags": ["operations"],
    "summary": "This document",
    "description": "The OpenAPI 3.0 description of HTTP API v1 (docs/openapi.md).",
    "responses": {
      "200": {
        "description": "The document.",
        "content": {"application/json": {"schema": {"$ref": "#/components/schemas/OpenApiDocument"}}}
      }
    }
  },
  "listModels": {
    "operationId": "listModels",
    "tags": ["models"],
    "summary": "Served models",
    "description": "Each served model's descriptor (citation, parameters with units, defaults and ranges, capabilities, wavelength range) and the state of its default tables.",
    "responses": {
      "200": {
        "description": "The models, in the paper's order.",
        "content": {"application/json": {
          "schema": {"$ref": "#/components/schemas/ModelList"},
          "example": {"models": [{"capabilities": {"aerial_perspective": false, "altitude_range_m": [0.0, 0.0], "dark_beyond_sun_zenith_deg": null, "max_sun_zenith_deg": 90.0, "per_sun_precomputation": false, "scattering_orders": "all", "sky_irradiance": true, "sun_below_horizon": false, "sun_irradiance": true, "view_below_horizon": false, "view_from_space": false}, "citation": "A. J. Preetham, P. Shirley, B. Smits. A Practical Analytic Model for Daylight. Proceedings of SIGGRAPH 1999, pages 91-100.", "id": "preetham", "name": "Preetham 1999", "native_wavelengths_nm": [], "parameters": [{"default": 2.53, "description": "atmospheric (Linke-style) turbidity of the fitted models (the study: 2.53)", "integer": false, "kind": "atmosphere", "max": 10.0, "min": 2.0, "name": "turbidity", "unit": ""}, {"default": 0.0, "description": "1: where the fitted spectrum turns negative (a low sun, views near the horizon towards it) answer 0 there; 0: refuse those samples (status outside_fit_domain)", "integer": true, "kind": "model", "max": 1.0, "min": 0.0, "name": "clamp_negative_fit", "unit": ""}], "state": {"loaded_from_cache": false, "precompute_seconds": 4.9338e-05, "progress": 1.0, "stage": "", "status": "ready", "table_bytes": 0}, "summary": "Analytic sky luminance and chromaticity: Perez distributions fitted to Nishita96 skies, with zenith luminance and chromaticity as functions of turbidity and sun zenith; the spectrum is the CIE daylight basis S0 + M1 S1 + M2 S2 for the chromaticity, scaled to the luminance. As in the 2016 study: turbidity 2.53; the extraterrestrial spectrum, albedo and aerosol parameters are built into the fit and ignored. Ground views only, sun above the horizon.", "version": "2", "wavelength_range_nm": [360.0, 830.0]}]}
        }}
      },
      "400": {
        "description": "A query parameter (the endpoint takes none; code unknown_parameter).",
        "content": {"application/json": {
          "schema": {"$ref": "#/components/schemas/Error"},
          "example": {"error": {"code": "unknown_parameter", "message": "verbose: not a parameter of GET /v1/models (or not used by this request)", "parameter": "verbose"}}
        }}
      }
    }
  }
})json");
  add_revalidation(area.operations["openapi"]);
  add_revalidation(area.operations["listModels"]);
  for (auto& [id, operation] : area.operations.items()) {
    operation["security"] = Json::array();
    add_common_errors(operation, false);
  }
  return area;
}

}  // namespace clearsky::api::openapi
