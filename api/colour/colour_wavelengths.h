// The wavelengths a colour answer (RGB, XYZ, luminance) is computed on, per quality level
// (docs/quality-levels.md "Colour wavelengths"): standard and reference use the model's own grid
// (the paper's 40 wavelengths), so their colours are those of the spectral answer, bit for bit;
// draft uses a short grid of kDraftColourWavelengthsNm, on which a table model builds tables for
// those wavelengths only, with XYZ weights that integrate the colour matching functions against
// the spectrum interpolated between them (XyzWeights::interpolating). Each draft answer states
// the grid and its colour error, Delta E 2000 against the 40-wavelength colour over the skydome
// (docs/quality-levels.md), from the table of measured figures here.
// Pure functions over constant data; thread-safe.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "models/quality/quality_levels.h"

namespace clearsky::api {

// 400 to 720 nm every 40 nm: Hosek and Wilkie's band centres (models/hosek/hosek_tables.h),
// spanning the colour matching functions' main lobes (CIE 15:2004 table T.4); outside them the
// spectrum is held at its end values.
inline const std::vector<double> kDraftColourWavelengthsNm = {400.0, 440.0, 480.0, 520.0, 560.0,
                                                              600.0, 640.0, 680.0, 720.0};

// The colour grid of a level: nullopt for the model's own grid.
std::optional<std::vector<double>> colour_wavelengths_nm(QualityLevel level);

// Delta E 2000 of a level's colour against the 40-wavelength colour over the skydome, as
// measured (docs/quality-levels.md "Colour wavelengths").
struct ColourError {
  double median = 0, p95 = 0, max = 0;
};
// The measured figures of the model's draft colour; nullopt when not measured.
std::optional<ColourError> draft_colour_error(const std::string& model_id);

// "400,440,...": the header text of a colour grid.
std::string wavelength_list_text(const std::vector<double>& wavelengths_nm);
// "Delta E 2000 against 40 wavelengths over the skydome: median 0.1, p95 0.2, max 0.3", or
// "not measured".
std::string colour_error_text(const std::optional<ColourError>& error);

}  // namespace clearsky::api
