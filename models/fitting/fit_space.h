// The space a fit searches (docs/fits.md "Free parameters and bounds"): which of a model's
// numeric parameters are free, their bounds and the coarse grid laid over them.
// A free parameter is any non-integer numeric parameter the model's descriptor lists: the shared
// atmosphere parameters (alpha, beta, g, turbidity, albedo; models/atmosphere/
// atmosphere_parameter_table.h) or a model option. Bounds default to the descriptor's range,
// except for the three aerosol parameters of the Bruneton family, whose default box is the one
// the study searched (Bruneton 2016, section "Quantitative evaluations": alpha in [0, 2], beta in
// [0.02, 0.2], g in [0.5, 0.9], on an 11 x 10 x 5 grid). Grid counts default to the study's for
// those three, 21 for a parameter searched alone, and 11 otherwise.
#pragma once

#include <cstddef>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "models/core/model_descriptor.h"
#include "models/core/sky_model.h"

namespace clearsky {

struct FreeParameter {
  std::string name;
  double min_value = 0;  // inclusive
  double max_value = 0;  // inclusive
  int grid_points = 0;   // >= 2 (1: the grid holds only the middle of the bounds)
};

// Bounds given by the user, by name (each inside the descriptor's range).
using FitBounds = std::map<std::string, std::pair<double, double>>;

// The free parameters with their bounds and grid counts. Throws InvalidInput naming "free" for a
// name the descriptor does not list, an integer option, a name given twice or an empty list;
// naming "bounds" for bounds of a parameter that is not free, outside the descriptor's range,
// NaN, or with min >= max; naming "grid" when grid_points is not empty and does not hold one
// count in [1, 101] per free parameter.
std::vector<FreeParameter> make_free_parameters(const ModelDescriptor& descriptor,
                                                std::span<const std::string> names,
                                                const FitBounds& bounds = {},
                                                std::span<const int> grid_points = {});

// The names a fit frees when the user names none: the descriptor's atmosphere parameters among
// alpha, beta, g (the Bruneton family) or else turbidity; empty when it lists none of them.
std::vector<std::string> default_free_parameters(const ModelDescriptor& descriptor);

// The values of the grid along one parameter: grid_points values evenly spaced from min to max,
// both included (the middle when grid_points is 1).
std::vector<double> grid_values(const FreeParameter& parameter);

// Every point of the grid, the first parameter varying slowest.
std::vector<std::vector<double>> grid_points(std::span<const FreeParameter> parameters);

// config with the free parameters set to values (atmosphere parameters in config.atmosphere,
// options in config.options); unchecked (the model's factory validates).
ModelConfig with_values(ModelConfig config, std::span<const FreeParameter> parameters,
                        std::span<const double> values);

// The value a free parameter has in config (the option's default when config has none).
double value_in(const ModelDescriptor& descriptor, const ModelConfig& config,
                const FreeParameter& parameter);

// Cheap table options for the search of a table model (docs/fits.md "Table models"): the
// smallest table resolution of models/bruneton/README.md's resolution table (8 x 32 x 8 x 4, 4
// orders, RMSE 11.394 instead of 11.333 at the paper resolution) for the options the descriptor lists; empty for a model
// without table options.
std::map<std::string, double> cheap_search_options(const ModelDescriptor& descriptor);

}  // namespace clearsky
