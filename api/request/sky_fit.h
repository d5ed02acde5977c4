// The fit parameter of the sky endpoints and of evaluations (docs/fits.md "Using a fit"):
//
// clang-format off
// | parameter | values                     | meaning                                                                 |
// |-----------|----------------------------|-------------------------------------------------------------------------|
// | fit       | ID, latest, latest:DATASET | a stored succeeded fit of the request's model: its fitted values, as if  |
// |           |                            | the request had given them (latest: the newest, on DATASET when named)  |
// clang-format on
//
// The fit sets the free parameters it fitted (alpha, beta, g, turbidity, albedo, a model option)
// and nothing else: its fixed parameters are not applied. A parameter the request gives itself
// and the fit sets too is refused (400 conflicting_parameters naming the parameter): there is no
// precedence to remember. Each value then goes through the same parsing and range checks as a
// value the request gave. The answer says which fit and which values it used.
#pragma once

#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "api/error/api_error.h"
#include "api/request/parameters.h"
#include "models/core/sky_model.h"

namespace clearsky::api {

inline constexpr const char* kFitParameter = "fit";

// A stored fit as a request uses it.
struct AppliedFit {
  std::int64_t id = 0;
  std::string model_id;
  std::string model_version;  // the model's version when it was fitted
  std::string dataset;
  // Named by fit=latest: the answer depends on the stored fits, not on the request alone.
  bool latest = false;
  // The fitted free parameters and their values, in the fit's order.
  std::vector<std::pair<std::string, double>> values;
};

// The succeeded fit the text of a fit parameter names, for the model (an ApiError naming fit
// otherwise: 400 unreadable, 404 unknown or none, 409 not succeeded or of another model).
using FitLookup =
    std::function<AppliedFit(const std::string& reference, const ModelDescriptor& descriptor)>;

// Reads `fit` and, when given, adds the fit's values to p under their names, as text that parses
// back to the same double, for the model's parser to read like any parameter. A name p already
// has is a 400 conflicting_parameters naming it; a name the descriptor does not list (a model
// changed since the fit) a 409 naming fit.
std::optional<AppliedFit> expand_fit(Parameters& p, const ModelDescriptor& descriptor,
                                     const FitLookup& fits);

// 409 fit_model_mismatch naming fit when the fit sets a parameter the descriptor does not list
// (the model changed since the fit).
void require_fit_parameters_listed(const AppliedFit& fit, const ModelDescriptor& descriptor);
// 400 conflicting_parameters naming a parameter the request gives and the fit sets too.
ApiError parameter_set_by_fit(const std::string& name, const AppliedFit& fit);

// {"id", "model", "model_version", "dataset", "parameters": {name: value}}.
nlohmann::json applied_fit_json(const AppliedFit& fit);
// The answer's "fit" member, when a fit was used.
void add_fit_member(nlohmann::json& body, const std::optional<AppliedFit>& fit);
// The header Clearsky-Fit ("12; turbidity=2.348"), and Cache-Control: no-store for fit=latest,
// when a fit was used.
void add_fit_headers(std::vector<std::pair<std::string, std::string>>& headers,
                     const std::optional<AppliedFit>& fit);
// "12; turbidity=2.348" (id, then each value at full precision).
std::string fit_summary(const AppliedFit& fit);
// The shortest text that parses back to value (std::to_chars).
std::string round_trip_text(double value);

}  // namespace clearsky::api
