// The atlas of one model (model_atlas.h).
#include "models/atlas/model_atlas.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <memory>
#include <sstream>

#include "models/atlas/atlas_geometry.h"
#include "models/atlas/error_summary.h"
#include "models/colour/colour_spaces.h"
#include "models/colour/three_wavelength_rgb.h"
#include "models/core/numeric.h"

namespace clearsky::atlas {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// CPU time of the whole process (every thread), seconds (POSIX clock_gettime).
double process_cpu_s() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Wall time of one call of f: f repeated until min_s has passed (at least 3 times).
template <class F>
double time_per_call(double min_s, F&& f) {
  std::size_t calls = 0;
  const Clock::time_point start = Clock::now();
  do {
    f();
    ++calls;
  } while (calls < 3 || seconds_since(start) < min_s);
  return seconds_since(start) / static_cast<double>(calls);
}

// The sky of a model over the geometry set, on the paper's 40 bins (a setting on another grid
// is brought to them: the paper's reconstruction from 3 samples for the RGB points, linear
// interpolation in wavelength, end values held, for other point grids), with each sample's
// status; samples in the order sun, altitude, view.
struct SkySamples {
  std::vector<Spectrum> spectra;
  std::vector<bool> answered;
};

Spectrum on_paper_bins(const Spectrum& s, const WavelengthGrid& grid, AtlasGrid kind) {
  const WavelengthGrid bins = WavelengthGrid::paper_bins();
  if (kind == AtlasGrid::paper_bins) return s;
  if (kind == AtlasGrid::rgb_points) return ThreeWavelengthRgb().reconstruct_spectrum(s, bins);
  Spectrum out(bins.size());
  const std::vector<double>& nm = grid.nanometres();
  for (std::size_t i = 0; i < bins.size(); ++i) {
    const double w = bins[i];
    const auto upper = std::upper_bound(nm.begin(), nm.end(), w);
    if (upper == nm.begin()) {
      out[i] = s[0];
    } else if (upper == nm.end()) {
      out[i] = s[nm.size() - 1];
    } else {
      const std::size_t k = static_cast<std::size_t>(upper - nm.begin());
      const double t = (w - nm[k - 1]) / (nm[k] - nm[k - 1]);
      out[i] = (1.0 - t) * s[k - 1] + t * s[k];
    }
  }
  return out;
}

SkySamples sample_sky(const SkyModel& model, AtlasGrid kind, const AtlasGeometry& g,
                      const PrecomputeContext& context) {
  SkySamples out;
  SpectralBatch batch;
  for (double sun_zenith_deg : g.sun_zeniths_deg) {
    const SunPosition sun{degrees_to_radians(sun_zenith_deg),
                          degrees_to_radians(kAtlasSunAzimuthDeg)};
    const std::shared_ptr<const SunState> state = model.prepare_sun(sun, context);
    for (double altitude_m : g.altitudes_m) {
      model.sky_radiance(*state, Viewpoint{altitude_m}, g.views, batch);
      for (std::size_t i = 0; i < batch.size(); ++i) {
        const bool ok = batch.status[i] == SampleStatus::ok;
        const std::span<const double> v = batch.spectrum(i);
        out.spectra.push_back(ok ? on_paper_bins(Spectrum(std::vector<double>(v.begin(), v.end())),
                                                 model.wavelengths(), kind)
                                 : Spectrum());
        out.answered.push_back(ok);
      }
    }
  }
  return out;
}

// The relative L2 difference of the spectra over the bins the reference answers, and of the
// luminances, for every sample the reference answers with light (a zero reference radiance,
// e.g. a view of the ground of a model without ground, has no relative error).
void compare(const SkySamples& tested, const SkySamples& reference,
             const std::vector<bool>& answered_bins, SettingMeasurement& m) {
  const WavelengthGrid bins = WavelengthGrid::paper_bins();
  std::vector<double> spectral;
  std::vector<double> luminance;
  m.samples_refused = 0;
  for (std::size_t i = 0; i < reference.spectra.size(); ++i) {
    if (!reference.answered[i]) continue;
    if (!tested.answered[i]) {
      ++m.samples_refused;
      continue;
    }
    const Spectrum& r = reference.spectra[i];
    const Spectrum& t = tested.spectra[i];
    double diff2 = 0;
    double ref2 = 0;
    Spectrum r_answered(bins.size());
    Spectrum t_answered(bins.size());
    for (std::size_t k = 0; k < bins.size(); ++k) {
      if (!answered_bins[k]) continue;
      diff2 += (t[k] - r[k]) * (t[k] - r[k]);
      ref2 += r[k] * r[k];
      r_answered[k] = r[k];
      t_answered[k] = t[k];
    }
    if (!(ref2 > 0.0)) continue;
    spectral.push_back(std::sqrt(diff2 / ref2));
    const double y_ref = spectrum_to_luminance(r_answered, bins);
    if (y_ref > 0.0)
      luminance.push_back(std::abs(spectrum_to_luminance(t_answered, bins) - y_ref) / y_ref);
  }
  m.spectral_error = summarise_errors(std::move(spectral));
  m.luminance_error = summarise_errors(std::move(luminance));
}

class ModelAtlas {
 public:
  ModelAtlas(const ModelFactory& factory, const AtlasOptions& options)
      : factory_(factory), options_(options), descriptor_(*factory.descriptor) {
    context_.threads = options.precompute_threads;
    // Each build is measured on its own: tables another live model holds are not taken.
    context_.reuse_live_tables = false;
  }

