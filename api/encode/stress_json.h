// JSON form of a stress run (`clearsky stress --json`, docs/stability.md): one object per
// model with its samples, refusals by status (declared and undeclared), values that must never
// appear, each sweep's worst neighbour jump and the excluded documented jumps, and the checks.
// Numbers that are not finite (a ratio to a zero bound) are written as null.
#pragma once

#include <nlohmann/json.hpp>

#include "models/stress/stress_report.h"

namespace clearsky::api {

nlohmann::json stress_report_to_json(const stress::ModelStressReport& report);

}  // namespace clearsky::api
