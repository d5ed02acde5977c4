// Elek 2010 as a variant of the Bruneton 2008 implementation: its descriptor, factory and
// original 15-wavelength RGB output.
#include "models/elek/elek.h"

#include <stdexcept>

namespace clearsky {

WavelengthGrid elek_native_grid() { return WavelengthGrid::bins(360.0, 24.0, 15); }

const ModelDescriptor& elek_descriptor() {
  static const ModelDescriptor d = [] {
    // Everything but the identity, the summary and the native wavelengths is Bruneton's.
    ModelDescriptor m;
    m.parameters = bruneton_descriptor().parameters;
    m.capabilities = bruneton_descriptor().capabilities;
    m.min_wavelength_nm = bruneton_descriptor().min_wavelength_nm;
    m.max_wavelength_nm = bruneton_descriptor().max_wavelength_nm;
    m.id = std::string("elek");
    m.name = std::string("Elek 2010");
    m.version = std::string("1");
    m.citation =
        "O. Elek and P. Kmoch, Real-time spectral scattering in large-scale natural participating "
        "media, "
        "Spring Conference on Computer Graphics (SCCG) 2010, 83-90";
    m.summary =
        "The precomputed 4D scattering tables of Bruneton 2008 (same implementation, resolutions "
        "and 4 "
        "scattering orders) computed on 15 wavelengths (360..720 nm, 24 nm apart) and converted to "
        "RGB at the end; "
        "on the 2016 study's 40-wavelength grid it is identical to Bruneton.";
    m.native_wavelengths_nm = elek_native_grid().nanometres();
    return m;
  }();
  return d;
}

ModelFactory elek_factory() {
  return {&elek_descriptor(), [](const ModelConfig& config, const PrecomputeContext& context) {
            return std::shared_ptr<const SkyModel>(
                BrunetonModel::create(elek_descriptor(), config, context));
          }};
}

LinearSrgb elek_original_rgb(const Spectrum& radiance_on_native_grid) {
  const WavelengthGrid grid = elek_native_grid();
  if (radiance_on_native_grid.size() != grid.size()) {
    throw std::invalid_argument("radiance: expected the 15 native wavelengths of the Elek model");
  }
  return spectrum_to_linear_srgb(radiance_on_native_grid, grid);
}

}  // namespace clearsky
