// A sky patch's (or the sun's) spectrum in the output GET /v1/skypatches asks for
// (docs/building-energy.md "Units and outputs"), shared by the sky vector and the sky matrix:
//  - spectral: the radiance at each answered wavelength, W/(m2.sr.nm);
//  - rgb: Radiance's RGB (api/colour/radiance_rgb.h), W/(m2.sr), negative components clipped
//    to 0 and counted;
//  - luminance: 683 lm/W x Y, cd/m2.
// Not thread-safe (it counts the clipped values): one per answer.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "api/colour/xyz_weights.h"
#include "models/spectral/spectrum.h"

namespace clearsky::api {

class PatchValueEncoder {
 public:
  // output: spectral, rgb or luminance; indices: the answered samples of the model's grid.
  PatchValueEncoder(std::string output, const std::vector<std::size_t>& indices,
                    const XyzWeights& xyz);

  // Numbers per value: the answered wavelengths, 3 or 1.
  std::size_t components() const;
  std::vector<double> values(const Spectrum& spectrum);
  // A number (luminance) or an array (spectral, rgb).
  nlohmann::json json(const Spectrum& spectrum);
  const std::string& output() const { return output_; }
  // W/(m2.sr.nm), W/(m2.sr) or cd/m2.
  const char* unit() const;
  // Colours with a negative Radiance RGB component clipped so far.
  std::size_t clipped() const { return clipped_; }

 private:
  std::string output_;
  const std::vector<std::size_t>& indices_;
  const XyzWeights& xyz_;
  std::size_t clipped_ = 0;
};

}  // namespace clearsky::api
