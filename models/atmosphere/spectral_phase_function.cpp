// Wavelength interpolation of tabulated phase functions (spectral_phase_function.h).
#include "models/atmosphere/spectral_phase_function.h"

#include <algorithm>

#include "models/core/invalid_input.h"

namespace clearsky {

namespace {

// The known function below wavelength_nm and the weight of the one above.
std::pair<int, double> bracket(const std::vector<double>& known, double wavelength_nm) {
  if (wavelength_nm <= known.front()) return {0, 0.0};
  if (wavelength_nm >= known.back()) return {static_cast<int>(known.size()) - 1, 0.0};
  const auto it = std::upper_bound(known.begin(), known.end(), wavelength_nm);
  const int i = static_cast<int>(it - known.begin()) - 1;
  return {i, (wavelength_nm - known[i]) / (known[i + 1] - known[i])};
}

}  // namespace

SpectralPhaseFunction::SpectralPhaseFunction(std::vector<double> known_wavelengths_nm,
                                             std::vector<TabulatedPhaseFunction> phase,
                                             const WavelengthGrid& grid)
    : known_nm_(std::move(known_wavelengths_nm)), phase_(std::move(phase)) {
  if (known_nm_.empty() || known_nm_.size() != phase_.size())
    throw InvalidInput("phase_function", "one phase function per known wavelength expected");
  for (std::size_t i = 1; i < known_nm_.size(); ++i)
    if (!(known_nm_[i] > known_nm_[i - 1]))
      throw InvalidInput("phase_function", "the wavelengths must increase");
  for (std::size_t i = 0; i < grid.size(); ++i) {
    const auto [lower, weight] = bracket(known_nm_, grid[i]);
    lower_.push_back(lower);
    upper_weight_.push_back(weight);
  }
}

double SpectralPhaseFunction::at(double mu, std::size_t i) const {
  const double low = phase_[static_cast<std::size_t>(lower_[i])](mu);
  if (upper_weight_[i] == 0.0) return low;
  const double high = phase_[static_cast<std::size_t>(lower_[i]) + 1](mu);
  return low + upper_weight_[i] * (high - low);
}

void SpectralPhaseFunction::evaluate(double mu, float* out) const {
  // At most a handful of known functions: evaluate each once.
  double known[16];
  const std::size_t n_known = std::min<std::size_t>(phase_.size(), 16);
  for (std::size_t k = 0; k < n_known; ++k) known[k] = phase_[k](mu);
  for (std::size_t i = 0; i < lower_.size(); ++i) {
    const auto k = static_cast<std::size_t>(lower_[i]);
    const double low = k < n_known ? known[k] : phase_[k](mu);
    double value = low;
    if (upper_weight_[i] != 0.0) {
      const double high = k + 1 < n_known ? known[k + 1] : phase_[k + 1](mu);
      value = low + upper_weight_[i] * (high - low);
    }
    out[i] = static_cast<float>(value);
  }
}

TabulatedPhaseFunction SpectralPhaseFunction::at_wavelength(double wavelength_nm) const {
  const auto [lower, weight] = bracket(known_nm_, wavelength_nm);
  const TabulatedPhaseFunction& low = phase_[static_cast<std::size_t>(lower)];
  std::vector<double> values = low.values_per_sr();
  if (weight != 0.0) {
    const TabulatedPhaseFunction& high = phase_[static_cast<std::size_t>(lower) + 1];
    for (std::size_t a = 0; a < values.size(); ++a)
      values[a] += weight * (high.at_angle_deg(low.angles_deg()[a]) - values[a]);
  }
  return TabulatedPhaseFunction(low.angles_deg(), values);
}

}  // namespace clearsky
