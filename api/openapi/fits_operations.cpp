// The fit operations (openapi_area.h): atmosphere fits of a model to a stored dataset, run on
// the background fit workers (api/fits/fits_api.h, api/fits/fit_pool.h; docs/fits.md). The
// answer is the JSON of `clearsky fit --json` (api/encode/fit_json.h).
#include "api/openapi/openapi_area.h"

namespace clearsky::api::openapi {
namespace {

Json schemas() {
  return parse(R"json({
  "FitRequest": {
    "type": "object",
    "required": ["dataset", "model"],
    "additionalProperties": false,
    "properties": {
      "dataset": {"type": "string", "description": "A stored dataset."},
      "model": {"type": "string", "description": "The model to fit (GET /v1/models)."},
      "free": {"type": "array", "items": {"type": "string"}, "description": "The free parameters: continuous parameters the model's descriptor lists (alpha, beta, g, turbidity, albedo or a model option). Default: alpha, beta, g for the models that list them, else turbidity."},
      "bounds": {"type": "object", "additionalProperties": {"type": "array", "items": {"type": "number"}, "minItems": 2, "maxItems": 2}, "description": "{name: [min, max]} inside the descriptor's range. Default: the descriptor's range, except alpha [0, 2], beta [0.02, 0.2], g [0.5, 0.9]."},
      "grid": {"type": "array", "items": {"type": "integer", "minimum": 1, "maximum": 101}, "description": "Grid points per free parameter, in the order of free."},
      "captures": {"type": "array", "items": {"type": "string"}, "description": "The capture labels to fit (default: all)."},
      "parameters": {"$ref": "#/components/schemas/EvaluationParameters"},
      "search_options": {"type": "object", "additionalProperties": {"type": "number"}, "description": "Table options for the search (default: cheap tables; {} searches at the standard setting)."},
      "per_capture": {"type": "boolean", "default": false, "description": "Also fit each capture alone."},
      "cross_validate": {"type": "boolean", "default": false, "description": "Leave-one-capture-out: the held-out RMSE."},
      "max_evaluations": {"type": "integer", "minimum": 0, "maximum": 10000, "default": 200, "description": "Refinement budget after the grid (model builds)."},
      "fold_evaluations": {"type": "integer", "minimum": 0, "maximum": 10000, "default": 60, "description": "Refinement budget per capture and per fold."}
    }
  },
  "Fit": {
    "type": "object",
    "description": "A stored fit (docs/fits.md \"The answer\"): the request, its state and progress while it runs, and its results when it succeeded. RMSE in mW/(m2.sr.nm); an RMSE the model could not give is null.",
    "required": ["id", "dataset", "model", "model_version", "status", "progress", "stage", "free_parameters", "parameters", "search_options", "captures", "settings", "software_version", "created_utc", "finished_utc"],
    "additionalProperties": false,
    "properties": {
      "id": {"type": "integer", "minimum": 1},
      "dataset": {"type": "string"},
      "model": {"type": "string"},
      "model_version": {"type": "string"},
      "status": {"type": "string", "enum": ["queued", "running", "succeeded", "failed", "interrupted"], "description": "interrupted: the server stopped before the fit ended."},
      "progress": {"type": "number", "minimum": 0, "maximum": 1},
      "stage": {"type": "string", "nullable": true, "description": "The stage running (before, grid, refine, scan, per_capture, cross_validate, confirm)."},
      "free_parameters": {"type": "array", "items": {"type": "object", "required": ["name", "min", "max", "grid_points"], "properties": {"name": {"type": "string"}, "min": {"type": "number"}, "max": {"type": "number"}, "grid_points": {"type": "integer"}}}},
      "parameters": {"type": "object", "description": "The fixed parameters and options as applied."},
      "search_options": {"type": "object"},
      "captures": {"type": "array", "items": {"type": "string"}},
      "settings": {"type": "object"},
      "software_version": {"type": "string"},
      "created_utc": {"type": "string"},
      "finished_utc": {"type": "string", "nullable": true},
      "error": {"type": "string", "description": "Why it failed or was interrupted."},
      "location": {"type": "string", "description": "The fit to follow (POST only)."},
      "values": {"type": "object", "additionalProperties": {"type": "number"}, "description": "The fitted values by name."},
      "rmse_before": {"type": "number", "nullable": true},
      "rmse_search": {"type": "number", "nullable": true},
      "rmse_after": {"type": "number", "nullable": true},
      "cross_validated_rmse": {"type": "number", "nullable": true},
      "search": {"type": "object", "description": "Initial values, best grid point and its RMSE, the refinement's algorithm, stop reason and evaluations."},
      "uncertainty": {"type": "array", "items": {"type": "object"}, "description": "Per free parameter: value, scan and sampled 1% ranges."},
      "captures_fitted": {"type": "array", "items": {"type": "object"}},
      "seconds": {"type": "object", "additionalProperties": {"type": "number"}},
      "history": {"type": "array", "items": {"type": "object"}, "description": "Every point evaluated (history=true)."}
    }
  },
  "FitList": {"type": "array", "items": {"$ref": "#/components/schemas/Fit"}}
})json");
}

const char* kQueuedExample =
    R"json({"id": 1, "dataset": "synthetic", "model": "preetham", "model_version": "1", "status": "queued", "progress": 0.0, "stage": null, "free_parameters": [{"name": "turbidity", "min": 2.0, "max": 6.0, "grid_points": 9}], "parameters": {}, "search_options": {}, "captures": [], "settings": {"cross_validate": false, "max_fold_refine_evaluations": 60, "max_refine_evaluations": 200, "per_capture": false, "uncertainty_fraction": 0.01}, "software_version": "0.1.0", "created_utc": "2026-11-25T13:30:00.000Z", "finished_utc": null, "location": "/v1/fits/1"})json";

Json fit_path_parameter() {
  return parse(
      R"json({"name": "id", "in": "path", "required": true, "description": "The fit's id.", "schema": {"type": "integer", "minimum": 1}, "example": 1})json");
}

Json operations() {
  Json ops = parse(R"json({
  "listFits": {
    "operationId": "listFits",
    "tags": ["fits"],
    "summary": "Stored fits",
    "description": "Fits, newest first, without their history.",
    "parameters": [
      {"$ref": "#/components/parameters/limit"},
      {"$ref": "#/components/parameters/cursor"}
    ],
    "responses": {
      "200": {
        "description": "The fits.",
        "headers": {"Link": {"$ref": "#/components/headers/Link"}},
        "content": {"application/json": {"schema": {"$ref": "#/components/schemas/FitList"}}}
      },
      "400": {"description": "An unknown parameter, an invalid limit or cursor."}
    }
  },
  "createFit": {
    "operationId": "createFit",
    "tags": ["fits"],
    "summary": "Start an atmosphere fit",
    "description": "Fits a model's parameters to a stored dataset on the background fit worker (docs/fits.md: a grid, then BOBYQA refinement, uncertainty ranges, optionally per capture and cross-validated). The body is checked before it is queued; 202 with the queued fit, whose progress and stage GET /v1/fits/{id} gives while it runs.",
    "requestBody": {
      "required": true,
      "content": {"application/json": {
        "schema": {"$ref": "#/components/schemas/FitRequest"},
        "example": {"dataset": "synthetic", "model": "preetham", "free": ["turbidity"], "bounds": {"turbidity": [2, 6]}, "grid": [9]}
      }}
    },
    "responses": {
      "202": {
        "description": "Queued: the fit; follow Location (also the body's location).",
        "headers": {"Location": {"description": "/v1/fits/{id}", "required": true, "schema": {"type": "string"}}},
        "content": {"application/json": {"schema": {"$ref": "#/components/schemas/Fit"}}}
      },
      "400": {"description": "A body that is not a JSON object, an unknown member, no dataset or model, an unknown model, a parameter that cannot be fitted, bad bounds or grid counts, a capture label the dataset does not hold, or an invalid parameter (the error names the member)."},
      "404": {"description": "No such dataset (unknown_dataset)."},
      "503": {"description": "The fit queue is full (code busy)."}
    }
  },
  "getFit": {
    "operationId": "getFit",
    "tags": ["fits"],
    "summary": "One fit",
    "description": "A fit's state and progress while it is queued or runs; its values, RMSE before and after, uncertainty and per-capture results when it succeeded; the error when it failed or was interrupted. Fits are stored: they answer after a restart.",
    "parameters": [
      {"name": "history", "in": "query", "required": false, "description": "true: add every point evaluated.", "schema": {"type": "boolean", "default": false}}
    ],
    "responses": {
      "200": {
        "description": "The fit.",
        "content": {"application/json": {"schema": {"$ref": "#/components/schemas/Fit"}}}
      },
      "400": {"description": "An unknown parameter, an id that is not a positive integer, or a history value other than true or false."},
      "404": {"description": "No such fit (code unknown_fit)."}
    }
  }
})json");
  ops["createFit"]["responses"]["202"]["content"]["application/json"]["example"] =
      parse(kQueuedExample);
  ops["getFit"]["parameters"].insert(ops["getFit"]["parameters"].begin(), fit_path_parameter());
  return ops;
}

}  // namespace

Area fits_area() {
  Area area;
  area.components["schemas"] = schemas();
  area.operations = operations();
  complete_errors(area.operations);
  for (auto& [id, operation] : area.operations.items()) {
    operation["security"] = Json::array();
    if (id == "createFit") make_write(operation);
    add_common_errors(operation, id == "createFit");
    add_query_replica_answer(operation);
  }
  return area;
}

}  // namespace clearsky::api::openapi
