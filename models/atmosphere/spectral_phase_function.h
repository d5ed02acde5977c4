// A phase function that depends on the wavelength, known at a few wavelengths (the AERONET
// retrieval's 442, 674, 871 and 1020 nm) and evaluated on a model's wavelength grid:
// at a grid wavelength between two known ones, the linear interpolation in wavelength of their
// values; below the first or above the last known wavelength, the phase function of that
// wavelength (held, not extrapolated: the shape of a phase function beyond the retrieval's
// range is not implied by it, and a linear extrapolation of values can turn negative). Each
// known phase function integrates to 1 over the sphere, hence so does every interpolation.
// Immutable; thread-safe.
#pragma once

#include <vector>

#include "models/atmosphere/tabulated_phase_function.h"
#include "models/spectral/wavelength_grid.h"

namespace clearsky {

class SpectralPhaseFunction {
 public:
  // known_wavelengths_nm increasing, one phase function each. Throws InvalidInput
  // ("phase_function") when empty or mismatched.
  SpectralPhaseFunction(std::vector<double> known_wavelengths_nm,
                        std::vector<TabulatedPhaseFunction> phase, const WavelengthGrid& grid);

  std::size_t size() const { return lower_.size(); }  // the grid's wavelengths
  // The phase function (1/sr) at the cosine mu of the scattering angle, at each grid
  // wavelength: out[0 .. size()).
  void evaluate(double mu, float* out) const;
  // At grid wavelength i.
  double at(double mu, std::size_t i) const;
  // The phase function interpolated to one wavelength (held beyond the known ones) as a table
  // on the known angles: for the precomputation's single, wavelength-independent function.
  TabulatedPhaseFunction at_wavelength(double wavelength_nm) const;

 private:
  std::vector<double> known_nm_;
  std::vector<TabulatedPhaseFunction> phase_;
  std::vector<int> lower_;            // per grid wavelength: the known function below
  std::vector<double> upper_weight_;  // and the weight of the one above (0 when held)
};

}  // namespace clearsky
