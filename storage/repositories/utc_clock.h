// The current time as stored in the database: ISO 8601 UTC with milliseconds,
// e.g. "2026-11-21T09:30:00.123Z" (sorts as text in time order).
#pragma once

#include <string>

namespace clearsky::storage {

std::string utc_now_iso8601();

}  // namespace clearsky::storage
