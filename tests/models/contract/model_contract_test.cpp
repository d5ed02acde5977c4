// The SkyModel contract (docs/model-contract.md), checked on every model of the registry: a
// model registered later is covered without any test code. Each model is built once, cheaply:
// a 3-wavelength grid and the cheap settings below for the options a descriptor lists (by
// option name, so that a new model sharing an option name shares its cheap value; a model with
// other options runs with its defaults).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <regex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "models/atmosphere/atmosphere_parameter_table.h"
#include "models/core/fit_domain.h"
#include "models/core/invalid_input.h"
#include "models/core/numeric.h"
#include "models/registry.h"
#include "tests/models/support/cheap_model_config.h"
#include "tests/models/support/parameter_table_text.h"
#include "tests/support/model_queries.h"

namespace clearsky {
namespace {

using testing::cheap_config;
using testing::cheap_model;
using testing::cheap_options;

std::vector<const ModelFactory*> registered() { return testing::registered_factories(); }

double deg(double degrees) { return degrees_to_radians(degrees); }

// The declared domain, sampled: suns from the zenith to the largest declared zenith, views over
// every answered direction, altitudes over the declared range.
std::vector<double> sun_zeniths_deg(const ModelCapabilities& c) {
  std::vector<double> z = {0.0, 30.0, 60.0, 85.0};
  if (c.max_sun_zenith_deg >= 90.0) z.push_back(90.0);
  if (c.max_sun_zenith_deg > 95.0) z.push_back(95.0);
  z.push_back(c.max_sun_zenith_deg);
  return z;
}

std::vector<ViewDirection> domain_views(const ModelCapabilities& c) {
  std::vector<ViewDirection> views;
  const double last = c.view_below_horizon ? 180.0 : 90.0;
  for (double z = 0.0; z <= last + 1e-9; z += 15.0)
    for (double a = 0.0; a < 360.0; a += 45.0) views.push_back({deg(z), deg(a)});
  views.push_back({deg(89.9), deg(10.0)});
  return views;
}

std::vector<double> altitudes_m(const ModelCapabilities& c) {
  std::vector<double> h = {c.min_altitude_m};
  if (c.max_altitude_m > c.min_altitude_m) {
    for (double x : {1000.0, 30e3, 100e3, 3.6e7})
      if (x > c.min_altitude_m && x < c.max_altitude_m) h.push_back(x);
    h.push_back(c.max_altitude_m);
  }
  return h;
}

class ModelContract : public ::testing::TestWithParam<const ModelFactory*> {
 protected:
  const ModelFactory& factory() const { return *GetParam(); }
  const ModelDescriptor& declared() const { return *factory().descriptor; }
  const SkyModel& model() const { return *cheap_model(factory()); }
};

TEST_P(ModelContract, DescriptorIsComplete) {
  const ModelDescriptor& d = declared();
  EXPECT_TRUE(std::regex_match(d.id, std::regex("[a-z][a-z0-9_]*"))) << d.id;
  EXPECT_EQ(find_model(d.id), &factory());
  EXPECT_FALSE(d.name.empty());
  EXPECT_FALSE(d.version.empty()) << "part of every cache key";
  EXPECT_FALSE(d.citation.empty());
  EXPECT_FALSE(d.summary.empty());
  EXPECT_TRUE(std::isfinite(d.min_wavelength_nm) && d.min_wavelength_nm >= 0.0);
  EXPECT_LT(d.min_wavelength_nm, d.max_wavelength_nm);
  EXPECT_TRUE(std::is_sorted(d.native_wavelengths_nm.begin(), d.native_wavelengths_nm.end()));
  for (double w : d.native_wavelengths_nm) {
    EXPECT_GE(w, d.min_wavelength_nm - 1e-9);
    EXPECT_LE(w, d.max_wavelength_nm + 1e-9);
  }
  std::set<std::string> names;
  for (const ParameterSpec& p : d.parameters) {
    EXPECT_TRUE(names.insert(p.name).second) << p.name << " declared twice";
    EXPECT_TRUE(std::isfinite(p.min_value) && std::isfinite(p.max_value)) << p.name;
    EXPECT_LE(p.min_value, p.max_value) << p.name;
    EXPECT_FALSE(p.description.empty()) << p.name;
    const AtmosphereParameterInfo* shared = find_atmosphere_parameter(p.name);
    EXPECT_EQ(p.atmosphere, shared != nullptr)
        << p.name << ": atmosphere entries are exactly the table's names";
    if (shared != nullptr) {
      // Declared once: everything but a narrowed range comes from the table.
      EXPECT_EQ(p.unit, shared->unit) << p.name;
      EXPECT_EQ(p.description, shared->description) << p.name;
      EXPECT_FALSE(p.integer) << p.name;
      EXPECT_TRUE(shared->in_range(p.min_value) && shared->in_range(p.max_value)) << p.name;
      if (!shared->has_numeric_default()) {
        EXPECT_TRUE(std::isnan(p.default_value)) << p.name << ": its default is not a number";
        continue;
      }
      EXPECT_EQ(p.default_value, shared->default_value) << p.name;
    }
    EXPECT_GE(p.default_value, p.min_value) << p.name;
    EXPECT_LE(p.default_value, p.max_value) << p.name;
    if (p.integer) {
      for (double v : {p.default_value, p.min_value, p.max_value})
        EXPECT_EQ(v, std::floor(v)) << p.name;
    }
  }
  const ModelCapabilities& c = d.capabilities;
  EXPECT_TRUE(std::isfinite(c.min_altitude_m) && std::isfinite(c.max_altitude_m));
  EXPECT_LE(c.min_altitude_m, c.max_altitude_m);
  EXPECT_GE(c.max_sun_zenith_deg, 0.0);
  EXPECT_LE(c.max_sun_zenith_deg, 180.0);
  EXPECT_TRUE(c.scattering_orders == -1 || c.scattering_orders >= 1);
  const AtmosphereParameters atmosphere;
  const double top_m = atmosphere.top_radius_m - atmosphere.earth_radius_m;
  // Views from space: observers above the top of the atmosphere, and views downwards to it.
  EXPECT_EQ(c.view_from_space, c.max_altitude_m > top_m);
  if (c.view_from_space) {
    EXPECT_TRUE(c.view_below_horizon);
  }
  if (c.aerial_perspective) {
    EXPECT_TRUE(c.view_below_horizon) << "points on the ground";
  }
}

TEST_P(ModelContract, DocumentedParameterTableMatchesTheDescriptor) {
  // The table for people: the model header's comment table, else its README's.
  const ModelDescriptor& d = declared();
  const auto folder = testing::source_root() / "models" / d.id;
  std::vector<testing::TableRow> rows =
      testing::read_table(testing::read_text(folder / (d.id + ".h")), "parameter");
  if (rows.empty())
    rows = testing::read_table(testing::read_text(folder / "README.md"), "parameter");
  ASSERT_FALSE(rows.empty()) << "no parameter table in " << folder;
  std::set<std::string> documented;
  for (const testing::TableRow& row : rows) {
    const std::string& name = row.at("parameter");
    documented.insert(name);
    const ParameterSpec* p = d.find_parameter(name);
    ASSERT_NE(p, nullptr) << name << " is documented but not declared";
    EXPECT_EQ(testing::unit_of(row.at("unit")), p->unit) << name;
    const std::string& written_default = row.at("default");
    if (std::isnan(p->default_value)) {
      EXPECT_EQ(written_default, find_atmosphere_parameter(name)->default_text) << name;
    } else {
      EXPECT_TRUE(testing::matches_as_written(testing::number_of(written_default),
                                              testing::decimals_of(written_default),
                                              p->default_value))
          << name << ": documented " << written_default << ", declared " << p->default_value;
    }
    const auto range = testing::range_of(row.at("range"));
    ASSERT_TRUE(range) << name << ": " << row.at("range");
    EXPECT_TRUE(testing::matches_as_written(range->min, range->min_decimals, p->min_value))
        << name << ": documented min " << range->min << ", declared " << p->min_value;
    EXPECT_TRUE(testing::matches_as_written(range->max, range->max_decimals, p->max_value))
        << name << ": documented max " << range->max << ", declared " << p->max_value;
    EXPECT_FALSE(range->min_exclusive || range->max_exclusive) << name << ": inclusive ranges";
    if (row.at("range").find('{') != std::string::npos) {
      EXPECT_TRUE(p->integer) << name;
    }
  }
  for (const ParameterSpec& p : d.parameters)
    EXPECT_TRUE(documented.contains(p.name)) << p.name << " is declared but not documented";
}

TEST_P(ModelContract, FactoryValidatesEveryParameterByName) {
  const ModelDescriptor& d = declared();
  const auto expect_refused = [&](const ModelConfig& config, const std::string& field) {
    try {
      factory().create(config, {});
      ADD_FAILURE() << field << " accepted";
    } catch (const InvalidInput& e) {
      EXPECT_EQ(e.field(), field) << e.what();
    }
  };
  for (const ParameterSpec& p : d.parameters) {
    for (double bad :
         {p.min_value - 1.0, p.max_value + 1.0, std::numeric_limits<double>::quiet_NaN()}) {
      ModelConfig config = cheap_config(d);
      if (p.atmosphere) {
        set_atmosphere_parameter(config.atmosphere, p.name, bad);
      } else {
        config.options[p.name] = bad;
      }
      expect_refused(config, p.name);
    }
    if (p.integer && p.max_value > p.min_value) {
      ModelConfig config = cheap_config(d);
      config.options[p.name] = p.min_value + 0.5;
      expect_refused(config, p.name);
    }
  }
  ModelConfig unknown = cheap_config(d);
  unknown.options["no_such_option"] = 1.0;
  expect_refused(unknown, "no_such_option");
}

TEST_P(ModelContract, BuildsWhatItDeclares) {
  const SkyModel& m = model();
  EXPECT_EQ(m.descriptor().id, declared().id);
  EXPECT_EQ(m.descriptor().parameters.size(), declared().parameters.size());
  EXPECT_EQ(m.config().canonical_string(), cheap_config(declared()).canonical_string());
  for (std::size_t i = 0; i < m.wavelengths().size(); ++i) EXPECT_TRUE(m.answers_wavelength(i));
}

// The server admits a build against its table memory on the factory's estimate
// (server/tables/table_store.h), so the estimate must be the built tables' size: within 10% on
// two cheap configurations (the contract's, and 7 wavelengths), exactly 0 for a model without
// tables; an invalid configuration is refused like the build refuses it.
TEST_P(ModelContract, EstimatesItsTableBytesBeforeBuilding) {
  ASSERT_NE(factory().estimate_table_bytes, nullptr) << declared().id;
  ModelConfig seven = cheap_config(declared());
  seven.wavelengths = WavelengthGrid::points({400.0, 440.0, 500.0, 550.0, 600.0, 650.0, 700.0});
  const std::shared_ptr<const SkyModel> on_seven = factory().create(seven, {});
  for (const auto& [config, built] :
       {std::pair{cheap_config(declared()), &model()}, std::pair{seven, on_seven.get()}}) {
    SCOPED_TRACE(config.canonical_string());
    const std::size_t estimate = factory().estimate_table_bytes(config);
    const std::size_t bytes = built->table_bytes();
    if (bytes == 0) {
      EXPECT_EQ(estimate, 0u);
    } else {
      EXPECT_NEAR(static_cast<double>(estimate), static_cast<double>(bytes),
                  0.10 * static_cast<double>(bytes));
    }
  }
  ModelConfig unknown = cheap_config(declared());
  unknown.options["no_such_option"] = 1.0;
  EXPECT_THROW(factory().estimate_table_bytes(unknown), std::invalid_argument);
}

TEST_P(ModelContract, DeclaredRefusalsHappen) {
  const SkyModel& m = model();
  const ModelCapabilities& c = m.descriptor().capabilities;
  const std::vector<ViewDirection> up = {{deg(30.0), deg(40.0)}};
  SpectralBatch out;
  // The sun beyond the declared zenith: refused by check_sun, prepare_sun and every query.
  if (c.max_sun_zenith_deg < 180.0) {
    const SunPosition low{deg(std::min(c.max_sun_zenith_deg + 1.0, 180.0)), 0.0};
    EXPECT_EQ(m.check_sun(low), SampleStatus::sun_below_horizon_unsupported);
    try {
      m.prepare_sun(low);
      ADD_FAILURE() << "prepare_sun accepted a refused sun";
    } catch (const InvalidInput& e) {
      EXPECT_EQ(e.field(), "sun_zenith");
    }
    const SunState unprepared(low);
    m.sky_radiance(unprepared, {c.min_altitude_m}, up, out);
    EXPECT_EQ(out.status[0], SampleStatus::sun_below_horizon_unsupported);
    EXPECT_EQ(m.sun_irradiance(unprepared, {c.min_altitude_m}).status,
              SampleStatus::sun_below_horizon_unsupported);
    EXPECT_EQ(m.sky_irradiance(unprepared, {c.min_altitude_m}).status,
              SampleStatus::sun_below_horizon_unsupported);
  }
  const auto sun = m.prepare_sun({deg(40.0), deg(10.0)});
  // Views below the horizon, where not supported.
  const std::vector<ViewDirection> down = {{deg(120.0), 0.0}, {deg(30.0), 0.0}};
  m.sky_radiance(*sun, {c.min_altitude_m}, down, out);
  EXPECT_EQ(out.status[0],
            c.view_below_horizon ? SampleStatus::ok : SampleStatus::view_below_horizon_unsupported);
  EXPECT_EQ(out.status[1], SampleStatus::ok) << "one refused view does not refuse the batch";
  // Observers outside the declared altitudes.
  for (double altitude :
       {c.min_altitude_m - 1.0, c.max_altitude_m + 1.0 + 1e-3 * std::abs(c.max_altitude_m)}) {
    m.sky_radiance(*sun, {altitude}, up, out);
    EXPECT_EQ(out.status[0], SampleStatus::viewpoint_unsupported) << altitude;
    EXPECT_EQ(m.sun_irradiance(*sun, {altitude}).status, SampleStatus::viewpoint_unsupported);
    EXPECT_EQ(m.sky_irradiance(*sun, {altitude}).status, SampleStatus::viewpoint_unsupported);
  }
  // Inputs that are not angles.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<ViewDirection> broken = {{nan, 0.0}, {deg(200.0), 0.0}};
  m.sky_radiance(*sun, {c.min_altitude_m}, broken, out);
  EXPECT_EQ(out.status[0], SampleStatus::invalid_input);
  EXPECT_EQ(out.status[1], SampleStatus::invalid_input);
  EXPECT_EQ(m.check_sun({nan, 0.0}), SampleStatus::invalid_input);
  // Aerial perspective only where declared.
  const auto ap = m.aerial_perspective(*sun, {c.min_altitude_m}, up[0], 1000.0);
  EXPECT_EQ(ap.status, c.aerial_perspective ? SampleStatus::ok : SampleStatus::invalid_input);
  if (c.aerial_perspective) {
    for (double t : ap.transmittance) EXPECT_TRUE(t >= 0.0 && t <= 1.0) << t;
    EXPECT_EQ(m.aerial_perspective(*sun, {c.min_altitude_m}, up[0], -1.0).status,
              SampleStatus::invalid_input);
  }
}

TEST_P(ModelContract, WavelengthsOutsideTheRangeAreNotAnswered) {
  // A grid reaching outside the declared spectral range is either refused when the model is
  // built (InvalidInput naming "wavelengths") or built with those wavelengths unanswered (0).
  const ModelDescriptor& d = declared();
  std::vector<double> outside;
  if (d.min_wavelength_nm > 20.0) outside.push_back(d.min_wavelength_nm - 10.0);
  if (std::isfinite(d.max_wavelength_nm)) outside.push_back(d.max_wavelength_nm + 10.0);
  ASSERT_FALSE(outside.empty()) << "a model must declare a finite spectral range";
  for (double w : outside) {
    ModelConfig config = cheap_config(d);
    std::vector<double> nm = {w, 550.0};
    std::sort(nm.begin(), nm.end());
    config.wavelengths = WavelengthGrid::points(nm);
    std::shared_ptr<const SkyModel> m;
    try {
      m = factory().create(config, {});
    } catch (const InvalidInput& e) {
      EXPECT_EQ(e.field(), "wavelengths") << e.what();
      continue;
    }
    const std::size_t out_index = nm[0] == w ? 0 : 1;
    EXPECT_FALSE(m->answers_wavelength(out_index)) << w;
    EXPECT_TRUE(m->answers_wavelength(1 - out_index));
    const auto sun = m->prepare_sun({deg(30.0), 0.0});
    SpectralBatch out;
    m->sky_radiance(*sun, {d.capabilities.min_altitude_m}, std::vector<ViewDirection>{{0.5, 1.0}},
                    out);
    ASSERT_EQ(out.status[0], SampleStatus::ok);
    EXPECT_EQ(out.spectrum(0)[out_index], 0.0) << w;
    EXPECT_GT(out.spectrum(0)[1 - out_index], 0.0);
  }
}

TEST_P(ModelContract, AnswersEverywhereInsideTheDeclaredDomain) {
  const SkyModel& m = model();
  const ModelCapabilities& c = m.descriptor().capabilities;
  const std::vector<ViewDirection> views = domain_views(c);
  for (double sun_zenith : sun_zeniths_deg(c)) {
    const auto sun = m.prepare_sun({deg(sun_zenith), deg(70.0)});
    for (double altitude : altitudes_m(c)) {
      SpectralBatch out;
      m.sky_radiance(*sun, {altitude}, views, out);
      double largest = 0.0;
      for (std::size_t i = 0; i < views.size(); ++i) {
        ASSERT_EQ(out.status[i], SampleStatus::ok)
            << "sun " << sun_zenith << " altitude " << altitude << " view "
            << radians_to_degrees(views[i].zenith_rad) << ", "
            << radians_to_degrees(views[i].azimuth_rad) << ": " << describe(out.status[i]);
        for (double v : out.spectrum(i)) {
          ASSERT_TRUE(std::isfinite(v) && v >= 0.0) << v;
          largest = std::max(largest, v);
        }
      }
      // A sky lit by a sun above the horizon is not black (from space, Earth's day side).
      if (sun_zenith < 85.0 && altitude <= 30e3) {
        EXPECT_GT(largest, 0.0) << sun_zenith;
      }
      for (const SpectralSample& s :
           {m.sun_irradiance(*sun, {altitude}), m.sky_irradiance(*sun, {altitude})}) {
        ASSERT_EQ(s.status, SampleStatus::ok) << "sun " << sun_zenith << " altitude " << altitude;
        for (double v : s.value) ASSERT_TRUE(std::isfinite(v) && v >= 0.0) << v;
      }
    }
  }
}

TEST_P(ModelContract, SymmetricAboutTheSunsVerticalPlane) {
  // Every model's atmosphere is horizontally uniform, so views at sun azimuth + d and - d see
  // the same sky. The two directions differ only by the rounding of the azimuths (1e-16 rad);
  // tables stored in float (Bruneton, Elek) interpolate that into differences of a few float
  // ulps, hence 1e-6 relative (float epsilon 1.2e-7 times a few interpolation weights).
  const SkyModel& m = model();
  const ModelCapabilities& c = m.descriptor().capabilities;
  const double sun_azimuth = 123.0;
  std::vector<ViewDirection> views;
  const double last = c.view_below_horizon ? 175.0 : 89.0;
  for (double zenith = 5.0; zenith <= last; zenith += 12.0) {
    for (double offset : {7.0, 45.0, 100.0, 170.0}) {
      views.push_back({deg(zenith), deg(sun_azimuth + offset)});
      views.push_back({deg(zenith), deg(sun_azimuth - offset)});
    }
  }
  for (double sun_zenith : {20.0, 70.0}) {
    const auto sun = m.prepare_sun({deg(sun_zenith), deg(sun_azimuth)});
    for (double altitude : altitudes_m(c)) {
      SpectralBatch out;
      m.sky_radiance(*sun, {altitude}, views, out);
      for (std::size_t i = 0; i < views.size(); i += 2) {
        ASSERT_EQ(out.status[i], SampleStatus::ok);
        ASSERT_EQ(out.status[i + 1], SampleStatus::ok);
        for (std::size_t w = 0; w < out.wavelength_count; ++w) {
          const double a = out.spectrum(i)[w], b = out.spectrum(i + 1)[w];
          EXPECT_LE(std::abs(a - b), 1e-6 * std::max(std::abs(a), std::abs(b)))
              << "sun " << sun_zenith << " altitude " << altitude << " view "
              << radians_to_degrees(views[i].zenith_rad) << " +-"
              << radians_to_degrees(views[i].azimuth_rad) - sun_azimuth;
        }
      }
    }
  }
}

// All the answers of one model for a few suns, in a fixed order.
std::vector<double> answers(const SkyModel& m, const std::vector<double>& sun_zeniths) {
  const ModelCapabilities& c = m.descriptor().capabilities;
  const std::vector<ViewDirection> views = domain_views(c);
  std::vector<double> all;
  for (double sun_zenith : sun_zeniths) {
    const auto sun = m.prepare_sun({deg(sun_zenith), deg(200.0)});
    SpectralBatch out;
    m.sky_radiance(*sun, {c.min_altitude_m}, views, out);
    all.insert(all.end(), out.values.begin(), out.values.end());
    for (SampleStatus s : out.status) all.push_back(static_cast<double>(s));
    const SpectralSample direct = m.sun_irradiance(*sun, {c.min_altitude_m});
    const SpectralSample diffuse = m.sky_irradiance(*sun, {c.min_altitude_m});
    all.insert(all.end(), direct.value.begin(), direct.value.end());
    all.insert(all.end(), diffuse.value.begin(), diffuse.value.end());
  }
  return all;
}

TEST_P(ModelContract, ConcurrentQueriesAnswerLikeSerialOnes) {
  // Several threads query one model (and, for per-sun models, prepare the same suns at once
  // through the model's shared cache); every answer is bit-identical to the serial one.
  const std::vector<double> suns = {25.0, 55.0, 80.0};
  const std::shared_ptr<const SkyModel> fresh = factory().create(cheap_config(declared()), {});
  constexpr int kThreads = 4;
  std::vector<std::vector<double>> concurrent(kThreads);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] { concurrent[t] = answers(*fresh, suns); });
  for (std::thread& t : threads) t.join();
  const std::vector<double> serial = answers(model(), suns);
  for (int t = 0; t < kThreads; ++t) {
    ASSERT_EQ(concurrent[t].size(), serial.size());
    std::size_t differing = 0;
    for (std::size_t i = 0; i < serial.size(); ++i) differing += concurrent[t][i] != serial[i];
    EXPECT_EQ(differing, 0u) << "thread " << t;
  }
}

using testing::irradiance_tolerance;

TEST_P(ModelContract, SkyIrradianceIsTheIntegralOfItsRadiance) {
  const SkyModel& m = model();
  const double tolerance = irradiance_tolerance(m);
  for (double sun_zenith : {20.0, 50.0, 75.0}) {
    const auto sun = m.prepare_sun({deg(sun_zenith), deg(160.0)});
    const SpectralSample e = m.sky_irradiance(*sun, {m.descriptor().capabilities.min_altitude_m});
    ASSERT_EQ(e.status, SampleStatus::ok);
    const Spectrum reference = testing::reference_sky_irradiance(m, *sun, 64, 128);
    for (std::size_t w = 0; w < reference.size(); ++w) {
      ASSERT_GT(reference[w], 0.0);
      EXPECT_NEAR(e.value[w] / reference[w], 1.0, tolerance)
          << "sun " << sun_zenith << " wavelength " << m.wavelengths()[w];
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Registered, ModelContract, ::testing::ValuesIn(registered()),
                         [](const ::testing::TestParamInfo<const ModelFactory*>& param) {
                           return param.param->descriptor->id;
                         });

}  // namespace
}  // namespace clearsky
