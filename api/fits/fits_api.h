// The fits of the HTTP API (docs/fits.md "Over HTTP"): the body of POST /v1/fits turned into a
// FitRequest (api/fits/fit_runner.h), checked before anything is queued, and the stored fits
// as GET /v1/fits (paged, newest first; api/paging/list_page.h) and GET /v1/fits/{id} answer
// them (api/encode/fit_json.h, the JSON of `clearsky fit --json`).
// Thread-safety: pure functions of their arguments; each uses the given Database from the
// calling thread only.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "api/fits/fit_runner.h"
#include "api/paging/list_page.h"
#include "api/request/parameters.h"
#include "storage/sqlite/database.h"

namespace clearsky::api {

// The JSON body of POST /v1/fits: dataset and model (required), free, bounds, grid, captures,
// parameters, search_options, per_capture, cross_validate, max_evaluations, fold_evaluations
// (the options of `clearsky fit`, docs/fits.md). 400 naming the member for an unknown member,
// a wrong type or what check_fit_request refuses (unknown model, a parameter that cannot be
// fitted, bad bounds or grid counts, a capture label the dataset does not hold); 404
// unknown_dataset when no such dataset is stored.
FitRequest parse_fit_request(storage::Database& db, const std::string& body,
                             const std::string& software_version);

// GET /v1/fits: limit and cursor (400 for other parameters); newest first.
ListPage list_fits(storage::Database& db, Parameters query);

// GET /v1/fits/{id}: the query's history (true or false, default false; 400 for another
// parameter) adds every point evaluated.
bool parse_show_fit_history(Parameters query);
// The stored fit; 404 unknown_fit.
nlohmann::json show_fit(storage::Database& db, std::int64_t id, bool with_history);

// The path of a fit.
std::string fit_location(std::int64_t id);

}  // namespace clearsky::api
