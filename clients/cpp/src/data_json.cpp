// The data endpoints' JSON (data_json.h).
#include "data_json.h"

#include "json_fields.h"

namespace clearsky::client::detail {

namespace {

// "all" for no model named (docs/data-api.md "Evaluations").
nlohmann::json models_json(const std::vector<std::string>& models) {
  if (models.empty()) return "all";
  return models;
}

std::vector<std::string> models_of(const nlohmann::json& json) {
  const nlohmann::json models = member<nlohmann::json>(json, "models");
  if (models.is_string()) return {};
  return models.get<std::vector<std::string>>();
}

CaptureSample capture_sample_of(const nlohmann::json& json) {
  CaptureSample sample;
  sample.index = member<std::int64_t>(json, "index");
  sample.view = {member<double>(json, "view_zenith"), member<double>(json, "view_azimuth")};
  sample.flags = member<std::int64_t>(json, "flags");
  sample.wavelengths_nm =
      optional_member<std::vector<double>>(json, "wavelengths_nm").value_or(std::vector<double>{});
  sample.radiance_w_m2_sr_nm =
      optional_member<std::vector<double>>(json, "radiance").value_or(std::vector<double>{});
  return sample;
}

Capture capture_of(const nlohmann::json& json) {
  Capture capture;
  capture.label = member<std::string>(json, "label");
  capture.time = member<std::string>(json, "time");
  capture.time_utc = member<std::string>(json, "time_utc");
  const nlohmann::json place = member<nlohmann::json>(json, "place");
  capture.place = {member<double>(place, "latitude"), member<double>(place, "longitude"),
                   member<double>(place, "elevation_m")};
  capture.sun_zenith_deg = optional_member<double>(json, "sun_zenith");
  capture.sun_azimuth_deg = optional_member<double>(json, "sun_azimuth");
  capture.sun_azimuth_estimated_deg = optional_member<double>(json, "sun_azimuth_estimated");
  // samples: a count, or the samples themselves.
  const nlohmann::json samples = member<nlohmann::json>(json, "samples");
  if (samples.is_array()) {
    for (const nlohmann::json& s : samples) capture.samples.push_back(capture_sample_of(s));
    capture.sample_count = static_cast<std::int64_t>(capture.samples.size());
  } else {
    capture.sample_count = member<std::int64_t>(json, "samples");
  }
  return capture;
}

}  // namespace

nlohmann::json evaluation_request_json(const EvaluationRequest& request) {
  return {{"dataset", request.dataset},
          {"models", models_json(request.models)},
          {"parameters", parameters_json(request.parameters)}};
}

nlohmann::json fit_request_json(const FitRequest& request) {
  nlohmann::json body = {{"dataset", request.dataset},
                         {"model", request.model},
                         {"parameters", parameters_json(request.parameters)},
                         {"per_capture", request.per_capture},
                         {"cross_validate", request.cross_validate}};
  if (!request.free.empty()) body["free"] = request.free;
  if (!request.bounds.empty()) {
    nlohmann::json bounds = nlohmann::json::object();
    for (const auto& [name, range] : request.bounds) bounds[name] = {range[0], range[1]};
    body["bounds"] = std::move(bounds);
  }
  if (!request.captures.empty()) body["captures"] = request.captures;
  if (request.max_evaluations) body["max_evaluations"] = *request.max_evaluations;
  return body;
}

nlohmann::json job_request_json(const JobRequest& request) {
  return {{"name", request.name},
          {"schedule", request.schedule},
          {"dataset", request.dataset},
          {"models", models_json(request.models)},
          {"parameters", parameters_json(request.parameters)}};
}

DatasetSummary dataset_summary_of(const nlohmann::json& json) {
  DatasetSummary summary;
  summary.name = member<std::string>(json, "name");
  summary.format = member<std::string>(json, "format");
  summary.created = member<std::string>(json, "created");
  summary.captures = member<std::int64_t>(json, "captures");
  summary.samples = member<std::int64_t>(json, "samples");
  return summary;
}

Dataset dataset_of(const nlohmann::json& json) {
  Dataset dataset;
  dataset.name = member<std::string>(json, "name");
  dataset.format = member<std::string>(json, "format");
  dataset.created = member<std::string>(json, "created");
  for (const nlohmann::json& c : member<nlohmann::json>(json, "captures"))
    dataset.captures.push_back(capture_of(c));
  return dataset;
}

ImportState import_state_of(const nlohmann::json& json) {
  ImportState state;
  state.id = member<std::int64_t>(json, "id");
  state.dataset = member<std::string>(json, "dataset");
  state.format = member<std::string>(json, "format");
  state.source = member<std::string>(json, "source");
  state.path = optional_member<std::string>(json, "path");
  state.upload_bytes = optional_member<std::int64_t>(json, "upload_bytes");
  state.status = member<std::string>(json, "status");
  // A queued import has no progress yet (null).
  if (const auto progress = optional_member<nlohmann::json>(json, "progress")) {
    state.progress.phase = member<std::string>(*progress, "phase");
    state.progress.bytes_read = member<std::int64_t>(*progress, "bytes_read");
    state.progress.bytes_total = optional_member<std::int64_t>(*progress, "bytes_total");
    state.progress.entries_read = member<std::int64_t>(*progress, "entries_read");
    state.progress.entries_total = optional_member<std::int64_t>(*progress, "entries_total");
    state.progress.files_read = member<std::int64_t>(*progress, "files_read");
    state.progress.captures_added = member<std::int64_t>(*progress, "captures_added");
    state.progress.samples_added = member<std::int64_t>(*progress, "samples_added");
  }
  if (const auto report = optional_member<nlohmann::json>(json, "report")) {
    ImportReport r;
    r.dataset = member<std::string>(*report, "dataset");
    r.added = member<std::vector<std::string>>(*report, "added");
    r.unchanged = member<std::vector<std::string>>(*report, "unchanged");
    r.samples_added = member<std::int64_t>(*report, "samples_added");
    r.seconds = member<double>(*report, "seconds");
    state.report = std::move(r);
  }
  if (const auto error = optional_member<nlohmann::json>(json, "error"))
    state.error =
        ImportFailure{member<std::string>(*error, "code"), member<std::string>(*error, "message")};
  state.location = member<std::string>(json, "location");
  return state;
}

EvaluationTicket ticket_of(const nlohmann::json& json) {
  EvaluationTicket ticket;
  ticket.ticket = member<std::int64_t>(json, "ticket");
  ticket.dataset = member<std::string>(json, "dataset");
  ticket.status = member<std::string>(json, "status");
  ticket.created = member<std::string>(json, "created");
  ticket.finished = optional_member<std::string>(json, "finished");
  ticket.runs = member<std::vector<std::int64_t>>(json, "runs");
  for (const nlohmann::json& m : member<nlohmann::json>(json, "models")) {
    ticket.models.push_back(
        {member<std::string>(m, "model"), optional_member<std::int64_t>(m, "run"),
         member<std::string>(m, "status"), optional_member<std::string>(m, "error")});
  }
  ticket.error = optional_member<std::string>(json, "error");
  return ticket;
}

namespace {

// The run's RMSE in the member its unit names: rmse_unit W/m2 (a broadband irradiance dataset)
// or mW/(m2.sr.nm) (captures, and servers that predate rmse_unit).
void set_rmse(const nlohmann::json& json, std::optional<double>& mw_m2_sr_nm,
              std::optional<double>& w_m2) {
  const auto unit = optional_member<std::string>(json, "rmse_unit");
  (unit && *unit == "W/m2" ? w_m2 : mw_m2_sr_nm) = optional_member<double>(json, "rmse");
}

std::vector<IrradianceComponentResult> irradiance_components_of(const nlohmann::json& json) {
  std::vector<IrradianceComponentResult> out;
  if (!json.contains("irradiance_components")) return out;
  for (const nlohmann::json& c : member<nlohmann::json>(json, "irradiance_components")) {
    IrradianceComponentResult r;
    r.component = member<std::string>(c, "component");
    r.rmse_w_m2 = optional_member<double>(c, "rmse_w_m2");
    r.mean_bias_w_m2 = optional_member<double>(c, "mean_bias_w_m2");
    r.samples_compared = member<std::int64_t>(c, "samples_compared");
    if (c.contains("errors_w_m2"))
      for (const nlohmann::json& e : c["errors_w_m2"])
        r.errors_w_m2.push_back(e.is_number() ? std::optional(e.get<double>()) : std::nullopt);
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace

EvaluationSummary evaluation_summary_of(const nlohmann::json& json) {
  EvaluationSummary summary;
  summary.id = member<std::int64_t>(json, "id");
  summary.dataset = optional_member<std::string>(json, "dataset").value_or("");
  summary.model = member<std::string>(json, "model");
  summary.status = member<std::string>(json, "status");
  summary.started = member<std::string>(json, "started");
  summary.finished = optional_member<std::string>(json, "finished");
  set_rmse(json, summary.rmse_mw_m2_sr_nm, summary.rmse_w_m2);
  summary.samples_compared = optional_member<std::int64_t>(json, "samples_compared");
  summary.irradiance_components = irradiance_components_of(json);
  summary.job = optional_member<std::int64_t>(json, "job");
  return summary;
}

Evaluation evaluation_of(const nlohmann::json& json) {
  Evaluation run;
  run.id = member<std::int64_t>(json, "id");
  run.dataset = optional_member<std::string>(json, "dataset");
  run.model = member<std::string>(json, "model");
  run.model_version = member<std::string>(json, "model_version");
  run.parameters = parameters_of(member<nlohmann::json>(json, "parameters"));
  run.software_version = member<std::string>(json, "software_version");
  run.wavelength_range_nm = member<std::vector<double>>(json, "wavelength_range_nm");
  run.job = optional_member<std::int64_t>(json, "job");
  run.status = member<std::string>(json, "status");
  run.error = optional_member<std::string>(json, "error");
  run.started = member<std::string>(json, "started");
  run.finished = optional_member<std::string>(json, "finished");
  set_rmse(json, run.rmse_mw_m2_sr_nm, run.rmse_w_m2);
  run.irradiance_components = irradiance_components_of(json);
  run.out_of_domain = member<std::string>(json, "out_of_domain");
  run.samples_compared = optional_member<std::int64_t>(json, "samples_compared");
  run.samples_excluded = optional_member<std::int64_t>(json, "samples_excluded");
  run.samples_clamped = optional_member<std::int64_t>(json, "samples_clamped");
  run.processing_steps = member<std::vector<std::string>>(json, "processing_steps");
  for (const nlohmann::json& c : member<nlohmann::json>(json, "captures")) {
    EvaluationCapture capture;
    capture.label = member<std::string>(c, "label");
    capture.time = member<std::string>(c, "time");
    capture.sun_zenith_deg = member<double>(c, "sun_zenith");
    capture.sun_azimuth_deg = member<double>(c, "sun_azimuth");
    capture.rmse_mw_m2_sr_nm = optional_member<double>(c, "rmse");
    capture.values_compared = member<std::int64_t>(c, "values_compared");
    capture.samples_compared = optional_member<std::int64_t>(c, "samples_compared");
    run.captures.push_back(std::move(capture));
  }
  run.timings = json.value("timings", nlohmann::json::object());
  run.history = json.value("history", nlohmann::json::object());
  return run;
}

Job job_of(const nlohmann::json& json) {
  Job job;
  job.id = member<std::int64_t>(json, "id");
  job.name = member<std::string>(json, "name");
  job.schedule = member<std::string>(json, "schedule");
  job.dataset = member<std::string>(json, "dataset");
  job.models = models_of(json);
  job.parameters = parameters_of(member<nlohmann::json>(json, "parameters"));
  job.paused = member<bool>(json, "paused");
  job.created = member<std::string>(json, "created");
  job.last_run = optional_member<std::string>(json, "last_run");
  job.next_run = optional_member<std::string>(json, "next_run");
  for (const nlohmann::json& r : member<nlohmann::json>(json, "last_result")) {
    job.last_result.push_back({member<std::int64_t>(r, "run"), member<std::string>(r, "model"),
                               member<std::string>(r, "status"), member<std::string>(r, "started"),
                               optional_member<double>(r, "rmse")});
  }
  return job;
}

Fit fit_of(const nlohmann::json& json) {
  Fit fit;
  fit.id = member<std::int64_t>(json, "id");
  fit.dataset = member<std::string>(json, "dataset");
  fit.model = member<std::string>(json, "model");
  fit.status = member<std::string>(json, "status");
  fit.progress = member<double>(json, "progress");
  fit.stage = optional_member<std::string>(json, "stage");
  if (const auto values = optional_member<nlohmann::json>(json, "values")) {
    for (const auto& [name, value] : values->items())
      if (value.is_number()) fit.values[name] = value.get<double>();
  }
  fit.rmse_before = optional_member<double>(json, "rmse_before");
  fit.rmse_after = optional_member<double>(json, "rmse_after");
  fit.cross_validated_rmse = optional_member<double>(json, "cross_validated_rmse");
  fit.created = member<std::string>(json, "created_utc");
  fit.finished = optional_member<std::string>(json, "finished_utc");
  fit.error = optional_member<std::string>(json, "error");
  return fit;
}

AerosolInversion aerosol_inversion_of(const nlohmann::json& json) {
  AerosolInversion a;
  a.id = member<std::int64_t>(json, "id");
  a.name = member<std::string>(json, "name");
  a.content_hash = member<std::string>(json, "content_hash");
  a.site = member<std::string>(json, "site");
  a.first_day = member<std::string>(json, "first_day");
  a.last_day = member<std::string>(json, "last_day");
  a.retrieval_count = member<std::int64_t>(json, "retrieval_count");
  a.created = member<std::string>(json, "created_utc");
  if (const auto wavelengths = optional_member<std::vector<double>>(json, "wavelengths_nm"))
    a.wavelengths_nm = *wavelengths;
  if (const auto retrievals = optional_member<nlohmann::json>(json, "retrievals")) {
    for (const nlohmann::json& r : *retrievals) {
      AerosolRetrieval one;
      one.date = member<std::string>(r, "date");
      one.time_utc = member<std::string>(r, "time_utc");
      one.time_utc_h = member<double>(r, "time_utc_h");
      one.aod_440 = member<double>(r, "aod_440");
      one.angstrom_440_870 = member<double>(r, "angstrom_440_870");
      one.aod = member<std::vector<double>>(r, "aod");
      a.retrievals.push_back(std::move(one));
    }
  }
  return a;
}

}  // namespace clearsky::client::detail
