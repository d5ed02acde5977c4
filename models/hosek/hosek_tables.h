// The Hosek-Wilkie fitted coefficients (Hosek and Wilkie 2012, "An Analytic Model for Full
// Spectral Sky-Dome Radiance"; 2013, "Adding a Solar Radiance Function to the Hosek Skylight
// Model"), parsed once from the embedded tables of models/data/hosek (BSD-3, see the LICENSE
// beside them; their layout below).
//
// Every sky dataset holds, for each channel (an 11-band spectrum 320..720 nm every 40 nm, or
// the 3 channels of the RGB and XYZ versions), ground albedo 0 and 1, turbidity 1..10 and the
// 6 control points of a quintic Bezier curve in (solar elevation / (pi/2))^(1/3): the nine
// coefficients A..I of the radiance distribution and one overall radiance scale.
// Immutable after construction; get() is thread-safe (static initialisation).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace clearsky::hosek {

inline constexpr int kBandCount = 11;
inline constexpr double kFirstBandNm = 320.0;
inline constexpr double kBandSpacingNm = 40.0;
inline constexpr double kLastBandNm = kFirstBandNm + (kBandCount - 1) * kBandSpacingNm;  // 720
inline constexpr int kTurbidityCount = 10;   // turbidity 1..10
inline constexpr int kControlPoints = 6;     // quintic Bezier
inline constexpr int kCoefficientCount = 9;  // A..I
inline constexpr int kSolarSegments = 45;    // solar radiance fit: pieces in elevation
inline constexpr int kSolarOrder = 4;        // cubic polynomial per piece
inline constexpr int kLimbDarkeningOrder = 6;

using Coefficients = std::array<double, kCoefficientCount>;

// One channel of a sky dataset.
struct SkyChannel {
  // [albedo 0..1][turbidity 1..10 -> 0..9][control point 0..5]
  std::array<std::array<std::array<Coefficients, kControlPoints>, kTurbidityCount>, 2>
      coefficients{};
  std::array<std::array<std::array<double, kControlPoints>, kTurbidityCount>, 2> radiance{};
};

struct Tables {
  std::array<SkyChannel, kBandCount> spectral;  // W/(m2.sr.nm) with the fit's solar spectrum
  std::array<SkyChannel, 3> rgb;                // linear sRGB primaries, radiometric
  std::array<SkyChannel, 3> xyz;                // CIE XYZ, radiometric (x 683 for cd/m2)
  // Solar disc radiance fit, W/(m2.sr.nm): [band][turbidity 0..9][segment 0..44], with the
  // polynomial c0 x^3 + c1 x^2 + c2 x + c3 in x = elevation - start of the segment (rad).
  std::array<
      std::array<std::array<std::array<double, kSolarOrder>, kSolarSegments>, kTurbidityCount>,
      kBandCount>
      solar{};
  // Limb darkening polynomial sum_k c_k mu^k in the cosine mu on the solar surface.
  std::array<std::array<double, kLimbDarkeningOrder>, kBandCount> limb_darkening{};
  // The solar radiance the fit was made with, W/(m2.sr.nm).
  std::array<double, kBandCount> original_solar_radiance{};

  static const Tables& get();
};

// Wavelength of band b, nm.
constexpr double band_wavelength_nm(int band) { return kFirstBandNm + kBandSpacingNm * band; }

}  // namespace clearsky::hosek
