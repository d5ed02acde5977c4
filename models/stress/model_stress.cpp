// The stress run of one model (model_stress.h).
#include "models/stress/model_stress.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <memory>
#include <sstream>

#include "models/atmosphere/atmosphere_parameter_table.h"
#include "models/core/fit_domain.h"
#include "models/core/invalid_input.h"
#include "models/core/numeric.h"
#include "models/measured_aerosols/aerosol_inversion_source.h"
#include "models/stress/documented_jumps.h"
#include "models/stress/documented_limits.h"
#include "models/stress/domain_sweeps.h"
#include "models/stress/neighbour_jumps.h"

namespace clearsky::stress {

namespace {

constexpr double kBaseSunZenithDeg = 30.0;
constexpr double kSunAzimuthDeg = 180.0;
// Apparent angular radius of the sun (models/solar/solar_position.cpp): the sun's radiance is
// its extraterrestrial irradiance over the solid angle of its disc.
constexpr double kSunAngularRadiusDeg = 0.26667;
// The sky irradiance (a quadrature of the radiance) is followed along the sun sweep every
// this many degrees.
constexpr double kIrradianceSunStepDeg = 0.5;

// A probe view: zenith and azimuth offset from the sun, degrees.
struct Probe {
  double zenith_deg = 0;
  double offset_deg = 0;
};

std::string probe_name(const Probe& p) {
  std::ostringstream out;
  out << "view_zenith_deg=" << p.zenith_deg << " azimuth_offset_deg=" << p.offset_deg;
  return out.str();
}

ViewDirection view_of(const Probe& p) {
  return {degrees_to_radians(p.zenith_deg), degrees_to_radians(kSunAzimuthDeg + p.offset_deg)};
}

// The probes of the sun, altitude and parameter sweeps: the zenith, towards and away from the
// sun, across it near the horizon, and just above the horizon towards the sun; views below
// the horizon for the models that answer them.
std::vector<Probe> probes(const ModelCapabilities& caps) {
  std::vector<Probe> out = {{0, 0}, {45, 0}, {45, 180}, {85, 90}, {89.5, 0}};
  if (caps.view_below_horizon) {
    out.push_back({95, 0});
    out.push_back({180, 0});
  }
  return out;
}

std::vector<ViewDirection> views_of(const std::vector<Probe>& ps) {
  std::vector<ViewDirection> out;
  for (const Probe& p : ps) out.push_back(view_of(p));
  return out;
}

class ModelStress {
 public:
  ModelStress(const ModelFactory& factory, const StressOptions& options)
      : factory_(factory), options_(options) {}

  ModelStressReport run() {
    const auto start = std::chrono::steady_clock::now();
    const ModelDescriptor& d = *factory_.descriptor;
    report_.model = d.id;
    report_.version = d.version;
    report_.symmetry = {.name = "symmetry",
                        .bound =
                            "views mirrored about the sun's vertical plane differ by at "
                            "most 1e-6 relative"};
    report_.energy = {.name = "energy",
                      .bound =
                          "(1 - ground albedo) x (sky + direct irradiance on the "
                          "horizontal) at most the extraterrestrial irradiance on it (suns "
                          "up to 85 degrees)"};
    report_.radiance_below_sun = {.name = "radiance_below_sun",
                                  .bound =
                                      "sky radiance at most the sun's (extraterrestrial "
                                      "irradiance over the solid angle of the disc)"};
    base_ = base_config();
    report_.wavelengths_nm = base_.wavelengths.nanometres();
    report_.options = base_.options;
    const std::shared_ptr<const SkyModel> model = build(base_, "base configuration");
    if (model) {
      if (runs("sun_zenith")) sweep_sun_zenith(*model);
      if (runs("view_zenith")) sweep_view_zenith(*model);
      if (runs("view_azimuth")) sweep_view_azimuth(*model);
      if (runs("altitude")) sweep_altitude(*model);
    }
    if (runs("parameters"))
      for (const ParameterSpec& p : d.parameters)
        // An option naming stored data (measured_aerosols' aerosols, an uploaded inversion's
        // id) is no quantity to sweep: most ids name nothing.
        if ((p.atmosphere || options_.sweep_options) && p.name != kAerosolsOption)
          sweep_parameter(p);
    if (model) {
      for (BoundCheck* check : {&report_.symmetry, &report_.energy, &report_.radiance_below_sun})
        apply_documented_limit(*model, *check);
      for (BoundCheck& check : report_.trends) apply_documented_limit(*model, check);
    }
    report_.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return std::move(report_);
  }

