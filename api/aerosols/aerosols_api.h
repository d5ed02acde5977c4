// Users' AERONET phase-function inversions over HTTP (docs/data-api.md "Aerosol inversions"):
// POST /v1/aerosols stores an uploaded file after the reader of models/aeronet has accepted it
// whole, GET /v1/aerosols lists them (paged, newest first; api/paging/list_page.h) and
// GET /v1/aerosols/{id} describes one (site, days, wavelengths, every retrieval with its time and
// aerosol optical depth per wavelength). The `aerosols` parameter of the sky endpoints and of
// evaluations and fits (models/measured_aerosols) loads a stored file by id.
//
// | parameter | unit | default  | range            | meaning                                     |
// |-----------|------|----------|------------------|---------------------------------------------|
// | name      | -    | required | 1..100 printable | the upload's label (POST)                   |
// | body      | byte | required | 1..1 MiB         | the .pfn file, text (POST)                  |
//
// Thread-safety: pure functions of their arguments; each uses the given Database from the
// calling thread only.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>

#include "api/paging/list_page.h"
#include "api/request/parameters.h"
#include "models/aeronet/aeronet_phase_functions.h"
#include "storage/sqlite/database.h"

namespace clearsky::api {

// The largest file accepted: a day of AERONET retrievals is about 4.5 KiB per retrieval
// (models/data/aeronet: five in 22 KiB), so 1 MiB holds far more than a day's.
constexpr std::size_t kMaxAerosolFileBytes = std::size_t{1} << 20;

// The media types an inversion may be sent as (absent, text/plain, text/csv,
// application/octet-stream, with any parameters); 415 naming Content-Type for another.
void check_aerosol_media_type(std::optional<std::string_view> content_type);

// Checks name and body whole (400 naming `name`, or `body` with the reader's reason; 413 naming
// `body` beyond kMaxAerosolFileBytes), then stores the file; returns its id.
std::int64_t store_aerosol_inversion(storage::Database& db, const std::string& name,
                                     std::string_view body);

// GET /v1/aerosols: limit and cursor (400 for other parameters); newest first.
ListPage list_aerosol_inversions(storage::Database& db, Parameters query);

// GET /v1/aerosols/{id}; 404 unknown_aerosols naming `parameter`.
nlohmann::ordered_json show_aerosol_inversion(storage::Database& db, std::int64_t id,
                                              const std::string& parameter = "id");

// The stored file of an id, parsed; 404 unknown_aerosols naming `parameter` when there is none.
aeronet::PhaseFunctionFile load_aerosol_inversion(storage::Database& db, std::int64_t id,
                                                  const std::string& parameter);

// The path of a stored inversion.
std::string aerosols_location(std::int64_t id);

}  // namespace clearsky::api
