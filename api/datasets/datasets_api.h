// /v1/datasets, transport-free: list, show, delete and import stored measurement datasets
// (docs/data-api.md "Datasets"). The HTTP layer passes the path's dataset name and the query;
// the answers are JSON:
//   list:   [{"name", "format", "kind", "created", "captures", "samples",
//           "irradiance_samples"}], by name, paged (limit, cursor: api/paging/list_page.h); kind
//           sky_radiance or broadband_irradiance (docs/data-api.md "Dataset kinds")
//   show:   {"name", "format", "kind", "created", "captures": [{"label", "time" (ISO, site offset),
//            "time_utc", "place": {"latitude", "longitude", "elevation_m"}, "sun_zenith",
//            "sun_azimuth" (computed, SPA without refraction), "sun_azimuth_estimated" (or null),
//            "samples": N}]}; samples=true adds each capture's samples {"index", "view_zenith",
//            "view_azimuth" (degrees, clockwise from North), "flags"}, and capture=LABEL keeps one
//            capture and adds each sample's spectrum {"wavelengths_nm", "radiance"} (W/(m2.sr.nm)).
//           A broadband_irradiance dataset has no captures and its series instead:
//           "irradiance": [{"time", "time_utc", "place", "ghi", "dhi", "dni", "averaging_s"}]
//           by instant (W/m2, s; null where not measured).
//   import: the import report {"dataset", "added", "unchanged", "samples_added", "seconds"}
//           (over HTTP, imports run as background jobs: api/imports/).
// Errors are ApiError: 404 unknown dataset or capture, 400 bad parameter or archive content,
// 409 conflicting content. An import is one transaction: a failure leaves nothing behind.
// Thread-safety: each call uses the given Database from the calling thread only.
#pragma once

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "api/paging/list_page.h"
#include "storage/importers/kider_importer.h"
#include "storage/sqlite/database.h"

namespace clearsky::api {

// limit and cursor from the query (400 for other parameters).
ListPage list_datasets(storage::Database& db, Parameters query = Parameters("GET /v1/datasets"));

struct ShowDatasetOptions {
  bool samples = false;
  std::optional<std::string> capture;  // one capture by label, with spectra
};
nlohmann::ordered_json show_dataset(storage::Database& db, const std::string& name,
                                    const ShowDatasetOptions& options = {});

// 404 when absent; returns {"deleted": NAME}.
nlohmann::ordered_json delete_dataset(storage::Database& db, const std::string& name);

// What an import reads and under which rules: an archive (.7z, zip, tar: anything libarchive
// reads) or a folder of Kider .asd.rad.txt files; confine_to the import root a server-side path
// resolved in (import_roots.h; empty for an upload's spool file); the byte limits.
// shown_as names it in messages (a server-side path as requested, "upload" for an upload's spool
// file, so that messages do not show where the server keeps it; empty: the path itself).
struct ImportSource {
  std::filesystem::path archive_or_folder;
  std::filesystem::path confine_to;
  storage::ImportByteLimits limits;
  std::string shown_as;
  // The site and clock of an archive's captures (import_site_clock.h).
  storage::KiderImportOptions site_clock = {};
};
// Imports the source into the named dataset. format is kider (an archive or folder) or
// sky-radiance-csv / sky-radiance-json (one file of the open format, sky_radiance_import.h;
// 400 invalid_body naming the member) or irradiance-csv / irradiance-json (irradiance_import.h,
// whose report it returns). progress is called as
// storage::KiderImportRequest::progress (kider_importer.h). Refusals: 400 invalid_archive,
// 400 invalid_parameter (name), 409 conflict, 413 too_large naming max_entry_bytes or
// max_import_bytes, 507 insufficient_storage (SQLITE_FULL).
nlohmann::ordered_json import_dataset(
    storage::Database& db, const std::string& name, const std::string& format,
    const ImportSource& source,
    const std::function<void(const storage::ImportProgress&)>& progress = {});
// The import report of captures as JSON (the API's and `clearsky import --json`'s): kind
// sky_radiance, which tells it from a broadband irradiance import's (import_irradiance_samples).
nlohmann::ordered_json import_report_json(const storage::ImportReport& report);
// Checks the format before an import is queued (400 naming "format"; import_format.h).
void check_import_format(const std::string& format);
// Checks a new dataset's name (storage/repositories/dataset_name.h; 400 naming "name").
void check_dataset_name(const std::string& name);

}  // namespace clearsky::api