 private:
  ModelConfig base_config() const {
    const ModelDescriptor& d = *factory_.descriptor;
    ModelConfig config;
    config.wavelengths = WavelengthGrid::points({d.min_wavelength_nm, 550.0, d.max_wavelength_nm});
    for (const auto& [name, value] : options_.options)
      if (const ParameterSpec* p = d.find_parameter(name); p != nullptr && !p->atmosphere)
        config.options[name] = value;
    return config;
  }

  // Builds config; a refusal is an undeclared refusal, except one naming swept_parameter (a
  // constraint a range cannot express, such as an odd table size: docs/model-contract.md),
  // which is declared and returns nullptr for the caller to try a neighbouring value.
  std::shared_ptr<const SkyModel> build(const ModelConfig& config, const std::string& where,
                                        const std::string& swept_parameter = "") {
    PrecomputeContext context;
    context.threads = options_.precompute_threads;
    try {
      ++report_.models_built;
      return factory_.create(config, context);
    } catch (const InvalidInput& e) {
      RefusalTally& tally = report_.refusals[SampleStatus::invalid_input];
      ++report_.samples;
      if (!swept_parameter.empty() && e.field() == swept_parameter) {
        ++tally.declared;
      } else if (tally.undeclared++ == 0) {
        tally.first_undeclared_at = where + ": " + e.what();
      }
      return nullptr;
    } catch (const std::exception& e) {
      // A configuration inside the declared ranges that cannot be built is an undeclared
      // refusal.
      RefusalTally& tally = report_.refusals[SampleStatus::invalid_input];
      ++report_.samples;
      if (tally.undeclared++ == 0) tally.first_undeclared_at = where + ": " + e.what();
      return nullptr;
    }
  }

  std::string location(double sun_zenith_deg, double altitude_m, const Probe* probe) const {
    std::ostringstream out;
    out.precision(10);
    if (!configuration_.empty()) out << configuration_ << ' ';
    out << "sun_zenith_deg=" << sun_zenith_deg << " altitude_m=" << altitude_m;
    if (probe != nullptr) out << ' ' << probe_name(*probe);
    return out.str();
  }

  // Whether the descriptor declares a refusal of this input (stress_report.h RefusalTally).
  static bool declared(const SkyModel& m, SampleStatus status, double sun_zenith_deg,
                       double altitude_m, const Probe* probe) {
    const ModelCapabilities& caps = m.descriptor().capabilities;
    switch (status) {
      case SampleStatus::sun_below_horizon_unsupported:
        return sun_zenith_deg > caps.max_sun_zenith_deg;
      case SampleStatus::viewpoint_unsupported:
        return altitude_m < caps.min_altitude_m || altitude_m > caps.max_altitude_m;
      case SampleStatus::view_below_horizon_unsupported:
        return probe != nullptr && probe->zenith_deg > 90.0 && !caps.view_below_horizon;
      case SampleStatus::outside_fit_domain:
        return m.descriptor().find_parameter(kClampNegativeFitOption) != nullptr &&
               option_or_default(m.descriptor(), m.config(), kClampNegativeFitOption) == 0.0;
      default:
        return false;
    }
  }

