// The one table of atmosphere parameters: defaults, validation, canonical strings (cache keys
// must not change), request names, descriptor entries, and the comment table of
// atmosphere_parameters.h read back and compared with it.
#include "models/atmosphere/atmosphere_parameter_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "models/bruneton/bruneton.h"
#include "models/core/invalid_input.h"
#include "models/registry.h"
#include "tests/models/support/parameter_table_text.h"

namespace clearsky {
namespace {

using testing::matches_as_written;
using testing::range_of;

TEST(AtmosphereParameterTable, DefaultsAreTheTables) {
  const AtmosphereParameters defaults;
  for (const AtmosphereParameterInfo& p : kAtmosphereParameterTable) {
    if (p.has_numeric_default()) {
      EXPECT_EQ(p.value_in(defaults), p.default_value) << p.name;
      EXPECT_TRUE(p.in_range(p.default_value)) << p.name;
    } else {
      EXPECT_FALSE(defaults.ground_albedo.has_value()) << p.name;
      EXPECT_EQ(p.default_text, "grass");
    }
  }
  EXPECT_NO_THROW(defaults.validate());
}

TEST(AtmosphereParameterTable, CanonicalStringIsByteIdenticalToTheCacheKeysInUse) {
  // The text every cache key and table store key of the default atmosphere was built from.
  EXPECT_EQ(AtmosphereParameters{}.canonical_string(),
            "R=6360000;top=6420000;HR=8000;HM=1200;T=15;alpha=0.80000000000000004;"
            "beta=0.040000000000000001;ssa=0.80000000000000004;g=0.69999999999999996;"
            "turbidity=2.5299999999999998;albedo=grass");
  AtmosphereParameters constant_albedo;
  constant_albedo.ground_albedo = 0.25;
  EXPECT_EQ(constant_albedo.canonical_string().substr(
                constant_albedo.canonical_string().rfind(";albedo=")),
            ";albedo=0.25");
  // The default Bruneton tables on disk are found by this key.
  EXPECT_EQ(BrunetonModel::cache_key(ModelConfig{}), "bruneton-a9ee3c37742c94db");
}

TEST(AtmosphereParameterTable, EveryParameterIsValidatedByItsName) {
  for (const AtmosphereParameterInfo& p : kAtmosphereParameterTable) {
    const double below = p.min_exclusive ? p.min_value : p.min_value - 1.0;
    const double above = std::isinf(p.max_value)
                             ? std::numeric_limits<double>::quiet_NaN()
                             : (p.max_exclusive ? p.max_value : p.max_value + 1.0);
    for (double bad : {below, above, std::numeric_limits<double>::quiet_NaN()}) {
      AtmosphereParameters a;
      ASSERT_TRUE(set_atmosphere_parameter(a, p.name, bad));
      try {
        a.validate();
        ADD_FAILURE() << p.name << " = " << bad << " accepted";
      } catch (const InvalidInput& e) {
        EXPECT_EQ(e.field(), p.name);
        EXPECT_EQ(std::string(e.what()).rfind(std::string(p.name) + ": must be", 0), 0u)
            << e.what();
      }
    }
    if (!p.min_exclusive && p.above.empty()) {
      AtmosphereParameters a;
      set_atmosphere_parameter(a, p.name, p.min_value);
      EXPECT_NO_THROW(a.validate()) << p.name << " at its inclusive minimum";
    }
  }
  AtmosphereParameters low_top;
  low_top.top_radius_m = low_top.earth_radius_m;
  try {
    low_top.validate();
    ADD_FAILURE() << "top at the ground accepted";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.field(), "top_radius_m");
    EXPECT_EQ(e.reason(), "must be finite and > earth_radius_m");
  }
}

TEST(AtmosphereParameterTable, RequestNamesSetTheirMembers) {
  for (const AtmosphereParameterInfo& p : kAtmosphereParameterTable) {
    AtmosphereParameters a;
    const double value = p.in_range(0.5) ? 0.5 : p.default_value * 1.01;
    ASSERT_TRUE(set_atmosphere_parameter(a, p.name, value)) << p.name;
    EXPECT_EQ(p.value_in(a), value) << p.name;
    EXPECT_NE(a, AtmosphereParameters{}) << p.name;
    EXPECT_EQ(find_atmosphere_parameter(p.name), &p);
  }
  AtmosphereParameters a;
  EXPECT_FALSE(set_atmosphere_parameter(a, "angstrom_alpha", 1.0)) << "member names are not";
  EXPECT_EQ(a, AtmosphereParameters{});
}

TEST(AtmosphereParameterTable, DescriptorEntriesComeFromTheTable) {
  const ParameterSpec g = atmosphere_parameter_spec("g");
  EXPECT_TRUE(g.atmosphere);
  EXPECT_EQ(g.default_value, 0.7);
  EXPECT_EQ(g.min_value, -0.999);
  const ParameterSpec narrowed = atmosphere_parameter_spec("turbidity", 2.0, 10.0);
  EXPECT_EQ(narrowed.min_value, 2.0);
  EXPECT_THROW(atmosphere_parameter_spec("turbidity", 0.5, 10.0), std::logic_error);
  EXPECT_THROW(atmosphere_parameter_spec("angstrom_alpha"), std::logic_error);
  // No range of the table can be published with an open bound it does not have.
  EXPECT_THROW(atmosphere_parameter_spec("earth_radius_m"), std::logic_error);
}

// The tables written for people (the comment table of atmosphere_parameters.h, the table of
// docs/model-contract.md), row by row, against the table.
class AtmosphereParameterDocumentation : public ::testing::TestWithParam<const char*> {};

TEST_P(AtmosphereParameterDocumentation, TableMatches) {
  const auto rows =
      testing::read_table(testing::read_text(testing::source_root() / GetParam()), "name");
  ASSERT_EQ(rows.size(), kAtmosphereParameterTable.size()) << GetParam();
  // The member column by name (the only place a test can learn a member's spelling).
  const std::map<std::string, double AtmosphereParameters::*> members = {
      {"earth_radius_m", &AtmosphereParameters::earth_radius_m},
      {"top_radius_m", &AtmosphereParameters::top_radius_m},
      {"rayleigh_scale_height_m", &AtmosphereParameters::rayleigh_scale_height_m},
      {"mie_scale_height_m", &AtmosphereParameters::mie_scale_height_m},
      {"rayleigh_temperature_celsius", &AtmosphereParameters::rayleigh_temperature_celsius},
      {"angstrom_alpha", &AtmosphereParameters::angstrom_alpha},
      {"angstrom_beta", &AtmosphereParameters::angstrom_beta},
      {"mie_single_scattering_albedo", &AtmosphereParameters::mie_single_scattering_albedo},
      {"mie_phase_g", &AtmosphereParameters::mie_phase_g},
      {"turbidity", &AtmosphereParameters::turbidity},
      {"precipitable_water_cm", &AtmosphereParameters::precipitable_water_cm},
      {"ozone_atm_cm", &AtmosphereParameters::ozone_atm_cm}};
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const testing::TableRow& row = rows[i];
    const AtmosphereParameterInfo& p = kAtmosphereParameterTable[i];
    EXPECT_EQ(row.at("name"), p.name) << "row " << i << ": the table's order";
    if (p.member != nullptr) {
      ASSERT_TRUE(members.contains(row.at("member"))) << row.at("member");
      EXPECT_TRUE(members.at(row.at("member")) == p.member) << p.name;
    } else {
      EXPECT_EQ(row.at("member"), "ground_albedo");
    }
    EXPECT_EQ(testing::unit_of(row.at("unit")), p.unit) << p.name;
    if (p.has_numeric_default()) {
      EXPECT_TRUE(matches_as_written(testing::number_of(row.at("default")),
                                     testing::decimals_of(row.at("default")), p.default_value))
          << p.name << ": " << row.at("default");
    } else {
      EXPECT_EQ(row.at("default"), p.default_text) << p.name;
    }
    const auto range = range_of(row.at("range"));
    ASSERT_TRUE(range) << p.name << ": " << row.at("range");
    EXPECT_TRUE(matches_as_written(range->min, range->min_decimals, p.min_value)) << p.name;
    EXPECT_TRUE(matches_as_written(range->max, range->max_decimals, p.max_value)) << p.name;
    EXPECT_EQ(range->min_exclusive, p.min_exclusive) << p.name;
    EXPECT_EQ(range->max_exclusive, p.max_exclusive) << p.name;
  }
}

INSTANTIATE_TEST_SUITE_P(Files, AtmosphereParameterDocumentation,
                         ::testing::Values("models/atmosphere/atmosphere_parameters.h",
                                           "docs/model-contract.md"));

}  // namespace
}  // namespace clearsky
