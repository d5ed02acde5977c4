// The reduced stress run of every registered model (docs/stability.md): a few dozen points per
// sweep, the minimum and maximum of each atmosphere parameter, the aerosol trends, the cheap
// tables of the contract suite. A
// model added to the registry is covered without test code. It must deliver no non-finite or
// negative value, refuse only what its descriptor declares, and pass the symmetry, energy,
// radiance and trend checks.
#include "models/stress/model_stress.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "models/stress/documented_limits.h"
#include "tests/models/support/cheap_model_config.h"

namespace clearsky::stress {
namespace {

class ReducedStress : public ::testing::TestWithParam<const ModelFactory*> {};

// One test per model (CTest runs each test in its own process: one reduced run each).
TEST_P(ReducedStress, FindsNothingUndeclared) {
  StressOptions options;
  options.max_points_per_sweep = 24;
  options.parameter_values = 2;
  // The model's own options (table sizes, scattering orders: costly builds) are swept by the
  // full run (docs/stability.md); here the atmosphere parameters.
  options.sweep_options = false;
  options.options = testing::cheap_options();
  options.precompute_threads = 1;
  const ModelStressReport r = stress_model(*GetParam(), options);
  // Only finite, non-negative values and declared refusals.
  EXPECT_GT(r.samples, 300u);
  EXPECT_EQ(r.non_finite_values, 0u);
  EXPECT_EQ(r.negative_values, 0u);
  for (const auto& [status, tally] : r.refusals)
    EXPECT_EQ(tally.undeclared, 0u)
        << to_string(status) << " first at " << tally.first_undeclared_at;
  // The symmetry, energy, radiance and trend checks.
  // (Within the documented limits of documented_limits.h, each explained in a README.)
  for (const BoundCheck* check : {&r.symmetry, &r.energy, &r.radiance_below_sun}) {
    EXPECT_GT(check->checked, 0u) << check->name;
    EXPECT_FALSE(failed(*check)) << check->name << ": worst " << check->worst << " at "
                                 << check->worst_at;
  }
  for (const BoundCheck& trend : r.trends)
    EXPECT_FALSE(failed(trend)) << trend.name << ": worst " << trend.worst << " at "
                                << trend.worst_at;
  EXPECT_TRUE(stress_passed(r));
  // Every coordinate the descriptor declares is swept.
  const ModelDescriptor& d = *GetParam()->descriptor;
  std::set<std::string> coordinates;
  for (const SweepSummary& s : r.sweeps) coordinates.insert(s.coordinate);
  for (const char* c : {"sun_zenith_deg", "view_zenith_deg", "azimuth_offset_deg"})
    EXPECT_TRUE(coordinates.count(c)) << c;
  EXPECT_EQ(coordinates.count("altitude_m") == 1,
            d.capabilities.max_altitude_m > d.capabilities.min_altitude_m);
  for (const ParameterSpec& p : d.parameters) {
    if (p.atmosphere) {
      EXPECT_TRUE(coordinates.count(p.name)) << p.name;
    }
  }
  if (d.find_parameter("beta") != nullptr || d.find_parameter("turbidity") != nullptr) {
    EXPECT_FALSE(r.trends.empty());
  }
}

// A model that precomputes per sun runs one state per sun for both the radiance and the
// irradiance of the sun sweep; --sweeps runs only the sweeps named.
TEST(SunSweepOfPerSunModels, OneStatePerSunServesRadianceAndIrradianceAndOnlyTheNamedSweepsRun) {
  const ModelFactory* nishita96 = nullptr;
  for (const ModelFactory* f : testing::registered_factories())
    if (f->descriptor->id == "nishita96") nishita96 = f;
  ASSERT_NE(nishita96, nullptr);
  StressOptions options;
  options.options = testing::cheap_options();
  options.precompute_threads = 1;
  options.sweeps = {"sun_zenith"};
  options.dense_per_sun_zeniths = true;
  options.max_points_per_sweep = 24;
  const ModelStressReport r = stress_model(*nishita96, options);
  std::size_t radiance_points = 0, irradiance_points = 0;
  for (const SweepSummary& s : r.sweeps) {
    EXPECT_EQ(s.coordinate, "sun_zenith_deg") << s.name;
    if (s.name == "sun_zenith_deg") radiance_points = s.points;
    if (s.name == "sun_zenith_deg irradiance") irradiance_points = s.points;
  }
  EXPECT_EQ(radiance_points, 24u);
  EXPECT_EQ(irradiance_points, radiance_points);
  EXPECT_EQ(r.non_finite_values, 0u);
  EXPECT_EQ(r.negative_values, 0u);
  EXPECT_TRUE(stress_passed(r));
}

INSTANTIATE_TEST_SUITE_P(Registered, ReducedStress,
                         ::testing::ValuesIn(testing::registered_factories()),
                         [](const ::testing::TestParamInfo<const ModelFactory*>& param) {
                           return param.param->descriptor->id;
                         });

}  // namespace
}  // namespace clearsky::stress