  // Counts one answer: its status, and the values that must never be delivered.
  void record(const SkyModel& m, SampleStatus status, std::span<const double> values,
              double sun_zenith_deg, double altitude_m, const Probe* probe) {
    ++report_.samples;
    if (status != SampleStatus::ok) {
      RefusalTally& tally = report_.refusals[status];
      if (declared(m, status, sun_zenith_deg, altitude_m, probe)) {
        ++tally.declared;
      } else if (tally.undeclared++ == 0) {
        tally.first_undeclared_at = location(sun_zenith_deg, altitude_m, probe);
      }
      return;
    }
    for (double v : values) {
      if (!std::isfinite(v)) ++report_.non_finite_values;
      if (v < 0.0) ++report_.negative_values;
    }
  }

  void check_radiance_bound(const SkyModel& m, std::span<const double> radiance,
                            double sun_zenith_deg, double altitude_m, const Probe& probe) {
    static const double sun_solid_angle_sr =
        2.0 * kPi * (1.0 - std::cos(degrees_to_radians(kSunAngularRadiusDeg)));
    for (std::size_t w = 0; w < radiance.size(); ++w) {
      if (!m.answers_wavelength(w)) continue;
      const double sun_radiance = m.atmosphere().solar_irradiance_w_m2_nm[w] / sun_solid_angle_sr;
      note(report_.radiance_below_sun, radiance[w] / sun_radiance,
           location(sun_zenith_deg, altitude_m, &probe));
    }
  }

  void check_energy(const SkyModel& m, const SpectralSample& direct, const SpectralSample& sky,
                    double sun_zenith_deg, double altitude_m) {
    if (direct.status != SampleStatus::ok || sky.status != SampleStatus::ok) return;
    if (!(sun_zenith_deg <= kEnergyCheckMaxSunZenithDeg)) return;
    // What the ground absorbs, (1 - albedo) of the downward irradiance, cannot exceed what
    // enters the atmosphere; models without a ground (no albedo parameter) absorb it all.
    const bool has_ground = m.descriptor().find_parameter("albedo") != nullptr;
    const double cos_sun = std::cos(degrees_to_radians(sun_zenith_deg));
    for (std::size_t w = 0; w < direct.value.size(); ++w) {
      if (!m.answers_wavelength(w)) continue;
      const double absorbed = has_ground ? 1.0 - m.atmosphere().ground_albedo[w] : 1.0;
      const double top = m.atmosphere().solar_irradiance_w_m2_nm[w] * cos_sun;
      note(report_.energy, absorbed * (sky.value[w] + direct.value[w] * cos_sun) / top,
           location(sun_zenith_deg, altitude_m, nullptr) +
               " wavelength_nm=" + std::to_string(report_.wavelengths_nm[w]));
    }
  }

  // A ratio to a bound of 1 (kBoundSlack of rounding allowed).
  static void note(BoundCheck& check, double ratio, const std::string& where) {
    ++check.checked;
    if (ratio > 1.0 + kBoundSlack && check.violations++ == 0) check.first_violation_at = where;
    if (ratio > check.worst) {
      check.worst = ratio;
      check.worst_at = where;
    }
  }

  // The radiance of the probes, recorded and checked; one chain point per probe.
  std::vector<ChainPoint> radiance(const SkyModel& m, const SunState& sun, double sun_zenith_deg,
                                   double altitude_m, const std::vector<Probe>& ps,
                                   double coordinate) {
    SpectralBatch batch;
    const std::vector<ViewDirection> views = views_of(ps);
    m.sky_radiance(sun, {altitude_m}, views, batch);
    std::vector<ChainPoint> out;
    for (std::size_t i = 0; i < ps.size(); ++i) {
      const auto values = batch.spectrum(i);
      record(m, batch.status[i], values, sun_zenith_deg, altitude_m, &ps[i]);
      ChainPoint point{coordinate, batch.status[i] == SampleStatus::ok, {}, batch.status[i]};
      if (point.answered) {
        point.values.assign(values.begin(), values.end());
        check_radiance_bound(m, values, sun_zenith_deg, altitude_m, ps[i]);
      }
      out.push_back(std::move(point));
    }
    return out;
  }

