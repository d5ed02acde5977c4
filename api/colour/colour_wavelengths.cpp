// Colour wavelengths per quality level and the measured draft colour error
// (colour_wavelengths.h).
#include "api/colour/colour_wavelengths.h"

#include <cstdio>
#include <map>

namespace clearsky::api {

std::optional<std::vector<double>> colour_wavelengths_nm(QualityLevel level) {
  if (level == QualityLevel::draft) return kDraftColourWavelengthsNm;
  return std::nullopt;
}

std::optional<ColourError> draft_colour_error(const std::string& model_id) {
  // Measured by DraftColour.DeltaE2000OverTheSkydome (tests/api/colour/colour_wavelengths_test.cpp,
  // which prints them and fails when a model exceeds its figure): median, 95th percentile and
  // maximum over suns at zenith 10, 40, 70 and 85 degrees and views on a 64 x 16 grid of the
  // upper hemisphere, at the draft's tables (docs/quality-levels.md "Colour wavelengths"); rounded up to
  // 2 decimals. Measured 2026-11-27.
  static const std::map<std::string, ColourError> measured = {
      {"nishita93", {0.26, 0.37, 0.53}},
      {"nishita96", {0.20, 0.37, 0.51}},
      {"preetham", {0.42, 0.95, 1.22}},
      {"oneal", {0.21, 0.35, 0.42}},
      {"haber", {0.18, 0.28, 0.41}},
      {"bruneton", {0.17, 0.38, 0.66}},
      {"elek", {0.17, 0.38, 0.66}},
      {"hosek", {0.31, 0.43, 0.49}},
      {"measured_aerosols", {0.15, 0.32, 0.55}},
  };
  const auto it = measured.find(model_id);
  if (it == measured.end()) return std::nullopt;
  return it->second;
}

std::string wavelength_list_text(const std::vector<double>& wavelengths_nm) {
  std::string text;
  for (double w : wavelengths_nm) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", w);
    if (!text.empty()) text += ",";
    text += buffer;
  }
  return text;
}

std::string colour_error_text(const std::optional<ColourError>& error) {
  if (!error) return "not measured";
  char buffer[160];
  std::snprintf(buffer, sizeof buffer,
                "Delta E 2000 against 40 wavelengths over the skydome: median %.3g, p95 %.3g, "
                "max %.3g",
                error->median, error->p95, error->max);
  return buffer;
}

}  // namespace clearsky::api
