// The fit parameter: expanding a stored fit into the request's parameters and stating it in the
// answer (sky_fit.h).
#include "api/request/sky_fit.h"

#include <array>
#include <charconv>

#include "api/error/api_error.h"
#include "api/http/api_types.h"

namespace clearsky::api {

std::string round_trip_text(double value) {
  std::array<char, 32> buffer{};
  const auto [end, error] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  if (error != std::errc()) throw std::logic_error("round_trip_text: no room for a double");
  return std::string(buffer.data(), end);
}

std::optional<AppliedFit> expand_fit(Parameters& p, const ModelDescriptor& descriptor,
                                     const FitLookup& fits) {
  const std::optional<std::string> reference = p.text(kFitParameter);
  if (!reference) return std::nullopt;
  AppliedFit fit = fits(*reference, descriptor);
  require_fit_parameters_listed(fit, descriptor);
  for (const auto& [name, value] : fit.values) {
    if (p.has(name)) throw parameter_set_by_fit(name, fit);
    p.add(name, round_trip_text(value));
  }
  return fit;
}

void require_fit_parameters_listed(const AppliedFit& fit, const ModelDescriptor& descriptor) {
  for (const auto& [name, value] : fit.values) {
    if (descriptor.find_parameter(name) == nullptr) {
      throw ApiError::about(409, "fit_model_mismatch", kFitParameter,
                            "fit " + std::to_string(fit.id) + " sets " + name + ", which " +
                                descriptor.id + " no longer takes");
    }
  }
}

ApiError parameter_set_by_fit(const std::string& name, const AppliedFit& fit) {
  return ApiError::about(400, "conflicting_parameters", name,
                         "cannot be given together with fit: fit " + std::to_string(fit.id) +
                             " sets it (leave it out, or give every value without fit)");
}

nlohmann::json applied_fit_json(const AppliedFit& fit) {
  nlohmann::json values = nlohmann::json::object();
  for (const auto& [name, value] : fit.values) values[name] = finite(value);
  return {{"id", fit.id},
          {"model", fit.model_id},
          {"model_version", fit.model_version},
          {"dataset", fit.dataset},
          {"parameters", std::move(values)}};
}

void add_fit_member(nlohmann::json& body, const std::optional<AppliedFit>& fit) {
  if (fit) body["fit"] = applied_fit_json(*fit);
}

void add_fit_headers(std::vector<std::pair<std::string, std::string>>& headers,
                     const std::optional<AppliedFit>& fit) {
  if (!fit) return;
  headers.emplace_back("Clearsky-Fit", fit_summary(*fit));
  // fit=latest answers with whichever fit is newest when asked: a later fit changes the answer
  // to the same request, so no cache may keep it (the route's caching policy leaves a
  // Cache-Control set here alone).
  if (!fit->latest) return;
  for (const auto& [name, value] : headers)
    if (name == "Cache-Control") return;
  headers.emplace_back("Cache-Control", "no-store");
}

std::string fit_summary(const AppliedFit& fit) {
  std::string out = std::to_string(fit.id);
  for (const auto& [name, value] : fit.values) out += "; " + name + '=' + round_trip_text(value);
  return out;
}

}  // namespace clearsky::api
