// /v1/datasets handlers (datasets_api.h).
#include "api/datasets/datasets_api.h"

#include <cmath>

#include "api/datasets/import_format.h"
#include "api/datasets/irradiance_import.h"
#include "api/datasets/sky_radiance_import.h"
#include "api/encode/iso8601_time.h"
#include "api/error/api_error.h"
#include "models/core/numeric.h"
#include "storage/importers/import_conflict.h"
#include "storage/importers/kider_format.h"
#include "storage/importers/kider_importer.h"
#include "storage/repositories/capture_repository.h"
#include "storage/repositories/dataset_name.h"
#include "storage/repositories/dataset_repository.h"
#include "storage/repositories/irradiance_sample_repository.h"

namespace clearsky::api {
namespace {

nlohmann::ordered_json number_or_null(double value) {
  if (!std::isfinite(value)) return nullptr;
  return value;
}

storage::DatasetSummary find_dataset(storage::Database& db, const std::string& name) {
  auto dataset = storage::DatasetRepository(db).find(name);
  if (!dataset)
    throw ApiError(404, "unknown_dataset", "dataset", "dataset: no dataset named '" + name + "'");
  return *dataset;
}

nlohmann::ordered_json sample_json(const MeasuredSample& s, bool spectrum) {
  nlohmann::ordered_json j{{"index", s.index},
                           {"view_zenith", radians_to_degrees(s.view.zenith_rad)},
                           {"view_azimuth", radians_to_degrees(s.view.azimuth_rad)},
                           {"flags", s.quality_flags}};
  if (spectrum) {
    j["wavelengths_nm"] = s.radiance.wavelengths_nm();
    j["radiance"] = s.radiance.values();
  }
  return j;
}

nlohmann::ordered_json optional_json(const std::optional<double>& value) {
  if (!value) return nullptr;
  return *value;
}

// The series of a broadband irradiance dataset, by instant.
nlohmann::ordered_json irradiance_series_json(storage::Database& db, std::int64_t dataset_id) {
  nlohmann::ordered_json series = nlohmann::ordered_json::array();
  for (const storage::IrradianceSample& s :
       storage::IrradianceSampleRepository(db).list(dataset_id))
    series.push_back({{"time", format_iso8601_time(s.time_utc_s, s.utc_offset_minutes)},
                      {"time_utc", format_iso8601_time(s.time_utc_s, 0, true)},
                      {"place",
                       {{"latitude", s.latitude_deg},
                        {"longitude", s.longitude_deg},
                        {"elevation_m", s.elevation_m}}},
                      {"ghi", optional_json(s.ghi_w_m2)},
                      {"dhi", optional_json(s.dhi_w_m2)},
                      {"dni", optional_json(s.dni_w_m2)},
                      {"averaging_s", optional_json(s.averaging_s)}});
  return series;
}

}  // namespace

ListPage list_datasets(storage::Database& db, Parameters query) {
  const PageRequest request = parse_page_request(query);
  query.reject_unused();
  const auto datasets = storage::DatasetRepository(db).list_page(
      request.limit,
      request.cursor ? std::optional(name_from_cursor(*request.cursor)) : std::nullopt);
  ListPage page;
  page.limit = request.limit;
  for (const auto& d : datasets.rows)
    page.items.push_back({{"name", d.name},
                          {"format", d.format},
                          {"kind", d.kind},
                          {"created", d.created_utc},
                          {"captures", d.captures},
                          {"samples", d.samples},
                          {"irradiance_samples", d.irradiance_samples}});
  if (datasets.more) page.next_cursor = name_cursor(datasets.rows.back().name);
  return page;
}

nlohmann::ordered_json show_dataset(storage::Database& db, const std::string& name,
                                    const ShowDatasetOptions& options) {
  const storage::DatasetSummary dataset = find_dataset(db, name);
  if (dataset.kind == storage::kBroadbandIrradianceKind) {
    if (options.capture)
      throw ApiError(404, "unknown_capture", "capture",
                     "capture: dataset '" + name + "' is a broadband irradiance series");
    return {{"name", dataset.name},
            {"format", dataset.format},
            {"kind", dataset.kind},
            {"created", dataset.created_utc},
            {"captures", nlohmann::ordered_json::array()},
            {"irradiance", irradiance_series_json(db, dataset.id)}};
  }
  nlohmann::ordered_json captures = nlohmann::ordered_json::array();
  bool found = false;
  for (const storage::StoredCapture& stored : storage::CaptureRepository(db).load(dataset.id)) {
    const MeasuredCapture& c = stored.capture;
    if (options.capture && c.label != *options.capture) continue;
    found = true;
    nlohmann::ordered_json j{{"label", c.label},
                             {"time", format_iso8601_time(c.unix_time_utc_s, c.utc_offset_minutes)},
                             {"time_utc", format_iso8601_time(c.unix_time_utc_s, 0, true)},
                             {"place",
                              {{"latitude", c.site.latitude_deg},
                               {"longitude", c.site.longitude_deg},
                               {"elevation_m", c.site.elevation_m}}},
                             {"sun_zenith", number_or_null(c.sun_zenith_computed_deg)},
                             {"sun_azimuth", number_or_null(c.sun_azimuth_computed_deg)},
                             {"sun_azimuth_estimated", number_or_null(c.sun_azimuth_estimated_deg)},
                             {"samples", c.samples.size()}};
    if (options.samples || options.capture) {
      nlohmann::ordered_json samples = nlohmann::ordered_json::array();
      for (const MeasuredSample& s : c.samples)
        samples.push_back(sample_json(s, options.capture.has_value()));
      j["samples"] = std::move(samples);
    }
    captures.push_back(std::move(j));
  }
  if (options.capture && !found)
    throw ApiError(404, "unknown_capture", "capture",
                   "capture: dataset '" + name + "' has no capture '" + *options.capture + "'");
  return {{"name", dataset.name},
          {"format", dataset.format},
          {"kind", dataset.kind},
          {"created", dataset.created_utc},
          {"captures", std::move(captures)}};
}

nlohmann::ordered_json delete_dataset(storage::Database& db, const std::string& name) {
  if (!storage::DatasetRepository(db).remove(name))
    throw ApiError(404, "unknown_dataset", "dataset", "dataset: no dataset named '" + name + "'");
  return {{"deleted", name}};
}

void check_import_format(const std::string& format) {
  if (format != kKiderImportFormat && !is_sky_radiance_format(format) &&
      !is_irradiance_format(format))
    throw invalid_parameter("format", "'" + format +
                                          "' is not an import format (known: kider, "
                                          "sky-radiance-csv, sky-radiance-json, irradiance-csv, "
                                          "irradiance-json)");
}

void check_dataset_name(const std::string& name) {
  if (name.empty()) throw missing_parameter("name", "the dataset to import into");
  if (!storage::is_valid_dataset_name(name))
    throw invalid_parameter("name", "a dataset name is " + std::string(storage::kDatasetNameRule));
}

nlohmann::ordered_json import_report_json(const storage::ImportReport& report) {
  return {{"dataset", report.dataset},
          {"kind", storage::kSkyRadianceKind},
          {"added", report.added},
          {"unchanged", report.unchanged},
          {"samples_added", report.samples_added},
          {"seconds", report.seconds}};
}

nlohmann::ordered_json import_dataset(
    storage::Database& db, const std::string& name, const std::string& format,
    const ImportSource& source,
    const std::function<void(const storage::ImportProgress&)>& progress) {
  check_import_format(format);
  check_dataset_name(name);
  const std::string shown_as =
      source.shown_as.empty() ? source.archive_or_folder.string() : source.shown_as;
  if (is_irradiance_format(format)) {
    try {
      return import_irradiance_samples(
          db, name, kIrradianceDatasetFormat,
          read_irradiance_file(source.archive_or_folder, format, source.limits, shown_as));
    } catch (const storage::SqliteError& e) {
      if (e.disk_full()) throw insufficient_storage("writing the database");
      throw;
    }
  }
  if (is_sky_radiance_format(format)) {
    try {
      return import_report_json(import_sky_radiance(db, name, source.archive_or_folder, format,
                                                    source.limits, shown_as, progress));
    } catch (const storage::ImportConflict& e) {
      throw ApiError(409, "conflict", "", e.what());
    } catch (const storage::SqliteError& e) {
      if (e.disk_full()) throw insufficient_storage("writing the database");
      throw;
    }
  }
  storage::KiderImportRequest request;
  request.dataset_name = name;
  request.paths = {source.archive_or_folder};
  request.confine_to = source.confine_to;
  request.limits = source.limits;
  if (!source.shown_as.empty()) request.path_names = {source.shown_as};
  request.progress = progress;
  request.options = source.site_clock;
  storage::ImportReport report;
  try {
    report = storage::import_kider(db, request);
  } catch (const storage::ImportConflict& e) {
    // A label already held with other content, or the dataset's format differs.
    throw ApiError(409, "conflict", "", e.what());
  } catch (const storage::ImportLimitExceeded& e) {
    throw ApiError(413, "too_large", e.limit(), e.what());
  } catch (const storage::SqliteError& e) {
    if (e.disk_full()) throw insufficient_storage("writing the database");
    throw;
  } catch (const storage::InvalidDatasetName& e) {
    throw invalid_parameter("name", e.what());
  } catch (const std::invalid_argument& e) {
    // An incomplete or mixed-up capture, no files.
    throw ApiError(400, "invalid_archive", "", e.what());
  } catch (const std::runtime_error& e) {
    // KiderFormatError, or an archive libarchive cannot read.
    throw ApiError(400, "invalid_archive", "", e.what());
  }
  return import_report_json(report);
}

}  // namespace clearsky::api
