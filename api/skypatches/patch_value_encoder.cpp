// A sky patch's spectrum in the requested output (patch_value_encoder.h).
#include "api/skypatches/patch_value_encoder.h"

#include <utility>

#include "api/colour/radiance_rgb.h"
#include "api/http/api_types.h"

namespace clearsky::api {

PatchValueEncoder::PatchValueEncoder(std::string output, const std::vector<std::size_t>& indices,
                                     const XyzWeights& xyz)
    : output_(std::move(output)), indices_(indices), xyz_(xyz) {}

std::size_t PatchValueEncoder::components() const {
  if (output_ == "spectral") return indices_.size();
  return output_ == "rgb" ? 3 : 1;
}

std::vector<double> PatchValueEncoder::values(const Spectrum& spectrum) {
  if (output_ == "spectral") {
    std::vector<double> out;
    out.reserve(indices_.size());
    for (std::size_t i : indices_) out.push_back(spectrum[i]);
    return out;
  }
  const Xyz colour = xyz_.xyz({spectrum.data(), spectrum.size()});
  if (output_ == "luminance") return {kMaxLuminousEfficacy * colour.y};
  const ClippedRadianceRgb rgb = clip_radiance_rgb(xyz_to_radiance_rgb(colour));
  if (rgb.clipped) ++clipped_;
  return {rgb.rgb.r, rgb.rgb.g, rgb.rgb.b};
}

nlohmann::json PatchValueEncoder::json(const Spectrum& spectrum) {
  const std::vector<double> v = values(spectrum);
  if (output_ == "luminance") return finite(v[0]);
  nlohmann::json out = nlohmann::json::array();
  for (double x : v) out.push_back(finite(x));
  return out;
}

const char* PatchValueEncoder::unit() const {
  if (output_ == "spectral") return "W/(m2.sr.nm)";
  if (output_ == "rgb") return "W/(m2.sr)";
  return "cd/m2";
}

}  // namespace clearsky::api
