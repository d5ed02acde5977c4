// The space a fit searches (fit_space.h).
#include "models/fitting/fit_space.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "models/atmosphere/atmosphere_parameter_table.h"
#include "models/core/invalid_input.h"

namespace clearsky {

namespace {

struct StudyBox {
  const char* name;
  double min_value;
  double max_value;
  int grid_points;
};
// Bruneton 2016, section "Quantitative evaluations": the grid the study searched for the
// atmosphere of the Bruneton family.
constexpr StudyBox kStudyBox[] = {
    {"alpha", 0.0, 2.0, 11}, {"beta", 0.02, 0.2, 10}, {"g", 0.5, 0.9, 5}};

const StudyBox* study_box(const std::string& name) {
  for (const StudyBox& box : kStudyBox)
    if (name == box.name) return &box;
  return nullptr;
}

std::string fmt(double value) {
  std::string text = std::to_string(value);
  while (!text.empty() && text.back() == '0') text.pop_back();
  if (!text.empty() && text.back() == '.') text.pop_back();
  return text;
}

}  // namespace

std::vector<FreeParameter> make_free_parameters(const ModelDescriptor& descriptor,
                                                std::span<const std::string> names,
                                                const FitBounds& bounds,
                                                std::span<const int> grid_points) {
  if (names.empty()) throw InvalidInput("free", "names no parameter");
  if (!grid_points.empty() && grid_points.size() != names.size())
    throw InvalidInput(
        "grid", "must give one count per free parameter (" + std::to_string(names.size()) + ")");
  std::vector<FreeParameter> out;
  std::set<std::string> seen;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string& name = names[i];
    const ParameterSpec* spec = descriptor.find_parameter(name);
    if (spec == nullptr)
      throw InvalidInput("free", name + " is not a parameter of " + descriptor.id);
    if (spec->integer)
      throw InvalidInput("free", name + " is an integer option; only continuous ones are fitted");
    if (!seen.insert(name).second) throw InvalidInput("free", name + " is given twice");
    FreeParameter p{name, spec->min_value, spec->max_value, 11};
    const StudyBox* box = study_box(name);
    if (box != nullptr && spec->atmosphere) {
      p.min_value = std::max(box->min_value, spec->min_value);
      p.max_value = std::min(box->max_value, spec->max_value);
      p.grid_points = box->grid_points;
    } else if (names.size() == 1) {
      p.grid_points = 21;
    }
    if (const auto it = bounds.find(name); it != bounds.end()) {
      const auto [low, high] = it->second;
      // Equal bounds are refused: a fixed value belongs in the fixed parameters.
      if (!(low >= spec->min_value && high <= spec->max_value && low < high))
        throw InvalidInput("bounds", name + ": [" + fmt(low) + ", " + fmt(high) +
                                         "] must be increasing and inside [" +
                                         fmt(spec->min_value) + ", " + fmt(spec->max_value) + "]");
      p.min_value = low;
      p.max_value = high;
    }
    if (!grid_points.empty()) {
      if (!(grid_points[i] >= 1 && grid_points[i] <= 101))
        throw InvalidInput("grid", name + ": the count must be in [1, 101]");
      p.grid_points = grid_points[i];
    }
    out.push_back(p);
  }
  for (const auto& [name, range] : bounds)
    if (!seen.contains(name)) throw InvalidInput("bounds", name + " is not a free parameter");
  return out;
}

std::vector<std::string> default_free_parameters(const ModelDescriptor& descriptor) {
  std::vector<std::string> out;
  for (const char* name : {"alpha", "beta", "g"})
    if (const ParameterSpec* spec = descriptor.find_parameter(name); spec && spec->atmosphere)
      out.emplace_back(name);
  if (out.empty() && descriptor.find_parameter("turbidity") != nullptr)
    out.emplace_back("turbidity");
  return out;
}

std::vector<double> grid_values(const FreeParameter& parameter) {
  if (parameter.grid_points <= 1) return {0.5 * (parameter.min_value + parameter.max_value)};
  std::vector<double> out;
  const double step =
      (parameter.max_value - parameter.min_value) / static_cast<double>(parameter.grid_points - 1);
  for (int i = 0; i < parameter.grid_points; ++i)
    out.push_back(i + 1 == parameter.grid_points ? parameter.max_value
                                                 : parameter.min_value + step * i);
  return out;
}

std::vector<std::vector<double>> grid_points(std::span<const FreeParameter> parameters) {
  std::vector<std::vector<double>> out{{}};
  for (const FreeParameter& p : parameters) {
    std::vector<std::vector<double>> next;
    for (const std::vector<double>& prefix : out)
      for (double v : grid_values(p)) {
        next.push_back(prefix);
        next.back().push_back(v);
      }
    out = std::move(next);
  }
  return out;
}

ModelConfig with_values(ModelConfig config, std::span<const FreeParameter> parameters,
                        std::span<const double> values) {
  for (std::size_t i = 0; i < parameters.size(); ++i)
    if (!set_atmosphere_parameter(config.atmosphere, parameters[i].name, values[i]))
      config.options[parameters[i].name] = values[i];
  return config;
}

double value_in(const ModelDescriptor& descriptor, const ModelConfig& config,
                const FreeParameter& parameter) {
  if (const AtmosphereParameterInfo* info = find_atmosphere_parameter(parameter.name))
    return info->value_in(config.atmosphere);
  if (const auto it = config.options.find(parameter.name); it != config.options.end())
    return it->second;
  const ParameterSpec* spec = descriptor.find_parameter(parameter.name);
  return spec != nullptr ? spec->default_value : std::nan("");
}

std::map<std::string, double> cheap_search_options(const ModelDescriptor& descriptor) {
  // models/bruneton/README.md, "Measured", the resolution table: 8 x 32 x 8 x 4 at 4 orders.
  constexpr std::pair<const char*, double> kCheap[] = {
      {"table_r_size", 8}, {"table_mu_size", 32}, {"table_mu_s_size", 8}, {"table_nu_size", 4}};
  std::map<std::string, double> out;
  for (const auto& [name, value] : kCheap)
    if (descriptor.find_parameter(name) != nullptr) out[name] = value;
  return out;
}

}  // namespace clearsky