  ModelAtlasReport run() {
    const Clock::time_point start = Clock::now();
    const ModelAtlasSettings settings = atlas_settings(descriptor_, options_.scope);
    geometry_ = atlas_geometry(descriptor_.capabilities, options_.scope == AtlasScope::quick);
    report_.model = descriptor_.id;
    report_.version = descriptor_.version;
    report_.reference_reason = settings.reference_reason;
    report_.sun_zeniths_deg = geometry_.sun_zeniths_deg;
    report_.altitudes_m = geometry_.altitudes_m;
    report_.views = geometry_.views.size();

    SkySamples reference_sky;
    report_.reference = measure(settings.reference, "reference", &reference_sky);
    if (!settings.reference_check.name.empty()) {
      SkySamples check_sky;
      SettingMeasurement check = measure(settings.reference_check, "reference_check", &check_sky);
      // The check's errors are those of the reference against it.
      compare(reference_sky, check_sky, answered_bins_, check);
      log(check, "reference against the check");
      report_.reference_check = std::move(check);
    }
    for (const AtlasSetting& s : settings.settings) {
      SkySamples sky;
      SettingMeasurement m = measure(s, "setting", &sky);
      compare(sky, reference_sky, answered_bins_, m);
      log(m, "against the reference");
      report_.settings.push_back(std::move(m));
    }
    name_fronts();
    report_.seconds = seconds_since(start);
    return std::move(report_);
  }

 private:
  void log(const SettingMeasurement& m, const std::string& what) const {
    if (!options_.log) return;
    std::ostringstream out;
    out << descriptor_.id << ' ' << m.setting.name << " (" << m.role << "): build "
        << m.build_wall_s << " s wall, " << m.build_cpu_s << " s CPU, " << m.table_bytes
        << " bytes; " << what << ": p95 " << m.spectral_error.p95 << ", max "
        << m.spectral_error.max;
    if (m.rmse) out << "; RMSE " << *m.rmse;
    options_.log(out.str());
  }

