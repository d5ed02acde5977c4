// The cost settings of each model that the run-time-vs-error atlas measures (docs/performance.md):
// option sets taken from the model's descriptor options (table resolutions, scattering orders,
// ray samples, per-sun buckets and grids; models/<id>/README.md lists each model's cost
// options) and wavelength grids, the study's standard setting (every option at its default, the
// paper's 40 bins) among them, and a converged reference setting of the model, finer than
// anything in the list, with a reference check one step finer still that shows it converged.
// A quick atlas (AtlasScope::quick) keeps fewer settings and a cheaper reference.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "models/core/sky_model.h"

namespace clearsky::atlas {

// The wavelengths a setting computes: the paper's 40 bins, the 3 points of the paper's RGB
// method (models/colour/three_wavelength_rgb.h), or the model's native bands.
enum class AtlasGrid { paper_bins, rgb_points, native_bands };
std::string to_string(AtlasGrid grid);

struct AtlasSetting {
  std::string name;                       // "standard", "orders=2", "rgb", ...
  std::map<std::string, double> options;  // the options that differ from the defaults
  AtlasGrid grid = AtlasGrid::paper_bins;

  ModelConfig config(const ModelDescriptor& descriptor) const;
};

enum class AtlasScope { full, quick };

struct ModelAtlasSettings {
  std::vector<AtlasSetting> settings;  // settings[0] is the standard setting
  AtlasSetting reference;
  // One step finer than the reference; empty name: no check (the model has no numerical
  // discretisation to refine: the fitted and analytic models, whose reference is the standard).
  AtlasSetting reference_check;
  std::string reference_reason;  // how the reference was chosen
};

// The settings of the model with this descriptor; std::invalid_argument for an unknown model.
ModelAtlasSettings atlas_settings(const ModelDescriptor& descriptor, AtlasScope scope);

}  // namespace clearsky::atlas
