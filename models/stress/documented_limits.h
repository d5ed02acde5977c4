// Checks of the stress run that a model is documented to fail, within a stated allowance
// (docs/stability.md "Documented limits"), each named and explained in the model's README. A
// violation within the allowance is reported under the limit's name; beyond it, or a check with
// no documented limit, is a failure. Allowances are the worst measured ratio to the bound with a
// margin, so that a change making the model worse fails.
#pragma once

#include <limits>
#include <span>
#include <string>

#include "models/core/sky_model.h"
#include "models/stress/stress_report.h"

namespace clearsky::stress {

struct DocumentedLimit {
  std::string model{};         // descriptor id
  std::string check_prefix{};  // the BoundCheck names it covers start with this
  std::string name{};          // e.g. "fit_energy_excess"
  double allowed_worst = 1.0;  // the largest ratio to the bound it allows
  // Applies while this option is below option_below (e.g. O'Neal's sample count); empty: always.
  std::string option{};
  double option_below = std::numeric_limits<double>::infinity();
  std::string documented_in{};  // the README that explains it
};

std::span<const DocumentedLimit> documented_limits();

// Marks check with the documented limit of model that covers it, if any.
void apply_documented_limit(const SkyModel& model, BoundCheck& check);

// Whether check fails: a violation beyond its documented limit, or with none.
inline bool failed(const BoundCheck& check) {
  return check.violations > 0 &&
         (check.documented_limit.empty() || check.worst > check.allowed_worst);
}

}  // namespace clearsky::stress