  SettingMeasurement measure(const AtlasSetting& s, const std::string& role, SkySamples* sky) {
    SettingMeasurement m;
    m.setting = s;
    m.role = role;
    const ModelConfig config = s.config(descriptor_);
    m.wavelengths = config.wavelengths.size();
    if (factory_.estimate_table_bytes != nullptr)
      m.estimated_table_bytes = factory_.estimate_table_bytes(config);
    const double cpu0 = process_cpu_s();
    const Clock::time_point start = Clock::now();
    const std::shared_ptr<const SkyModel> model = factory_.create(config, context_);
    m.build_wall_s = seconds_since(start);
    m.build_cpu_s = process_cpu_s() - cpu0;
    m.table_bytes = model->table_bytes();
    if (answered_bins_.empty()) {
      // The bins the reference answers (the reference is measured first, on the 40 bins).
      for (std::size_t k = 0; k < model->wavelengths().size(); ++k)
        answered_bins_.push_back(model->answers_wavelength(k));
    }

    // Timings at one sun off the geometry set's zeniths (a fresh per-sun preparation).
    const SunPosition sun{degrees_to_radians(33.3), degrees_to_radians(kAtlasSunAzimuthDeg)};
    const Clock::time_point sun_start = Clock::now();
    const std::shared_ptr<const SunState> state = model->prepare_sun(sun, context_);
    if (descriptor_.capabilities.per_sun_precomputation)
      m.sun_state_wall_s = seconds_since(sun_start);
    const Viewpoint ground{descriptor_.capabilities.min_altitude_m};
    const std::vector<ViewDirection> one = {{degrees_to_radians(50.0), degrees_to_radians(90.0)}};
    const std::vector<ViewDirection> batch_views = batch_views_81();
    SpectralBatch batch;
    m.radiance_s = time_per_call(options_.min_timing_s,
                                 [&] { model->sky_radiance(*state, ground, one, batch); });
    m.batch_81_s = time_per_call(options_.min_timing_s,
                                 [&] { model->sky_radiance(*state, ground, batch_views, batch); });
    if (descriptor_.capabilities.sky_irradiance)
      m.sky_irradiance_s = time_per_call(options_.min_timing_s,
                                         [&] { (void)model->sky_irradiance(*state, ground); });

    *sky = sample_sky(*model, s.grid, geometry_, context_);

    if (!options_.captures.empty() && (options_.rmse_of_every_setting || s.name == "standard")) {
      EvaluationOptions evaluation;
      evaluation.context = context_;
      evaluation.capture_threads = options_.capture_threads;
      const Clock::time_point eval_start = Clock::now();
      const EvaluationResult r = evaluate_sky_model(*model, options_.captures, evaluation);
      m.evaluate_s = seconds_since(eval_start);
      if (std::isfinite(r.rmse)) m.rmse = r.rmse;
      m.rmse_wavelengths = r.wavelengths_nm.size();
    }
    if (role == "reference") log(m, "measured");
    return m;
  }

  void name_fronts() {
    std::vector<CostErrorPoint> build;
    std::vector<CostErrorPoint> query;
    double draft_cost = INFINITY;
    for (const SettingMeasurement& m : report_.settings) {
      const double p95 = m.spectral_error.p95;
      build.push_back({m.setting.name, m.build_cpu_s + m.sun_state_wall_s, p95});
      query.push_back({m.setting.name, m.batch_81_s, p95});
      if (p95 <= kDraftMaxP95Error && m.samples_refused == 0 && m.first_sky_s() < draft_cost) {
        draft_cost = m.first_sky_s();
        report_.draft = m.setting.name;
      }
    }
    report_.pareto_build = pareto_front(std::move(build));
    report_.pareto_query = pareto_front(std::move(query));
  }

  const ModelFactory& factory_;
  const AtlasOptions& options_;
  const ModelDescriptor& descriptor_;
  PrecomputeContext context_;
  AtlasGeometry geometry_;
  std::vector<bool> answered_bins_;
  ModelAtlasReport report_;
};

}  // namespace

ModelAtlasReport model_atlas(const ModelFactory& factory, const AtlasOptions& options) {
  return ModelAtlas(factory, options).run();
}

}  // namespace clearsky::atlas
