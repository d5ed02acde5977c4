// The canonical form of a model configuration (models/core/canonical_config.h): options at their
// descriptor default are dropped, every other option kept.
#include "models/core/canonical_config.h"

#include <gtest/gtest.h>

#include "models/measured_aerosols/aerosol_inversion_source.h"
#include "models/measured_aerosols/measured_aerosols.h"

namespace clearsky {
namespace {

TEST(CanonicalConfig, MeasuredAerosolsZeroIsTheOptionLeftOut) {
  const ModelDescriptor& descriptor = measured_aerosols_descriptor();
  ModelConfig zero;
  zero.options[kAerosolsOption] = 0;
  EXPECT_EQ(canonical_config(descriptor, zero).canonical_string(),
            ModelConfig{}.canonical_string());
  ModelConfig uploaded;
  uploaded.options[kAerosolsOption] = 3;
  EXPECT_EQ(canonical_config(descriptor, uploaded).options, uploaded.options);
}

TEST(CanonicalConfig, KeepsOptionsAwayFromTheirDefaultAndUnknownOnes) {
  const ModelDescriptor& descriptor = measured_aerosols_descriptor();
  ModelConfig config;
  config.options = {{"aod_scale", 1.0}, {"retrieval_time_utc_h", 14.0}, {"colour", 1.0}};
  const ModelConfig canonical = canonical_config(descriptor, config);
  EXPECT_EQ(canonical.options,
            (std::map<std::string, double>{{"retrieval_time_utc_h", 14.0}, {"colour", 1.0}}));
  EXPECT_EQ(canonical.atmosphere, config.atmosphere);
  EXPECT_EQ(canonical.wavelengths, config.wavelengths);
}

}  // namespace
}  // namespace clearsky
