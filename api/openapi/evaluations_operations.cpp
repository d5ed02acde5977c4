// The evaluation and job operations (openapi_area.h): runs of models against a stored dataset
// on the background evaluation workers, and scheduled evaluations (api/evaluation/
// evaluations_api.h, api/evaluation/evaluation_pool.h, api/jobs/jobs_api.h). The examples are
// answers of a server that evaluated Preetham on a synthetic capture
// (tests/server/openapi/synthetic_kider.py).
#include "api/openapi/openapi_area.h"

namespace clearsky::api::openapi {
namespace {

Json schemas() {
  return parse(R"json({
  "ModelSelection": {
    "description": "\"all\" (every served model) or model ids.",
    "oneOf": [
      {"type": "string", "example": "all"},
      {"type": "array", "minItems": 1, "items": {"type": "string"}}
    ]
  },
  "EvaluationParameters": {
    "type": "object",
    "description": "The shared atmosphere parameters (alpha, beta, g, turbidity, albedo as a number or \"grass\", ...) and any option of a requested model, each applied to the models whose descriptor lists it and range-checked before queueing (GET /v1/models lists them).",
    "properties": {
      "out_of_domain": {"type": "string", "enum": ["exclude", "clamp"], "default": "exclude", "description": "Samples a model cannot answer (outside its fit domain, below its horizon, outside its wavelengths): left out of the RMSE and counted (exclude), or answered at the nearest point of the model's domain and counted (clamp)."},
      "fit": {"oneOf": [{"type": "integer", "minimum": 1}, {"type": "string", "pattern": "^([1-9][0-9]*|latest(:.+)?)$"}], "description": "A stored fit (docs/fits.md \"Using a fit\"): its id applies its fitted values to its own model (which must be requested; else 409 fit_model_mismatch), latest (or latest:DATASET) to each requested model its newest succeeded fit (404 unknown_fit when one has none); a fit not succeeded is a 409 fit_not_succeeded; a parameter given too that the fit sets is a 400 conflicting_parameters naming it. Expanded when each model's run starts (a job with latest uses the newest fit at each occurrence); a run stores the id used as fit and the values it set."}
    },
    "additionalProperties": {
      "oneOf": [{"type": "number"}, {"type": "string", "enum": ["grass"]}]
    },
    "example": {"turbidity": 3}
  },
  "EvaluationRequest": {
    "type": "object",
    "required": ["dataset"],
    "additionalProperties": false,
    "properties": {
      "dataset": {"type": "string", "description": "A stored dataset."},
      "models": {"allOf": [{"$ref": "#/components/schemas/ModelSelection"}], "default": "all"},
      "parameters": {"$ref": "#/components/schemas/EvaluationParameters"}
    }
  },
  "EvaluationTicket": {
    "type": "object",
    "description": "A started evaluation, stored in the database when it is accepted (ids are never reused; it outlives a restart): its state and every requested model, with the id of its run once it starts.",
    "required": ["ticket", "dataset", "status", "created", "finished", "runs", "models"],
    "additionalProperties": false,
    "properties": {
      "ticket": {"type": "integer", "minimum": 1},
      "dataset": {"type": "string"},
      "status": {"type": "string", "enum": ["queued", "running", "succeeded", "failed", "interrupted"], "description": "interrupted: the server stopped (was killed or shut down) before the ticket ended."},
      "created": {"type": "string", "format": "date-time"},
      "finished": {"type": "string", "format": "date-time", "nullable": true},
      "runs": {"type": "array", "items": {"type": "integer", "minimum": 1}, "description": "The ids of the runs started, in the order they started."},
      "models": {
        "type": "array",
        "description": "Every requested model from the start, in the order they run: queued until its run starts (run null), then its run's id and status; skipped when the ticket failed before it ran; interrupted when the server stopped first.",
        "items": {
          "type": "object",
          "required": ["model", "run", "status"],
          "additionalProperties": false,
          "properties": {
            "model": {"type": "string"},
            "run": {"type": "integer", "minimum": 1, "nullable": true},
            "status": {"type": "string", "enum": ["queued", "running", "succeeded", "failed", "skipped", "interrupted"]},
            "error": {"type": "string", "description": "Why the model was skipped or interrupted."}
          }
        }
      },
      "error": {"type": "string", "description": "When failed or interrupted."},
      "location": {"type": "string", "description": "In the answer of POST: /v1/evaluations/tickets/{ticket}."}
    }
  },
  "RunStatus": {
    "type": "string",
    "enum": ["running", "succeeded", "failed"]
  },
  "IrradianceComponentResult": {
    "type": "object",
    "required": ["component", "rmse_w_m2", "mean_bias_w_m2", "samples_compared"],
    "additionalProperties": false,
    "description": "One measured component of a broadband irradiance dataset against the model's broadband (300..4000 nm) figure (docs/data-api.md \"Evaluations of broadband irradiance\").",
    "properties": {
      "component": {"type": "string", "enum": ["ghi", "dhi", "dni"], "description": "Global horizontal, diffuse horizontal or direct normal irradiance."},
      "rmse_w_m2": {"type": "number", "minimum": 0, "nullable": true, "description": "RMSE over the samples compared, W/m2; null when none was compared."},
      "mean_bias_w_m2": {"type": "number", "nullable": true, "description": "Mean of model minus measured over the samples compared, W/m2; null when none was compared."},
      "samples_compared": {"type": "integer", "minimum": 0, "description": "Samples of this component compared (the sun above the horizon at the instant, or at the middle of an averaged sample's period)."},
      "errors_w_m2": {"type": "array", "items": {"type": "number", "nullable": true}, "description": "With samples=true or spectra (GET /v1/evaluations/{id}): each sample's error, model minus measured, W/m2, in the dataset's order by instant; null where not compared."}
    }
  },
  "EvaluationSummary": {
    "type": "object",
    "required": ["id", "dataset", "model", "status", "started", "finished", "rmse", "rmse_unit", "samples_compared", "irradiance_components", "job"],
    "additionalProperties": false,
    "properties": {
      "id": {"type": "integer", "minimum": 1},
      "dataset": {"type": "string"},
      "model": {"type": "string"},
      "status": {"$ref": "#/components/schemas/RunStatus"},
      "started": {"type": "string", "format": "date-time"},
      "finished": {"type": "string", "format": "date-time", "nullable": true},
      "rmse": {"type": "number", "nullable": true, "description": "In rmse_unit: mW/(m2.sr.nm) over the run's wavelength range on captures; W/m2 on a broadband irradiance dataset, all compared components pooled."},
      "rmse_unit": {"$ref": "#/components/schemas/RmseUnit"},
      "samples_compared": {"type": "integer", "minimum": 0, "nullable": true, "description": "The samples the RMSE covers; null for runs stored before it was kept."},
      "irradiance_components": {"type": "array", "items": {"$ref": "#/components/schemas/IrradianceComponentResult"}, "description": "On a broadband irradiance dataset, per measured component (ghi, dhi, dni in that order); empty for a run on captures."},
      "job": {"type": "integer", "nullable": true, "description": "The scheduled job that ran it."}
    }
  },
  "RmseUnit": {
    "type": "string",
    "enum": ["mW/(m2.sr.nm)", "W/m2"],
    "description": "The unit of the run's rmse: spectral radiance on captures, irradiance on a broadband irradiance dataset."
  },
  "EvaluationList": {
    "type": "array",
    "items": {"$ref": "#/components/schemas/EvaluationSummary"}
  },
  "SampleError": {
    "type": "object",
    "required": ["index", "view_zenith", "view_azimuth", "rmse", "bias"],
    "additionalProperties": false,
    "properties": {
      "index": {"type": "integer", "minimum": 0},
      "view_zenith": {"type": "number"},
      "view_azimuth": {"type": "number"},
      "rmse": {"type": "number", "minimum": 0, "description": "mW/(m2.sr.nm) over the run's wavelengths."},
      "bias": {"type": "number", "description": "Mean of model - measured, mW/(m2.sr.nm)."},
      "errors": {"type": "array", "items": {"type": "number"}, "description": "samples=spectra: model - measured at each of the run's wavelengths_nm."}
    }
  },
  "SampleHandling": {
    "type": "object",
    "description": "Samples of a capture the model could not answer for one reason, and what was done with them.",
    "required": ["reason", "count", "samples"],
    "additionalProperties": false,
    "properties": {
      "reason": {"type": "string", "description": "The refusal: the parameter the model refused (e.g. sun_zenith outside the fit domain) and why."},
      "count": {"type": "integer", "minimum": 1},
      "samples": {"type": "array", "items": {"type": "integer", "minimum": 0}, "description": "Scan indices."}
    }
  },
  "EvaluationCapture": {
    "type": "object",
    "required": ["label", "time", "sun_zenith", "sun_azimuth", "rmse", "values_compared", "samples_compared", "excluded", "clamped"],
    "additionalProperties": false,
    "properties": {
      "label": {"type": "string"},
      "time": {"type": "string", "format": "date-time"},
      "sun_zenith": {"type": "number"},
      "sun_azimuth": {"type": "number"},
      "rmse": {"type": "number", "minimum": 0, "nullable": true, "description": "null when the model could answer no sample of the capture (unanswered)."},
      "values_compared": {"type": "integer", "minimum": 0},
      "samples_compared": {"type": "integer", "minimum": 0, "nullable": true, "description": "null for runs stored before it was kept."},
      "excluded": {"type": "array", "items": {"$ref": "#/components/schemas/SampleHandling"}},
      "clamped": {"type": "array", "items": {"$ref": "#/components/schemas/SampleHandling"}},
      "samples": {"type": "array", "nullable": true, "items": {"$ref": "#/components/schemas/SampleError"}, "description": "With samples=true or spectra; null for runs stored before per-sample errors were kept."}
    }
  },
  "Evaluation": {
    "type": "object",
    "required": ["id", "dataset", "model", "model_version", "parameters", "software_version", "wavelength_range_nm", "job", "status", "error", "started", "finished", "rmse", "rmse_unit", "irradiance_components", "out_of_domain", "samples_compared", "samples_excluded", "samples_clamped", "captures_unanswered", "timings", "processing_steps", "captures", "history"],
    "additionalProperties": false,
    "properties": {
      "id": {"type": "integer", "minimum": 1},
      "dataset": {"type": "string", "nullable": true},
      "model": {"type": "string"},
      "model_version": {"type": "string"},
      "parameters": {"allOf": [{"$ref": "#/components/schemas/EvaluationParameters"}], "description": "The parameters applied to this run's model, as given, with a fit expanded: fit is then the id used and its values are among the parameters (docs/data-api.md)."},
      "software_version": {"type": "string"},
      "wavelength_range_nm": {"type": "array", "minItems": 2, "maxItems": 2, "items": {"type": "number"}},
      "wavelengths_nm": {"type": "array", "nullable": true, "items": {"type": "number"}, "description": "With samples=spectra; null for runs stored before per-sample errors were kept."},
      "job": {"type": "integer", "nullable": true},
      "status": {"$ref": "#/components/schemas/RunStatus"},
      "error": {"type": "string", "nullable": true},
      "started": {"type": "string", "format": "date-time"},
      "finished": {"type": "string", "format": "date-time", "nullable": true},
      "rmse": {"type": "number", "nullable": true, "description": "In rmse_unit."},
      "rmse_unit": {"$ref": "#/components/schemas/RmseUnit"},
      "irradiance_components": {"type": "array", "items": {"$ref": "#/components/schemas/IrradianceComponentResult"}, "description": "On a broadband irradiance dataset, per measured component (ghi, dhi, dni in that order), with each sample's error when samples=true; empty for a run on captures. processing_steps says at which altitude the model answered (the site's elevation, or its ground when its descriptor does not answer that altitude) and how averaged samples were compared."},
      "out_of_domain": {"type": "string", "enum": ["exclude", "clamp"], "description": "What was done with samples the model could not answer."},
      "samples_compared": {"type": "integer", "minimum": 0, "nullable": true, "description": "The samples the RMSE covers (null for runs stored before it was kept); the history compares runs over the same samples only."},
      "samples_excluded": {"type": "integer", "minimum": 0, "nullable": true},
      "samples_clamped": {"type": "integer", "minimum": 0, "nullable": true},
      "captures_unanswered": {"type": "integer", "minimum": 0, "nullable": true, "description": "Captures of which the model could answer no sample."},
      "timings": {
        "type": "object",
        "required": ["precompute_seconds", "evaluate_seconds"],
        "additionalProperties": false,
        "properties": {
          "precompute_seconds": {"type": "number", "nullable": true},
          "evaluate_seconds": {"type": "number", "nullable": true}
        }
      },
      "processing_steps": {"type": "array", "items": {"type": "string"}},
      "captures": {"type": "array", "items": {"$ref": "#/components/schemas/EvaluationCapture"}},
      "history": {
        "type": "object",
        "description": "The newest earlier succeeded run of the same dataset, model, parameters and wavelength range; nulls when there is none or this run did not succeed.",
        "required": ["previous_run", "previous_rmse", "rmse_changed"],
        "additionalProperties": false,
        "properties": {
          "previous_run": {"type": "integer", "nullable": true},
          "previous_rmse": {"type": "number", "nullable": true},
          "rmse_changed": {"type": "boolean", "nullable": true, "description": "Relative difference above 1e-9."}
        }
      }
    }
  },
  "JobRequest": {
    "type": "object",
    "required": ["name", "schedule", "dataset"],
    "additionalProperties": false,
    "properties": {
      "name": {"type": "string", "minLength": 1, "description": "Unique."},
      "schedule": {"type": "string", "description": "5-field cron schedule in UTC: minute hour day-of-month month day-of-week."},
      "dataset": {"type": "string"},
      "models": {"allOf": [{"$ref": "#/components/schemas/ModelSelection"}], "default": "all"},
      "parameters": {"$ref": "#/components/schemas/EvaluationParameters"},
      "refit": {"$ref": "#/components/schemas/JobRefit"}
    }
  },
  "JobRefit": {
    "type": "object",
    "nullable": true,
    "required": ["model"],
    "additionalProperties": false,
    "description": "The fit each occurrence runs before evaluating (docs/fits.md \"In evaluations and jobs\"): the body of POST /v1/fits without dataset (the job's dataset is fitted), checked at creation as POST /v1/fits checks it, a 400 naming refit.<member>. The model must be among the job's models; the job's parameters may not give fit or a parameter the fit frees. Each occurrence evaluates with \"fit\" = the new fit's id (the fitted model only); a failed fit fails the occurrence, nothing is evaluated. null: the job does not re-fit.",
    "properties": {
      "model": {"type": "string", "description": "The model to fit, one of the job's models."},
      "free": {"type": "array", "items": {"type": "string"}, "description": "As in FitRequest."},
      "bounds": {"type": "object", "additionalProperties": {"type": "array", "items": {"type": "number"}, "minItems": 2, "maxItems": 2}, "description": "As in FitRequest."},
      "grid": {"type": "array", "items": {"type": "integer", "minimum": 1, "maximum": 101}, "description": "As in FitRequest."},
      "captures": {"type": "array", "items": {"type": "string"}, "description": "As in FitRequest."},
      "parameters": {"$ref": "#/components/schemas/EvaluationParameters"},
      "search_options": {"type": "object", "additionalProperties": {"type": "number"}, "description": "As in FitRequest."},
      "per_capture": {"type": "boolean", "default": false},
      "cross_validate": {"type": "boolean", "default": false},
      "max_evaluations": {"type": "integer", "minimum": 0, "maximum": 10000, "default": 200},
      "fold_evaluations": {"type": "integer", "minimum": 0, "maximum": 10000, "default": 60}
    }
  },
  "JobFit": {
    "type": "object",
    "nullable": true,
    "required": ["id", "status", "rmse_after", "values", "error"],
    "additionalProperties": false,
    "description": "The fit the job's newest occurrence made (GET /v1/fits/{id} has all of it); null before the first occurrence, for a job without refit, or once the fit went with its dataset.",
    "properties": {
      "id": {"type": "integer", "minimum": 1},
      "status": {"type": "string", "enum": ["queued", "running", "succeeded", "failed", "interrupted"], "description": "failed: the occurrence failed and evaluated nothing."},
      "rmse_after": {"type": "number", "nullable": true, "description": "Null until the fit succeeded."},
      "values": {"type": "object", "nullable": true, "additionalProperties": {"type": "number"}, "description": "The fitted values; null until the fit succeeded."},
      "error": {"type": "string", "nullable": true, "description": "Why the fit failed or was interrupted."}
    }
  },
  "JobResult": {
    "type": "object",
    "required": ["run", "model", "status", "started", "rmse"],
    "additionalProperties": false,
    "properties": {
      "run": {"type": "integer", "minimum": 1},
      "model": {"type": "string"},
      "status": {"$ref": "#/components/schemas/RunStatus"},
      "started": {"type": "string", "format": "date-time"},
      "rmse": {"type": "number", "nullable": true}
    }
  },
  "Job": {
    "type": "object",
    "required": ["id", "name", "schedule", "dataset", "models", "parameters", "refit", "paused", "created", "last_run", "next_run", "skipped_count", "last_skipped", "last_fit", "last_result"],
    "additionalProperties": false,
    "properties": {
      "id": {"type": "integer", "minimum": 1},
      "name": {"type": "string"},
      "schedule": {"type": "string"},
      "dataset": {"type": "string"},
      "models": {"$ref": "#/components/schemas/ModelSelection"},
      "parameters": {"$ref": "#/components/schemas/EvaluationParameters"},
      "refit": {"$ref": "#/components/schemas/JobRefit"},
      "paused": {"type": "boolean"},
      "created": {"type": "string", "format": "date-time"},
      "last_run": {"type": "string", "format": "date-time", "nullable": true},
      "next_run": {"type": "string", "format": "date-time", "nullable": true, "description": "Computed from now at creation and on resume (a paused job does not catch up)."},
      "skipped_count": {"type": "integer", "minimum": 0, "description": "Due occurrences skipped because the job's previous run was still queued or running (one job never runs twice at once)."},
      "last_skipped": {"type": "string", "format": "date-time", "nullable": true, "description": "When the last skipped occurrence was due to start (the scheduler's clock, UTC); null: none skipped."},
      "last_fit": {"$ref": "#/components/schemas/JobFit"},
      "last_result": {"type": "array", "items": {"$ref": "#/components/schemas/JobResult"}, "description": "The newest run of each model the job evaluated; a re-fitting job's runs record their fit in their parameters."}
    }
  },
  "JobList": {
    "type": "array",
    "items": {"$ref": "#/components/schemas/Job"}
  },
  "JobDeleted": {
    "type": "object",
    "required": ["deleted"],
    "additionalProperties": false,
    "properties": {"deleted": {"type": "integer", "description": "The job's id."}}
  }
})json");
}

const char* kJobExample =
    R"json({"id": 1, "name": "nightly", "schedule": "0 3 * * *", "dataset": "synthetic", "models": ["preetham", "hosek"], "parameters": {"turbidity": 3}, "refit": null, "paused": false, "created": "2026-11-23T19:42:24.655Z", "last_run": null, "next_run": "2026-11-24T03:00:00Z", "skipped_count": 0, "last_skipped": null, "last_fit": null, "last_result": []})json";
const char* kRunExample =
    R"json({"id": 1, "dataset": "synthetic", "model": "preetham", "model_version": "1", "parameters": {"turbidity": 3}, "software_version": "0.1.0", "wavelength_range_nm": [360.0, 720.0], "job": null, "status": "succeeded", "error": null, "started": "2026-11-23T19:42:21.655Z", "finished": "2026-11-23T19:42:21.656Z", "rmse": 123.0398240797635, "rmse_unit": "mW/(m2.sr.nm)", "irradiance_components": [], "out_of_domain": "exclude", "samples_compared": 81, "samples_excluded": 0, "samples_clamped": 0, "captures_unanswered": 0, "timings": {"precompute_seconds": 3.9713e-05, "evaluate_seconds": 0.000182782}, "processing_steps": ["2013-05-27___11.45.00: sample 0 (zenith 77.8849 deg, azimuth 0.0000 deg) replaced by the mean of its ring neighbours 1 and 31", "2013-05-27___11.45.00: sun azimuth estimated from mirror symmetry: 116.077 deg (computed 136.077 deg, 201 candidates, +-20.0 deg in 0.20 deg steps)"], "captures": [{"label": "2013-05-27___11.45.00", "time": "2013-05-27T11:45:00-04:00", "sun_zenith": 26.651259213110777, "sun_azimuth": 116.07696990085265, "rmse": 123.0398240797635, "values_compared": 2511, "samples_compared": 81, "excluded": [], "clamped": []}], "history": {"previous_run": null, "previous_rmse": null, "rmse_changed": null}})json";

Json job_path_parameter() {
  return parse(
      R"json({"name": "id", "in": "path", "required": true, "description": "The job's id.", "schema": {"type": "integer", "minimum": 1}, "example": 1})json");
}

Json operations() {
  Json ops = parse(R"json({
  "listEvaluations": {
    "operationId": "listEvaluations",
    "tags": ["evaluations"],
    "summary": "Stored evaluation runs",
    "description": "Runs, newest first, with filters.",
    "parameters": [
      {"name": "model", "in": "query", "required": false, "description": "Runs of this model.", "schema": {"type": "string"}, "example": "preetham"},
      {"name": "dataset", "in": "query", "required": false, "description": "Runs on this dataset (404 when there is no such dataset).", "schema": {"type": "string"}},
      {"name": "since", "in": "query", "required": false, "description": "Started at or after this ISO 8601 time.", "schema": {"type": "string", "format": "date-time"}},
      {"name": "until", "in": "query", "required": false, "description": "Started before this ISO 8601 time.", "schema": {"type": "string", "format": "date-time"}},
      {"name": "status", "in": "query", "required": false, "description": "Runs in this state.", "schema": {"$ref": "#/components/schemas/RunStatus"}},
      {"name": "job", "in": "query", "required": false, "description": "Runs of this scheduled job (also after the job was deleted).", "schema": {"type": "integer", "minimum": 1}},
      {"name": "job_id", "in": "query", "required": false, "description": "The same as job (not both).", "schema": {"type": "integer", "minimum": 1}},
      {"$ref": "#/components/parameters/limit"},
      {"$ref": "#/components/parameters/cursor"}
    ],
    "responses": {
      "200": {
        "description": "The runs.",
        "headers": {"Link": {"$ref": "#/components/headers/Link"}},
        "content": {"application/json": {
          "schema": {"$ref": "#/components/schemas/EvaluationList"},
          "example": [{"id": 1, "dataset": "synthetic", "model": "preetham", "status": "succeeded", "started": "2026-11-23T19:42:21.655Z", "finished": "2026-11-23T19:42:21.656Z", "rmse": 123.0398240797635, "rmse_unit": "mW/(m2.sr.nm)", "samples_compared": 81, "irradiance_components": [], "job": null}]
        }}
      },
      "400": {"description": "An unknown parameter, an invalid time, status or job."},
      "404": {"description": "No such dataset (code unknown_dataset)."}
    }
  },
  "createEvaluation": {
    "operationId": "createEvaluation",
    "tags": ["evaluations"],
    "summary": "Start an evaluation",
    "description": "Evaluates models against a stored dataset on the background evaluation workers (--evaluation-workers). The body is checked before it is queued; 202 with a ticket whose state gives the run ids. On a broadband irradiance dataset each model's broadband GHI, DHI and DNI are compared with the measured series (docs/data-api.md \"Evaluations of broadband irradiance\"); models all means those with a broadband answer.",
    "requestBody": {
      "required": true,
      "content": {"application/json": {
        "schema": {"$ref": "#/components/schemas/EvaluationRequest"},
        "example": {"models": ["preetham"], "dataset": "synthetic", "parameters": {"turbidity": 3}}
      }}
    },
    "responses": {
      "202": {
        "description": "Queued: the ticket's state; follow Location (also the body's location).",
        "headers": {"Location": {"description": "/v1/evaluations/tickets/{ticket}", "required": true, "schema": {"type": "string"}}},
        "content": {"application/json": {
          "schema": {"$ref": "#/components/schemas/EvaluationTicket"},
          "example": {"ticket": 1, "dataset": "synthetic", "status": "queued", "created": "2026-11-25T09:30:00.000Z", "finished": null, "runs": [], "models": [{"model": "preetham", "run": null, "status": "queued"}], "location": "/v1/evaluations/tickets/1"}
        }}
      },
      "400": {"description": "A body that is not a JSON object, an unknown member, no dataset, or an invalid model list or parameter."},
      "404": {"description": "No such dataset (unknown_dataset) or model (unknown_model), or no stored fit matches parameters.fit (unknown_fit, parameter fit)."},
      "409": {"description": "parameters.fit names a fit that is not succeeded (fit_not_succeeded) or of a model not requested (fit_model_mismatch); parameter fit."},
      "422": {"description": "A broadband irradiance dataset with a model named that has no broadband answer, Preetham or Hosek-Wilkie (broadband_unavailable, parameter models)."},
      "503": {"description": "The evaluation queue is full (--evaluation-queue; code busy)."}
    }
  },
  "getEvaluation": {
    "operationId": "getEvaluation",
    "tags": ["evaluations"],
    "summary": "One evaluation run",
    "description": "A run: total and per-capture RMSE (mW/(m2.sr.nm)), per-sample errors on request, timings, parameters, software version, and whether the RMSE changed against the last run with the same model and parameters.",
    "parameters": [
      {"name": "id", "in": "path", "required": true, "description": "The run's id.", "schema": {"type": "integer", "minimum": 1}, "example": 1},
      {"name": "samples", "in": "query", "required": false, "description": "true: each capture adds \"samples\": [{index, view_zenith, view_azimuth, rmse, bias}] (degrees, azimuth clockwise from North; RMSE over the run's wavelengths and bias = mean of model - measured, mW/(m2.sr.nm)); spectra: each sample also adds \"errors\" (model - measured at each of the run's \"wavelengths_nm\", added after wavelength_range_nm); false (default): neither. For runs stored before per-sample errors were kept, \"samples\" and \"wavelengths_nm\" are null.", "schema": {"type": "string", "enum": ["false", "true", "spectra"], "default": "false"}},
      {"name": "capture", "in": "query", "required": false, "description": "Only the capture with this label.", "schema": {"type": "string"}}
    ],
    "responses": {
      "200": {
        "description": "The run.",
        "content": {"application/json": {"schema": {"$ref": "#/components/schemas/Evaluation"}}}
      },
      "400": {"description": "An unknown parameter, an id that is not a positive integer, or a samples value other than true, false or spectra."},
      "404": {"description": "No such run (unknown_evaluation), or no capture of that label in the run."}
    }
  },
  "getEvaluationTicket": {
    "operationId": "getEvaluationTicket",
    "tags": ["evaluations"],
    "summary": "State of a started evaluation",
    "description": "queued, running, succeeded, failed or interrupted (the server stopped first), with every requested model and the ids of its runs. Tickets are stored: they answer after a restart.",
    "parameters": [
      {"name": "ticket", "in": "path", "required": true, "description": "The ticket of POST /v1/evaluations.", "schema": {"type": "integer", "minimum": 1}, "example": 1}
    ],
    "responses": {
      "200": {
        "description": "The ticket.",
        "content": {"application/json": {
          "schema": {"$ref": "#/components/schemas/EvaluationTicket"},
          "example": {"ticket": 1, "dataset": "synthetic", "status": "succeeded", "created": "2026-11-25T09:30:00.000Z", "finished": "2026-11-25T09:30:02.500Z", "runs": [1], "models": [{"model": "preetham", "run": 1, "status": "succeeded"}]}
        }}
      },
      "400": {"description": "A ticket that is not a positive integer."},
      "404": {"description": "No such ticket (code unknown_ticket)."}
    }
  },
  "listJobs": {
    "operationId": "listJobs",
    "tags": ["jobs"],
    "summary": "Scheduled evaluations",
    "description": "Every job with its next run and the last result of each of its models.",
    "parameters": [
      {"$ref": "#/components/parameters/limit"},
      {"$ref": "#/components/parameters/cursor"}
    ],
    "responses": {
      "200": {
        "description": "The jobs.",
        "headers": {"Link": {"$ref": "#/components/headers/Link"}},
        "content": {"application/json": {"schema": {"$ref": "#/components/schemas/JobList"}}}
      },
      "400": {"description": "An unknown parameter."}
    }
  },
  "createJob": {
    "operationId": "createJob",
    "tags": ["jobs"],
    "summary": "Schedule an evaluation",
    "description": "A job evaluates models against a dataset on a 5-field cron schedule (UTC); its next run is computed from now.",
    "requestBody": {
      "required": true,
      "content": {"application/json": {
        "schema": {"$ref": "#/components/schemas/JobRequest"},
        "example": {"name": "nightly", "schedule": "0 3 * * *", "dataset": "synthetic", "models": ["preetham", "hosek"], "parameters": {"turbidity": 3}}
      }}
    },
    "responses": {
      "201": {
        "description": "Created: the job.",
        "headers": {"Location": {"description": "/v1/jobs/{id}", "required": true, "schema": {"type": "string"}}},
        "content": {"application/json": {"schema": {"$ref": "#/components/schemas/Job"}}}
      },
      "400": {"description": "A body that is not a JSON object, an unknown member, no name or schedule, an invalid schedule, model list or parameter."},
      "404": {"description": "No such dataset or model, or no stored fit matches parameters.fit (unknown_fit)."},
      "409": {"description": "A job of that name exists (code conflict), or parameters.fit names a fit that is not succeeded (fit_not_succeeded) or of a model not requested (fit_model_mismatch; parameter fit)."},
      "422": {"description": "A broadband irradiance dataset with a model named that has no broadband answer, Preetham or Hosek-Wilkie (broadband_unavailable, parameter models)."}
    }
  },
  "getJob": {
    "operationId": "getJob",
    "tags": ["jobs"],
    "summary": "One scheduled evaluation",
    "description": "A job with its next run and last results.",
    "responses": {
      "200": {
        "description": "The job.",
        "content": {"application/json": {"schema": {"$ref": "#/components/schemas/Job"}}}
      },
      "400": {"description": "An id that is not a positive integer."},
      "404": {"description": "No such job (code unknown_job)."}
    }
  },
  "deleteJob": {
    "operationId": "deleteJob",
    "tags": ["jobs"],
    "summary": "Delete a scheduled evaluation",
    "description": "Deletes the job; its runs stay.",
    "responses": {
      "200": {
        "description": "Deleted.",
        "content": {"application/json": {
          "schema": {"$ref": "#/components/schemas/JobDeleted"},
          "example": {"deleted": 1}
        }}
      },
      "400": {"description": "An id that is not a positive integer."},
      "404": {"description": "No such job (code unknown_job)."}
    }
  },
  "pauseJob": {
    "operationId": "pauseJob",
    "tags": ["jobs"],
    "summary": "Pause a scheduled evaluation",
    "description": "The scheduler skips a paused job until it is resumed. No body.",
    "responses": {
      "200": {
        "description": "The paused job.",
        "content": {"application/json": {"schema": {"$ref": "#/components/schemas/Job"}}}
      },
      "400": {"description": "An id that is not a positive integer."},
      "404": {"description": "No such job (code unknown_job)."}
    }
  },
  "resumeJob": {
    "operationId": "resumeJob",
    "tags": ["jobs"],
    "summary": "Resume a scheduled evaluation",
    "description": "Its next run is computed from now (a paused job does not catch up). No body.",
    "responses": {
      "200": {
        "description": "The resumed job.",
        "content": {"application/json": {"schema": {"$ref": "#/components/schemas/Job"}}}
      },
      "400": {"description": "An id that is not a positive integer."},
      "404": {"description": "No such job (code unknown_job)."}
    }
  }
})json");
  const Json job = parse(kJobExample);
  Json paused = job;
  paused["paused"] = true;
  ops["listJobs"]["responses"]["200"]["content"]["application/json"]["example"] =
      Json::array({job});
  ops["createJob"]["responses"]["201"]["content"]["application/json"]["example"] = job;
  ops["getJob"]["responses"]["200"]["content"]["application/json"]["example"] = job;
  ops["pauseJob"]["responses"]["200"]["content"]["application/json"]["example"] = paused;
  ops["resumeJob"]["responses"]["200"]["content"]["application/json"]["example"] = job;
  ops["getEvaluation"]["responses"]["200"]["content"]["application/json"]["example"] =
      parse(kRunExample);
  for (const char* id : {"getJob", "deleteJob", "pauseJob", "resumeJob"})
    ops[id]["parameters"] = Json::array({job_path_parameter()});
  return ops;
}

}  // namespace

Area evaluations_area() {
  Area area;
  area.components["schemas"] = schemas();
  area.operations = operations();
  complete_errors(area.operations);
  for (auto& [id, operation] : area.operations.items()) {
    operation["security"] = Json::array();
    const bool write = id == "createEvaluation" || id == "createJob" || id == "deleteJob" ||
                       id == "pauseJob" || id == "resumeJob";
    if (write) make_write(operation);
    const bool takes_body = id == "createEvaluation" || id == "createJob";
    add_common_errors(operation, takes_body);
    add_query_replica_answer(operation);
  }
  return area;
}

}  // namespace clearsky::api::openapi
