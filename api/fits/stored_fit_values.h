// A stored fit as a sky request or an evaluation uses it (fit=ID, latest or latest:DATASET;
// docs/fits.md "Using a fit"): the reference read, the fit found in the fits table and checked
// (succeeded, of the request's model), and its fitted values taken from its result.
// Thread-safety: pure functions of their arguments; each uses the given Database from the
// calling thread only. stored_fit_lookup opens its own connection per call.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "api/http/api_types.h"
#include "api/request/sky_fit.h"
#include "storage/sqlite/database.h"

namespace clearsky::api {

// What a fit parameter names: one fit by id, or the newest succeeded fit of the model (on a
// dataset when given).
struct FitReference {
  std::optional<std::int64_t> id;  // empty: latest
  std::optional<std::string> dataset;
};
// "12", "latest" or "latest:kider2014"; anything else is a 400 naming fit.
FitReference parse_fit_reference(const std::string& text);

// The fit reference names for the model. 404 unknown_fit naming fit (no such id, no succeeded
// fit of the model), 409 naming fit for a fit not succeeded (fit_not_succeeded: queued,
// running, failed, interrupted) or of another model (fit_model_mismatch).
AppliedFit find_applied_fit(storage::Database& db, const FitReference& reference,
                            const ModelDescriptor& descriptor);
// The stored fit with that id, whatever its model (404 unknown_fit, 409 fit_not_succeeded,
// naming fit).
AppliedFit find_succeeded_fit(storage::Database& db, std::int64_t id);

// The lookup of the sky endpoints: the server's database, opened when a request names a fit; a
// server without one (serve --role query) answers 404 no_database naming fit.
FitLookup stored_fit_lookup(const ApiContext& context);

}  // namespace clearsky::api