  ChainPoint irradiance_point(const SkyModel& m, const SpectralSample& s, double sun_zenith_deg,
                              double altitude_m, double coordinate) {
    record(m, s.status, s.value, sun_zenith_deg, altitude_m, nullptr);
    ChainPoint point{coordinate, s.status == SampleStatus::ok, {}, s.status};
    if (point.answered) point.values.assign(s.value.begin(), s.value.end());
    return point;
  }

  bool runs(const std::string& sweep) const {
    return options_.sweeps.empty() || options_.sweeps.contains(sweep);
  }

  std::shared_ptr<const SunState> sun_state(const SkyModel& m, double sun_zenith_deg) {
    PrecomputeContext context;
    context.threads = options_.precompute_threads;
    return m.prepare_sun({degrees_to_radians(sun_zenith_deg), degrees_to_radians(kSunAzimuthDeg)},
                         context);
  }

  void summarize(std::string name, std::string coordinate, const std::vector<Chain>& chains,
                 const SkyModel& m, double altitude_m) {
    SweepSummary summary{.name = std::move(name), .coordinate = std::move(coordinate)};
    const std::vector<DocumentedJump> documented =
        documented_jumps(m, summary.coordinate, altitude_m);
    summarize_jumps(chains, report_.wavelengths_nm, documented, summary);
    report_.sweeps.push_back(std::move(summary));
  }

  static std::vector<Chain> chains_named(const std::vector<Probe>& ps) {
    std::vector<Chain> chains;
    for (const Probe& p : ps) chains.push_back({probe_name(p), {}});
    return chains;
  }

  void sweep_sun_zenith(const SkyModel& m) {
    const ModelCapabilities& caps = m.descriptor().capabilities;
    const double altitude_m = caps.min_altitude_m;
    const std::vector<Probe> ps = probes(caps);
    std::vector<Chain> chains = chains_named(ps);
    chains.push_back({"sun_irradiance", {}});
    const std::vector<double> suns =
        thinned(swept_sun_zeniths_deg(caps.max_sun_zenith_deg, caps.per_sun_precomputation,
                                      options_.dense_per_sun_zeniths),
                options_.max_points_per_sweep);
    // The sky irradiance and the energy bound, on a coarser step (each is a quadrature), except
    // for models that precompute per sun: there the state is paid for already, so every sun.
    std::vector<Chain> irradiance = {{"sky_irradiance", {}}, {"global_irradiance", {}}};
    const std::vector<double> irradiance_suns =
        caps.per_sun_precomputation
            ? suns
            : thinned(steps_from_to(0.0, caps.max_sun_zenith_deg, kIrradianceSunStepDeg),
                      options_.max_points_per_sweep);
    std::size_t next_irradiance = 0;
    for (double sun_zenith : suns) {
      const auto sun = sun_state(m, sun_zenith);
      std::vector<ChainPoint> points = radiance(m, *sun, sun_zenith, altitude_m, ps, sun_zenith);
      for (std::size_t i = 0; i < ps.size(); ++i) chains[i].points.push_back(std::move(points[i]));
      chains.back().points.push_back(irradiance_point(m, m.sun_irradiance(*sun, {altitude_m}),
                                                      sun_zenith, altitude_m, sun_zenith));
      // One state per sun serves both sweeps of a per-sun model (a Nishita96 state costs
      // seconds).
      if (caps.per_sun_precomputation) {
        add_irradiance_point(m, *sun, sun_zenith, altitude_m, irradiance);
        ++next_irradiance;
      }
    }
    summarize("sun_zenith_deg", "sun_zenith_deg", chains, m, altitude_m);
    for (; next_irradiance < irradiance_suns.size(); ++next_irradiance) {
      const double sun_zenith = irradiance_suns[next_irradiance];
      add_irradiance_point(m, *sun_state(m, sun_zenith), sun_zenith, altitude_m, irradiance);
    }
    summarize("sun_zenith_deg irradiance", "sun_zenith_deg", irradiance, m, altitude_m);
  }

