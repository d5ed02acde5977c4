// /v1/datasets in the route table (route_handlers.h): list, show, delete, and the import of
// an uploaded archive (or a server-side path) as a background job.
#include <memory>
#include <optional>

#include "api/datasets/datasets_api.h"
#include "api/datasets/import_format.h"
#include "api/datasets/import_site_clock.h"
#include "api/datasets/irradiance_import.h"
#include "api/datasets/sky_radiance_import.h"
#include "api/datasets/upload_spool.h"
#include "api/error/api_error.h"
#include "api/imports/imports_api.h"
#include "api/paging/list_page.h"
#include "api/routes/data_access.h"
#include "api/routes/route_handlers.h"
#include "storage/importers/kider_reader.h"

namespace clearsky::api {

namespace {

// The uploaded body spooled to disk as it arrives, under the upload limit.
std::unique_ptr<UploadSpool> spool_body(const ApiRequest& request, const DataServices& data) {
  auto spool = std::make_unique<UploadSpool>(data.upload_dir, data.upload_max_bytes);
  if (request.body_reader == nullptr) {
    spool->append(request.body);
    return spool;
  }
  std::exception_ptr failure;
  request.body_reader->read([&](std::string_view piece) {
    try {
      spool->append(piece);
      return true;
    } catch (...) {
      failure = std::current_exception();
      return false;
    }
  });
  if (failure) std::rethrow_exception(failure);
  return spool;
}

}  // namespace

// A page of the list (api/paging/list_page.h), the next one in the Link header.
ApiResponse list_datasets_route(const ApiContext& context, const ApiRequest& request) {
  Parameters query = query_parameters(request);
  storage::Database db = open_database(context);
  return list_page_response(request, list_datasets(db, std::move(query)));
}

ApiResponse get_dataset_route(const ApiContext& context, const ApiRequest& request) {
  Parameters p = query_parameters(request);
  ShowDatasetOptions options;
  options.samples = p.boolean_or("samples", false);
  options.capture = p.text("capture");
  p.reject_unused();
  storage::Database db = open_database(context);
  return ordered_json_response(show_dataset(db, request.path_parameter("name"), options));
}

ApiResponse delete_dataset_route(const ApiContext& context, const ApiRequest& request) {
  query_parameters(request).reject_unused();
  storage::Database db = open_database(context);
  return ordered_json_response(delete_dataset(db, request.path_parameter("name")));
}

// The body is the archive or a file of the open sky-radiance format (its format from format=
// or the media type, api/datasets/import_format.h); or no body and path=SERVER_PATH (an archive
// or folder under one of the operator's import roots, api/datasets/import_roots.h). Checked
// here (parameters, name, format, path, size, and an upload's content), then imported on the
// ImportPool: 202 with the import's state and its Location.
ApiResponse import_dataset_route(const ApiContext& context, const ApiRequest& request) {
  const DataServices& data = data_services(context);
  Parameters p = query_parameters(request);
  storage::NewImport what;
  what.dataset = p.text("name").value_or("");
  const std::optional<std::string> format = p.text("format");
  const std::optional<std::string> path = p.text("path");
  // A path import has no body, hence no media type of its own.
  what.format = import_format_of(format, path ? std::nullopt : request.header("Content-Type"));
  const bool irradiance = is_irradiance_format(what.format);
  // The open formats' files (sky radiance or broadband irradiance).
  const bool open_format = is_sky_radiance_format(what.format) || irradiance;
  if (open_format) {
    // The open formats carry each row's site and clock themselves.
    for (const char* name : {"lat", "lon", "elevation", "utc_offset"})
      if (p.has(name))
        throw invalid_parameter(name, "only for kider archives: the " + what.format +
                                          " format gives each capture's site and time");
    if (path)
      throw invalid_parameter("path", "path imports read kider archives and folders; upload a " +
                                          what.format + " file as the body");
  }
  const storage::KiderImportOptions site_clock = parse_import_site_clock(p);
  p.reject_unused();
  check_dataset_name(what.dataset);
  // Refused before a body is spooled: a path import takes none.
  std::optional<ResolvedImportPath> resolved;
  if (path) resolved = data.import_roots.resolve(*path);
  std::unique_ptr<UploadSpool> spool = spool_body(request, data);
  std::filesystem::path source;
  std::filesystem::path confine_to;
  if (resolved) {
    if (spool->size_bytes() > 0) throw conflicting_parameters("path", "an uploaded body");
    spool.reset();
    what.source = "path";
    what.path = *path;
    source = resolved->path;
    confine_to = resolved->root;
  } else {
    if (spool->size_bytes() == 0)
      throw missing_parameter("body", open_format ? "the " + what.format + " file"
                                                  : "the archive (.7z, zip or tar), or path=");
    what.source = "upload";
    what.upload_bytes = static_cast<std::int64_t>(spool->size_bytes());
    source = spool->finish();
  }
  if (data.imports == nullptr)
    throw ApiError(503, "imports_unavailable", "", "this server runs no import workers");
  // An upload is checked whole before it is accepted: the open format's every value, an
  // archive's format from its first entry (a CSV sent as an archive is refused here, not by
  // a failed import). The messages name the body, never the spool file.
  if (!resolved) {
    if (irradiance) {
      read_irradiance_file(source, what.format, data.imports->limits(), "body");
    } else if (open_format) {
      read_sky_radiance_file(source, what.format, data.imports->limits(), "body");
    } else {
      try {
        storage::check_readable_archive(source, "body");
      } catch (const std::runtime_error& e) {
        throw ApiError(400, "invalid_archive", "body", e.what());
      }
    }
  }
  storage::Database db = open_database(context);
  const std::int64_t id =
      data.imports->submit(db, what, source, std::move(spool), confine_to, site_clock);
  ApiResponse response = ordered_json_response(show_import(db, data.imports, id), 202);
  response.headers.emplace_back("Location", import_location(id));
  return response;
}

}  // namespace clearsky::api
