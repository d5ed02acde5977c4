// The spectral range of the models built on AtmosphereSpectra is where the solar spectrum is
// defined: answered at its ends, refused (InvalidInput naming "wavelengths") beyond them.
#include <gtest/gtest.h>

#include <cmath>

#include "models/atmosphere/atmosphere_spectra.h"
#include "models/atmosphere/solar_spectrum.h"
#include "models/core/invalid_input.h"

namespace clearsky {
namespace {

TEST(SolarSpectrumRange, EndsAreAnsweredAndBeyondIsRefusedByName) {
  for (double nm : {kSolarSpectrumMinNm, kSolarSpectrumMaxNm}) {
    const double e = solar_spectrum_at_point_nm(nm);
    EXPECT_TRUE(std::isfinite(e) && e > 0.0) << nm;
  }
  for (double nm : {kSolarSpectrumMinNm - 0.01, kSolarSpectrumMaxNm + 0.01}) {
    try {
      solar_spectrum_at_point_nm(nm);
      ADD_FAILURE() << nm << " nm answered";
    } catch (const InvalidInput& e) {
      EXPECT_EQ(e.field(), "wavelengths");
    }
  }
  EXPECT_THROW(AtmosphereSpectra::build({}, WavelengthGrid::points({250.0, 550.0})), InvalidInput);
}

}  // namespace
}  // namespace clearsky