  // The sky and global irradiance of one sun, and the energy bound on them.
  void add_irradiance_point(const SkyModel& m, const SunState& sun, double sun_zenith,
                            double altitude_m, std::vector<Chain>& irradiance) {
    const SpectralSample direct = m.sun_irradiance(sun, {altitude_m});
    const SpectralSample sky = m.sky_irradiance(sun, {altitude_m});
    irradiance[0].points.push_back(irradiance_point(m, sky, sun_zenith, altitude_m, sun_zenith));
    ChainPoint global{sun_zenith, false, {}, SampleStatus::ok};
    if (direct.status == SampleStatus::ok && sky.status == SampleStatus::ok) {
      global.answered = true;
      const double cos_sun = std::max(0.0, std::cos(degrees_to_radians(sun_zenith)));
      for (std::size_t w = 0; w < sky.value.size(); ++w)
        global.values.push_back(sky.value[w] + direct.value[w] * cos_sun);
    }
    irradiance[1].points.push_back(std::move(global));
    check_energy(m, direct, sky, sun_zenith, altitude_m);
  }

  void sweep_view_zenith(const SkyModel& m) {
    const ModelCapabilities& caps = m.descriptor().capabilities;
    // Through the horizon: to the nadir where views below the horizon are answered, else one
    // degree past it (refusals declared).
    const double last = caps.view_below_horizon ? 180.0 : 91.0;
    const std::vector<double> zeniths =
        thinned(view_zeniths_deg(last), options_.max_points_per_sweep);
    std::vector<double> altitudes = {caps.min_altitude_m};
    if (caps.max_altitude_m >= 10e3 && caps.min_altitude_m < 10e3) altitudes.push_back(10e3);
    std::vector<double> suns = {kBaseSunZenithDeg};
    if (caps.max_sun_zenith_deg >= 85.0) suns.push_back(85.0);
    for (double altitude_m : altitudes) {
      for (double sun_zenith : suns) {
        const auto sun = sun_state(m, sun_zenith);
        std::vector<Chain> chains;
        for (double offset : {0.0, 90.0, 180.0}) {
          std::vector<Probe> ps;
          for (double z : zeniths) ps.push_back({z, offset});
          std::vector<ChainPoint> points = radiance(m, *sun, sun_zenith, altitude_m, ps, 0.0);
          for (std::size_t i = 0; i < ps.size(); ++i) points[i].coordinate = zeniths[i];
          std::ostringstream name;
          name << "azimuth_offset_deg=" << offset;
          chains.push_back({name.str(), std::move(points)});
        }
        std::ostringstream name;
        name << "view_zenith_deg sun_zenith_deg=" << sun_zenith << " altitude_m=" << altitude_m;
        summarize(name.str(), "view_zenith_deg", chains, m, altitude_m);
      }
    }
  }

  void sweep_view_azimuth(const SkyModel& m) {
    const ModelCapabilities& caps = m.descriptor().capabilities;
    const double altitude_m = caps.min_altitude_m;
    std::vector<double> offsets = azimuth_offsets_deg();
    // Thinned symmetrically, so that every offset keeps its mirror image.
    if (options_.max_points_per_sweep != 0 && offsets.size() > options_.max_points_per_sweep) {
      std::vector<double> half(offsets.begin(), offsets.begin() + offsets.size() / 2 + 1);
      half = thinned(half, options_.max_points_per_sweep / 2 + 1);
      offsets = half;
      for (auto it = half.rbegin(); it != half.rend(); ++it)
        if (*it > 0.0 && *it < 180.0) offsets.push_back(360.0 - *it);
    }
    std::vector<double> suns = {kBaseSunZenithDeg};
    if (caps.max_sun_zenith_deg >= 80.0) suns.push_back(80.0);
    for (double sun_zenith : suns) {
      const auto sun = sun_state(m, sun_zenith);
      std::vector<Chain> chains;
      for (double zenith : {45.0, 85.0}) {
        std::vector<Probe> ps;
        for (double a : offsets) ps.push_back({zenith, a});
        std::vector<ChainPoint> points = radiance(m, *sun, sun_zenith, altitude_m, ps, 0.0);
        for (std::size_t i = 0; i < ps.size(); ++i) points[i].coordinate = offsets[i];
        check_symmetry(points, offsets, sun_zenith, zenith);
        std::ostringstream name;
        name << "view_zenith_deg=" << zenith;
        chains.push_back({name.str(), std::move(points)});
      }
      std::ostringstream name;
      name << "azimuth_offset_deg sun_zenith_deg=" << sun_zenith;
      summarize(name.str(), "azimuth_offset_deg", chains, m, altitude_m);
    }
  }

