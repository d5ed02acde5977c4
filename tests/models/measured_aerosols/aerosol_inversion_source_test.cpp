// The process-wide inversion source (models/measured_aerosols/aerosol_inversion_source.h) and
// measured_aerosols' option aerosols: an installed source answers its ids; without one, or for an
// id it does not know, nothing is found and the factory refuses naming aerosols before building.
#include "models/measured_aerosols/aerosol_inversion_source.h"

#include <gtest/gtest.h>

#include "models/core/invalid_input.h"
#include "models/measured_aerosols/measured_aerosols.h"

namespace clearsky {
namespace {

// Removes whatever a test installed.
struct SourceReset {
  ~SourceReset() { install_aerosol_inversion_source({}); }
};

TEST(AerosolInversionSource, AnswersTheIdsOfTheInstalledSourceOnly) {
  const SourceReset reset;
  EXPECT_FALSE(aerosol_inversion_bytes(7));
  install_aerosol_inversion_source([](std::int64_t id) -> std::optional<std::string> {
    if (id == 7) return std::string("bytes of 7");
    return std::nullopt;
  });
  ASSERT_TRUE(aerosol_inversion_bytes(7));
  EXPECT_EQ(*aerosol_inversion_bytes(7), "bytes of 7");
  EXPECT_FALSE(aerosol_inversion_bytes(8));
  install_aerosol_inversion_source({});
  EXPECT_FALSE(aerosol_inversion_bytes(7));
}

TEST(AerosolInversionSource,
     TheDescriptorDeclaresAerosolsAsAnIntegerOptionDefaultingToTheShippedFile) {
  const ParameterSpec* p = measured_aerosols_descriptor().find_parameter(kAerosolsOption);
  ASSERT_NE(p, nullptr);
  EXPECT_TRUE(p->integer);
  EXPECT_FALSE(p->atmosphere);
  EXPECT_EQ(p->default_value, 0.0);
  EXPECT_EQ(p->min_value, 0.0);
}

TEST(AerosolInversionSource, AnUnknownIdIsRefusedNamingAerosols) {
  const SourceReset reset;
  install_aerosol_inversion_source(
      [](std::int64_t) -> std::optional<std::string> { return std::nullopt; });
  ModelConfig config;
  config.options[kAerosolsOption] = 5;
  try {
    measured_aerosols_factory().create(config, {});
    ADD_FAILURE() << "aerosols=5 accepted";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.field(), kAerosolsOption) << e.what();
  }
}

}  // namespace
}  // namespace clearsky
