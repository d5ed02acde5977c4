// Elek 2010 as a variant of the Bruneton 2008 implementation: its descriptor, factory and
// original 15-wavelength RGB output.
#include "models/elek/elek.h"

#include <stdexcept>

#include "models/core/invalid_input.h"

namespace clearsky {

WavelengthGrid elek_native_grid() { return WavelengthGrid::bins(360.0, 24.0, 15); }

const ModelDescriptor& elek_descriptor() {
  // Everything but the identity, the summary and the native wavelengths is Bruneton's.
  static const ModelDescriptor d{
      .id = "elek",
      .name = "Elek 2010",
      .version = "1",
      .citation =
          "O. Elek and P. Kmoch, Real-time spectral scattering in large-scale natural "
          "participating media, Spring Conference on Computer Graphics (SCCG) 2010, 83-90",
      .summary =
          "The precomputed 4D scattering tables of Bruneton 2008 (same implementation, "
          "resolutions and 4 scattering orders) computed on 15 wavelengths (360..720 nm, "
          "24 nm apart) and converted to RGB at the end; on the 2016 study's 40-wavelength "
          "grid it is identical to Bruneton.",
      .native_wavelengths_nm = elek_native_grid().nanometres(),
      .min_wavelength_nm = bruneton_descriptor().min_wavelength_nm,
      .max_wavelength_nm = bruneton_descriptor().max_wavelength_nm,
      .parameters = bruneton_descriptor().parameters,
      .capabilities = bruneton_descriptor().capabilities,
  };
  return d;
}

ModelFactory elek_factory() {
  return make_model_factory<&elek_descriptor, &BrunetonModel::build,
                            &BrunetonModel::estimated_table_bytes>();
}

LinearSrgb elek_original_rgb(const Spectrum& radiance_on_native_grid) {
  const WavelengthGrid grid = elek_native_grid();
  if (radiance_on_native_grid.size() != grid.size()) {
    throw InvalidInput("radiance", "expected the 15 native wavelengths of the Elek model");
  }
  return spectrum_to_linear_srgb(radiance_on_native_grid, grid);
}

}  // namespace clearsky
