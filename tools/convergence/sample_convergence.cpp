// Per-sample convergence breakdown of a model's discretisation (docs/performance.md
// "Findings"): builds the model at two option sets (a coarse one and a finer one, e.g. N and 2N
// spheres) and prints, for every sample of the atlas's full geometry set (models/atlas/
// atlas_geometry.h: sun zenith, observer altitude, view), the relative L2 spectral difference
// the atlas measures (models/atlas/model_atlas.cpp), the wavelength of the largest relative
// difference and the radiances, as tab-separated lines, so that the 95th percentile and the
// maximum can be traced to suns, altitudes and views.
//
//   clearsky_sample_convergence MODEL COARSE_OPTIONS FINE_OPTIONS [SUN_ZENITHS_DEG]
//   e.g. nishita93 spheres=512,cylinders=512 spheres=1024,cylinders=1024 0,89.3
//
// Columns: sun_zenith_deg altitude_m view_zenith_deg view_azimuth_offset_deg rel_l2
// worst_nm worst_rel mean_fine mean_sky_fine (the mean radiance of the fine sky at this sun
// and altitude over the views that see light, W/(m2.sr.nm)). Build: tools/convergence/README.md.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "models/atlas/atlas_geometry.h"
#include "models/core/numeric.h"
#include "models/registry.h"

using namespace clearsky;

namespace {

std::map<std::string, double> parse_options(const std::string& text) {
  std::map<std::string, double> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    const auto eq = item.find('=');
    if (eq == std::string::npos) continue;
    out[item.substr(0, eq)] = std::stod(item.substr(eq + 1));
  }
  return out;
}

std::vector<double> parse_list(const std::string& text) {
  std::vector<double> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(std::stod(item));
  return out;
}

// Every sample of the geometry at one sun and altitude: spectra in view order.
std::vector<std::vector<double>> sky(const SkyModel& model, const SunState& sun, double altitude_m,
                                     const atlas::AtlasGeometry& g) {
  SpectralBatch batch;
  model.sky_radiance(sun, Viewpoint{altitude_m}, g.views, batch);
  std::vector<std::vector<double>> out;
  for (std::size_t i = 0; i < batch.size(); ++i) {
    const auto s = batch.spectrum(i);
    out.emplace_back(s.begin(), s.end());
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: %s MODEL COARSE_OPTIONS FINE_OPTIONS [SUN_ZENITHS_DEG]\n",
                 argv[0]);
    return 2;
  }
  const ModelFactory* factory = find_model(argv[1]);
  if (factory == nullptr) {
    std::fprintf(stderr, "unknown model %s\n", argv[1]);
    return 2;
  }
  atlas::AtlasGeometry g = atlas::atlas_geometry(factory->descriptor->capabilities, false);
  if (argc > 4) g.sun_zeniths_deg = parse_list(argv[4]);
  ModelConfig coarse_config, fine_config;
  coarse_config.options = parse_options(argv[2]);
  fine_config.options = parse_options(argv[3]);
  const auto coarse = factory->create(coarse_config, {});
  const auto fine = factory->create(fine_config, {});
  const std::vector<double>& nm = fine->wavelengths().nanometres();
  std::printf(
      "sun_zenith_deg\taltitude_m\tview_zenith_deg\tview_azimuth_offset_deg\trel_l2\tworst_nm\t"
      "worst_rel\tmean_fine\tmean_sky_fine\n");
  for (double sun_deg : g.sun_zeniths_deg) {
    const SunPosition sun{degrees_to_radians(sun_deg),
                          degrees_to_radians(atlas::kAtlasSunAzimuthDeg)};
    const auto coarse_sun = coarse->prepare_sun(sun);
    const auto fine_sun = fine->prepare_sun(sun);
    for (double altitude_m : g.altitudes_m) {
      const auto c = sky(*coarse, *coarse_sun, altitude_m, g);
      const auto f = sky(*fine, *fine_sun, altitude_m, g);
      double sky_sum = 0;
      std::size_t lit = 0;
      for (const auto& s : f) {
        double m = 0;
        for (double v : s) m += v / static_cast<double>(s.size());
        if (m > 0) {
          sky_sum += m;
          ++lit;
        }
      }
      const double sky_mean = lit > 0 ? sky_sum / static_cast<double>(lit) : 0.0;
      for (std::size_t i = 0; i < g.views.size(); ++i) {
        double diff2 = 0, ref2 = 0, mean = 0, worst = 0, worst_nm = 0;
        for (std::size_t k = 0; k < nm.size(); ++k) {
          const double d = c[i][k] - f[i][k];
          diff2 += d * d;
          ref2 += f[i][k] * f[i][k];
          mean += f[i][k] / static_cast<double>(nm.size());
          if (f[i][k] > 0 && std::abs(d) / f[i][k] > worst) {
            worst = std::abs(d) / f[i][k];
            worst_nm = nm[k];
          }
        }
        if (!(ref2 > 0)) continue;
        std::printf("%.1f\t%.0f\t%.1f\t%.0f\t%.6g\t%.1f\t%.6g\t%.6g\t%.6g\n", sun_deg, altitude_m,
                    radians_to_degrees(g.views[i].zenith_rad),
                    radians_to_degrees(g.views[i].azimuth_rad) - atlas::kAtlasSunAzimuthDeg,
                    std::sqrt(diff2 / ref2), worst_nm, worst, mean, sky_mean);
      }
    }
  }
  return 0;
}
