// What the data route handlers share: the data services of the context (503 without them), a
// database connection per request (SQLite WAL: readers do not wait for writers), and the
// current time for schedules.
#pragma once

#include "api/http/api_types.h"
#include "storage/sqlite/database.h"

namespace clearsky::api {

// The refusal of a data route by a server without a database (serve --role query): 404
// no_database, naming the role (docs/deploy.md "Roles"), or the parameter that needs the
// database (a sky request's fit).
ApiError no_database(const std::string& parameter = "role");
// The context's data services; no_database() when the server has none.
const DataServices& data_services(const ApiContext& context);
// A new connection to the server's database.
storage::Database open_database(const ApiContext& context);
// Seconds since 1970-01-01 UTC.
double now_unix_s();

}  // namespace clearsky::api
