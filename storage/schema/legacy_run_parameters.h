// Converts an evaluation run's parameters as schema versions 1 to 3 stored them (the model
// configuration's canonical key, ModelConfig::canonical_string(): "R=6360000;...;alpha=
// 0.80000000000000004;...;albedo=grass;grid=bins:360,11.75,40;gain=2") into the JSON object
// that schema version 4 stores (docs/data-api.md "Evaluation parameters"): the parameters by
// their request names, with the values that differ from the defaults (the user gave those;
// a default given explicitly cannot be told apart), each number written as the shortest
// decimal that reads back to the same double ("alpha": 1.3, not 1.3000000000000000444). Model
// options are kept whatever their value (they were stored only when given). Text that is not
// such a key gives "{}".
// register_legacy_run_parameters() makes it the SQL function legacy_run_parameters_json(text)
// on a connection, for the migration.
#pragma once

#include <string>
#include <string_view>

#include "storage/sqlite/database.h"

namespace clearsky::storage {

std::string legacy_run_parameters_json(std::string_view canonical);
void register_legacy_run_parameters(Database& db);

}  // namespace clearsky::storage