  void check_symmetry(const std::vector<ChainPoint>& points, const std::vector<double>& offsets,
                      double sun_zenith, double view_zenith) {
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (!(offsets[i] > 0.0 && offsets[i] < 180.0)) continue;
      const auto mirror = std::find_if(offsets.begin(), offsets.end(), [&](double o) {
        return std::abs(o - (360.0 - offsets[i])) < 1e-9;
      });
      if (mirror == offsets.end()) continue;
      const ChainPoint& a = points[i];
      const ChainPoint& b = points[static_cast<std::size_t>(mirror - offsets.begin())];
      if (!a.answered || !b.answered) continue;
      double worst = 0.0;
      for (std::size_t w = 0; w < a.values.size(); ++w) {
        const double scale = std::max(std::abs(a.values[w]), std::abs(b.values[w]));
        if (scale > 0.0) worst = std::max(worst, std::abs(a.values[w] - b.values[w]) / scale);
      }
      std::ostringstream where;
      where << "sun_zenith_deg=" << sun_zenith << " view_zenith_deg=" << view_zenith
            << " azimuth_offset_deg=+-" << offsets[i];
      note(report_.symmetry, worst / kSymmetryTolerance, where.str());
    }
  }

  void sweep_altitude(const SkyModel& m) {
    const ModelCapabilities& caps = m.descriptor().capabilities;
    if (!(caps.max_altitude_m > caps.min_altitude_m)) return;
    const std::vector<Probe> ps = probes(caps);
    std::vector<Chain> chains = chains_named(ps);
    chains.push_back({"sun_irradiance", {}});
    const auto sun = sun_state(m, kBaseSunZenithDeg);
    const AtmosphereParameters& atmosphere = m.config().atmosphere;
    const double top_m = atmosphere.top_radius_m - atmosphere.earth_radius_m;
    for (double altitude_m :
         thinned(altitudes_m(caps.max_altitude_m, top_m), options_.max_points_per_sweep)) {
      std::vector<ChainPoint> points =
          radiance(m, *sun, kBaseSunZenithDeg, altitude_m, ps, altitude_m);
      for (std::size_t i = 0; i < ps.size(); ++i) chains[i].points.push_back(std::move(points[i]));
      chains.back().points.push_back(irradiance_point(m, m.sun_irradiance(*sun, {altitude_m}),
                                                      kBaseSunZenithDeg, altitude_m, altitude_m));
    }
    std::vector<DocumentedJump> documented;
    for (std::size_t i = 0; i < ps.size(); ++i)
      for (DocumentedJump& j : documented_altitude_jumps(m, ps[i].zenith_deg, chains[i].name))
        documented.push_back(std::move(j));
    SweepSummary summary{.name = "altitude_m", .coordinate = "altitude_m"};
    summarize_jumps(chains, report_.wavelengths_nm, documented, summary);
    report_.sweeps.push_back(std::move(summary));
  }

