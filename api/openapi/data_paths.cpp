// OpenAPI paths of /v1/datasets, /v1/imports, /v1/evaluations and /v1/jobs (data_paths.h).
#include "api/openapi/data_paths.h"

#include <string>

namespace clearsky::api {
namespace {

using nlohmann::json;

json ok(const std::string& description) {
  return {{"description", description},
          {"content", {{"application/json", {{"schema", {{"type", "object"}}}}}}}};
}

json error(const std::string& description) {
  return {
      {"description", description},
      {"content", {{"application/json", {{"schema", {{"$ref", "#/components/schemas/Error"}}}}}}}};
}

json query(const std::string& name, const std::string& type, const std::string& description,
           bool required = false) {
  return {{"name", name},
          {"in", "query"},
          {"required", required},
          {"description", description},
          {"schema", {{"type", type}}}};
}

json in_path(const std::string& name, const std::string& description) {
  return {{"name", name},
          {"in", "path"},
          {"required", true},
          {"description", description},
          {"schema", {{"type", "string"}}}};
}

const json kBearer = json::array({{{"bearer", json::array()}}});

json write(json operation) {
  operation["security"] = kBearer;
  operation["responses"]["401"] = error("Missing or wrong bearer token");
  operation["responses"]["403"] = error("Writes are disabled (no token configured)");
  return operation;
}

json json_body(const std::string& description) {
  return {{"required", true},
          {"description", description},
          {"content", {{"application/json", {{"schema", {{"type", "object"}}}}}}}};
}

}  // namespace

void add_data_paths(json& paths) {
  paths["/v1/datasets"]["get"] = {
      {"summary", "Stored measurement datasets with capture and sample counts"},
      {"responses", {{"200", ok("[{name, format, created, captures, samples}]")}}}};
  paths["/v1/datasets"]["post"] = write(
      {{"summary",
        "Import Kider captures into a dataset as a background job: the body is a .7z, zip or "
        "tar archive of .asd.rad.txt files or of such .7z files (streamed to disk under the "
        "upload limit, max-upload-bytes), or path= names an archive or folder on the server. "
        "202 with the import's state; follow Location (/v1/imports/{id}). The import is one "
        "transaction: a failure leaves nothing behind"},
       {"parameters",
        json::array({query("name", "string", "Dataset name", true),
                     query("format", "string", "kider (default)"),
                     query("path", "string", "Server-side archive or folder (no body)")})},
       {"requestBody",
        {{"required", false},
         {"content",
          {{"application/octet-stream",
            {{"schema", {{"type", "string"}, {"format", "binary"}}}}}}}}},
       {"responses",
        {{"202",
          {{"description", "Queued: the import's state (as GET /v1/imports/{id})"},
           {"headers",
            {{"Location",
              {{"description", "/v1/imports/{id}"}, {"schema", {{"type", "string"}}}}}}},
           {"content", {{"application/json", {{"schema", {{"type", "object"}}}}}}}}},
         {"400", error("Bad parameter, unknown format, no body and no path, or no such path")},
         {"413", error("Body above the upload limit")},
         {"503", error("Too many imports queued")}}}});
  paths["/v1/imports"]["get"] = {
      {"summary", "Dataset imports, newest first (state, progress, timings, report or error)"},
      {"parameters", json::array({query("status", "string", "queued, running, succeeded or failed"),
                                  query("dataset", "string", "Imports into this dataset")})},
      {"responses", {{"200", ok("[import]")}}}};
  paths["/v1/imports/{id}"]["get"] = {
      {"summary",
       "One import: {id, dataset, format, source, path, upload_bytes, status, progress: "
       "{phase, bytes_read, bytes_total, entries_read, entries_total, files_read, "
       "captures_added, samples_added}, timings: {created, started, finished}, report, "
       "error: {code, message}, location}; an import a crash interrupted is failed with code "
       "interrupted. Failures of the import itself: invalid_archive (not Kider content), "
       "conflict (a label held with other content)"},
      {"parameters", json::array({in_path("id", "Import id")})},
      {"responses",
       {{"200", ok("{id, dataset, status, progress, timings, report, error, ...}")},
        {"404", error("Unknown import")}}}};
  paths["/v1/datasets/{name}"]["get"] = {
      {"summary",
       "A dataset's captures: time, place, sun angles used; samples=true adds sample "
       "directions, capture=LABEL one capture with spectra"},
      {"parameters",
       json::array({in_path("name", "Dataset name"), query("samples", "boolean", "Include samples"),
                    query("capture", "string", "One capture by label, with spectra")})},
      {"responses",
       {{"200", ok("{name, format, created, captures: [...]}")},
        {"404", error("Unknown dataset or capture")}}}};
  paths["/v1/datasets/{name}"]["delete"] =
      write({{"summary", "Delete a dataset with its captures and evaluation runs"},
             {"parameters", json::array({in_path("name", "Dataset name")})},
             {"responses", {{"200", ok("{deleted}")}, {"404", error("Unknown dataset")}}}});

  paths["/v1/evaluations"]["get"] = {
      {"summary", "Stored evaluation runs, newest first"},
      {"parameters",
       json::array({query("model", "string", "Model id"), query("dataset", "string", "Dataset"),
                    query("since", "string", "Started at or after (ISO 8601)"),
                    query("until", "string", "Started before (ISO 8601)"),
                    query("status", "string", "running, succeeded or failed"),
                    query("job", "integer", "Runs of a scheduled job")})},
      {"responses", {{"200", ok("[{id, dataset, model, status, started, finished, rmse, job}]")}}}};
  paths["/v1/evaluations"]["post"] = write(
      {{"summary",
        "Start an evaluation of models against a dataset on the background evaluation workers"},
       {"requestBody", json_body("{models: [ids] or \"all\", dataset, parameters: {turbidity, "
                                 "alpha, beta, g, albedo, ... and options of the requested "
                                 "models, each applied to the models that list it, e.g. "
                                 "study_viewer_sample, scattering_orders, clamp_negative_fit}}")},
       {"responses",
        {{"202", ok("{ticket, status, runs, location}")},
         {"404", error("Unknown dataset or model")},
         {"503", error("The evaluation queue is full")}}}});
  json samples = query("samples", "string",
                       "true: each capture adds \"samples\": [{index, view_zenith, view_azimuth, "
                       "rmse, bias}] (degrees, azimuth clockwise from North; RMSE over the run's "
                       "wavelengths and bias = mean of model - measured, mW/(m2.sr.nm)); "
                       "spectra: each sample also adds \"errors\" (model - measured at each of "
                       "the run's \"wavelengths_nm\", added after wavelength_range_nm); false "
                       "(default): neither. For runs stored before per-sample errors were kept, "
                       "\"samples\" and \"wavelengths_nm\" are null");
  samples["schema"]["enum"] = json::array({"false", "true", "spectra"});
  paths["/v1/evaluations/{id}"]["get"] = {
      {"summary",
       "One run: total and per-capture RMSE (mW/(m2.sr.nm)), per-sample errors on request, "
       "timings, parameters, software version, and whether the RMSE changed against the last "
       "run with the same model and parameters"},
      {"parameters", json::array({in_path("id", "Run id"), samples,
                                  query("capture", "string", "Only the capture with this label")})},
      {"responses",
       {{"200", ok("Run: {id, dataset, model, ..., wavelength_range_nm, [wavelengths_nm], "
                   "rmse, timings, captures: [{label, time, sun_zenith, sun_azimuth, rmse, "
                   "values_compared, [samples]}], history}")},
        {"400", error("Unknown parameter or samples value")},
        {"404", error("Unknown run, or no capture of that label in the run")}}}};
  paths["/v1/evaluations/tickets/{ticket}"]["get"] = {
      {"summary", "State of a started evaluation: queued, running, succeeded or failed, run ids"},
      {"parameters", json::array({in_path("ticket", "Ticket from POST /v1/evaluations")})},
      {"responses",
       {{"200", ok("{ticket, status, runs, error}")}, {"404", error("Unknown ticket")}}}};

  paths["/v1/jobs"]["get"] = {
      {"summary", "Scheduled evaluations with their next run time and last result"},
      {"responses", {{"200", ok("[job]")}}}};
  paths["/v1/jobs"]["post"] =
      write({{"summary", "Schedule an evaluation (5-field cron schedule, UTC)"},
             {"requestBody",
              json_body("{name, schedule, dataset, models: [ids] or \"all\", parameters}")},
             {"responses", {{"201", ok("job")}, {"409", error("Name taken")}}}});
  paths["/v1/jobs/{id}"]["get"] = {
      {"summary", "One scheduled evaluation"},
      {"parameters", json::array({in_path("id", "Job id")})},
      {"responses", {{"200", ok("job")}, {"404", error("Unknown job")}}}};
  paths["/v1/jobs/{id}"]["delete"] =
      write({{"summary", "Delete a scheduled evaluation (its runs stay)"},
             {"parameters", json::array({in_path("id", "Job id")})},
             {"responses", {{"200", ok("{deleted}")}, {"404", error("Unknown job")}}}});
  paths["/v1/jobs/{id}/pause"]["post"] =
      write({{"summary", "Pause a scheduled evaluation"},
             {"parameters", json::array({in_path("id", "Job id")})},
             {"responses", {{"200", ok("job")}, {"404", error("Unknown job")}}}});
  paths["/v1/jobs/{id}/resume"]["post"] =
      write({{"summary", "Resume a scheduled evaluation; its next run is computed from now"},
             {"parameters", json::array({in_path("id", "Job id")})},
             {"responses", {{"200", ok("job")}, {"404", error("Unknown job")}}}});
}

}  // namespace clearsky::api