  void sweep_parameter(const ParameterSpec& p) {
    const ModelDescriptor& d = *factory_.descriptor;
    double base_value = p.default_value;
    if (auto it = base_.options.find(p.name); it != base_.options.end()) base_value = it->second;
    // A model that precomputes per sun pays a dome per value: at most 3 values.
    const std::size_t count = d.capabilities.per_sun_precomputation
                                  ? std::min<std::size_t>(options_.parameter_values, 3)
                                  : options_.parameter_values;
    const std::vector<double> values =
        parameter_values(p, parameter_sweep_top(p, base_value), count);
    const std::vector<Probe> ps = probes(d.capabilities);
    std::vector<Chain> chains = chains_named(ps);
    chains.push_back({"sun_irradiance", {}});
    chains.push_back({"sky_irradiance", {}});
    std::shared_ptr<const SkyModel> last_model;
    for (double value : values) {
      ModelConfig config = base_;
      if (p.atmosphere) {
        find_atmosphere_parameter(p.name)->set(config.atmosphere, value);
      } else {
        config.options[p.name] = value;
      }
      std::ostringstream where;
      where << p.name << '=' << value;
      configuration_ = where.str();
      std::shared_ptr<const SkyModel> m = build(config, where.str(), p.name);
      // An integer the build refuses by name (an odd or even size): the next one up or down.
      for (double step : {1.0, -1.0}) {
        if (m || !p.integer || p.atmosphere || !(value + step >= p.min_value) ||
            !(value + step <= p.max_value))
          continue;
        config.options[p.name] = value + step;
        m = build(config, where.str(), p.name);
      }
      if (!m) {
        for (Chain& c : chains) c.points.push_back({value, false, {}, SampleStatus::invalid_input});
        continue;
      }
      last_model = m;
      const double altitude_m = m->descriptor().capabilities.min_altitude_m;
      const auto sun = sun_state(*m, kBaseSunZenithDeg);
      std::vector<ChainPoint> points = radiance(*m, *sun, kBaseSunZenithDeg, altitude_m, ps, value);
      for (std::size_t i = 0; i < ps.size(); ++i) chains[i].points.push_back(std::move(points[i]));
      const SpectralSample direct = m->sun_irradiance(*sun, {altitude_m});
      const SpectralSample sky = m->sky_irradiance(*sun, {altitude_m});
      chains[ps.size()].points.push_back(
          irradiance_point(*m, direct, kBaseSunZenithDeg, altitude_m, value));
      chains[ps.size() + 1].points.push_back(
          irradiance_point(*m, sky, kBaseSunZenithDeg, altitude_m, value));
      check_energy(*m, direct, sky, kBaseSunZenithDeg, altitude_m);
    }
    configuration_.clear();
    if (!last_model) return;
    summarize("parameter " + p.name, p.name, chains, *last_model, d.capabilities.min_altitude_m);
    if (p.name == "beta" || p.name == "turbidity") {
      check_trend(p.name, chains[ps.size()], false, "direct sun dims as " + p.name + " grows",
                  nullptr, " (whole range)");
      sweep_trend(p);
    }
  }

  // More aerosol: a dimmer direct sun and a brighter horizon towards the sun, over the first
  // kTrendRangeFraction of the parameter's range (the horizon only where the view is thin).
  void sweep_trend(const ParameterSpec& p) {
    const std::vector<double> values = parameter_values(
        p, p.min_value + kTrendRangeFraction * (p.max_value - p.min_value), kTrendValues);
    const Probe horizon{kTrendHorizonZenithDeg, 0.0};
    Chain sun_chain{"sun_irradiance", {}};
    Chain horizon_chain{probe_name(horizon), {}};
    std::vector<std::vector<double>> slant_depths;
    for (double value : values) {
      ModelConfig config = base_;
      find_atmosphere_parameter(p.name)->set(config.atmosphere, value);
      std::ostringstream where;
      where << p.name << '=' << value;
      configuration_ = where.str();
      const std::shared_ptr<const SkyModel> m = build(config, where.str());
      if (!m) {
        sun_chain.points.push_back({value, false, {}, SampleStatus::invalid_input});
        horizon_chain.points.push_back({value, false, {}, SampleStatus::invalid_input});
        slant_depths.emplace_back();
        continue;
      }
      std::vector<double> depth = vertical_optical_depth(*m, value);
      for (double& d : depth) d /= std::cos(degrees_to_radians(kTrendHorizonZenithDeg));
      slant_depths.push_back(std::move(depth));
      const double altitude_m = m->descriptor().capabilities.min_altitude_m;
      const auto sun = sun_state(*m, kBaseSunZenithDeg);
      horizon_chain.points.push_back(
          radiance(*m, *sun, kBaseSunZenithDeg, altitude_m, {horizon}, value)[0]);
      sun_chain.points.push_back(irradiance_point(*m, m->sun_irradiance(*sun, {altitude_m}),
                                                  kBaseSunZenithDeg, altitude_m, value));
    }
    configuration_.clear();
    check_trend(p.name, sun_chain, false, "direct sun dims as " + p.name + " grows", nullptr,
                " (first 5% of the range)");
    std::ostringstream bound;
    bound << "horizon towards the sun brightens as " << p.name << " grows, where the slant "
          << "optical depth of the view is at most " << kThinSlantOpticalDepth;
    check_trend(p.name, horizon_chain, true, bound.str(), &slant_depths,
                " (first 5% of the range)");
  }

  // Vertical optical depth of the model's atmosphere per wavelength: Rayleigh and aerosol
  // extinction over their scale heights; for the fitted models, turbidity times the Rayleigh
  // depth (turbidity is the ratio of the total optical depth to the Rayleigh one; Preetham,
  // Shirley and Smits 1999, section 3.1).
  static std::vector<double> vertical_optical_depth(const SkyModel& m, double parameter_value) {
    const AtmosphereSpectra& a = m.atmosphere();
    std::vector<double> out;
    for (std::size_t w = 0; w < a.rayleigh_scattering_per_m.size(); ++w) {
      const double rayleigh = a.rayleigh_scattering_per_m[w] * a.parameters.rayleigh_scale_height_m;
      const double aerosol = a.mie_extinction_per_m[w] * a.parameters.mie_scale_height_m;
      const bool turbidity = m.descriptor().find_parameter("turbidity") != nullptr;
      out.push_back(turbidity ? parameter_value * rayleigh : rayleigh + aerosol);
    }
    return out;
  }

  // Along a parameter sweep: each value at least (rising) or at most (falling) the previous;
  // with depths, only where the vertical optical depth after the step is thin.
  void check_trend(const std::string& parameter, const Chain& chain, bool rising,
                   const std::string& bound, const std::vector<std::vector<double>>* depths,
                   const std::string& label) {
    BoundCheck check{.name = "trend " + parameter + " " + chain.name + label, .bound = bound};
    for (std::size_t i = 0; i + 1 < chain.points.size(); ++i) {
      const ChainPoint& a = chain.points[i];
      const ChainPoint& b = chain.points[i + 1];
      if (!a.answered || !b.answered) continue;
      for (std::size_t w = 0; w < a.values.size(); ++w) {
        const double before = a.values[w], after = b.values[w];
        if (before == 0.0 && after == 0.0) continue;
        if (depths != nullptr &&
            !((*depths)[i + 1].size() > w && (*depths)[i + 1][w] <= kThinSlantOpticalDepth))
          continue;
        const double ratio = rising ? before / after : after / before;
        std::ostringstream where;
        where << parameter << ' ' << a.coordinate << " -> " << b.coordinate << " at "
              << report_.wavelengths_nm[w] << " nm";
        note(check, ratio, where.str());
      }
    }
    report_.trends.push_back(std::move(check));
  }

  const ModelFactory& factory_;
  StressOptions options_;
  // The parameter value a parameter sweep is at ("beta=0.5"), for the locations it reports.
  std::string configuration_;
  ModelConfig base_;
  ModelStressReport report_;
};

}  // namespace

ModelStressReport stress_model(const ModelFactory& factory, const StressOptions& options) {
  return ModelStress(factory, options).run();
}

bool stress_passed(const ModelStressReport& r) {
  bool ok = r.non_finite_values == 0 && r.negative_values == 0 && r.undeclared_refusals() == 0;
  for (const BoundCheck* check : {&r.symmetry, &r.energy, &r.radiance_below_sun})
    ok = ok && !failed(*check);
  for (const BoundCheck& trend : r.trends) ok = ok && !failed(trend);
  return ok;
}

}  // namespace clearsky::stress
