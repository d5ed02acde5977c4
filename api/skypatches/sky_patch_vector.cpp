// Patch averages, the sun and the ground of a sky vector (sky_patch_vector.h).
#include "api/skypatches/sky_patch_vector.h"

#include <cmath>
#include <numbers>
#include <span>

namespace clearsky::api {

namespace {

constexpr double kPi = std::numbers::pi;

}  // namespace

double projected_solid_angle_sr(const SkyPatch& patch) {
  // Integral of cos(zenith) = sin(altitude) over the patch: width (sin^2 top - sin^2 bottom) / 2
  // for a band patch, pi sin^2(cap half-angle) for the cap.
  const double top = std::sin(patch.max_altitude_rad);
  const double bottom = std::sin(patch.min_altitude_rad);
  if (patch.cap) return kPi * (1.0 - bottom * bottom);
  return 0.5 * (patch.max_azimuth_rad - patch.min_azimuth_rad) * (top * top - bottom * bottom);
}

double sun_disk_solid_angle_sr() {
  // Nominal solar radius 695700 km (IAU 2015 Resolution B3) over 1 au = 149597870.7 km.
  const double angular_radius_rad = std::asin(695700.0 / 149597870.7);
  return 2.0 * kPi * (1.0 - std::cos(angular_radius_rad));
}

SkyPatchVector compute_sky_patch_vector(const SkyModel& model, const SunState& sun,
                                        const Viewpoint& viewpoint, const SkyPatchScheme& scheme,
                                        const PatchQuadratureOrder& order, SunHandling handling,
                                        double ground_reflectance) {
  const std::size_t n = model.wavelengths().size();
  const SunPosition& sun_direction = sun.sun();
  const bool sun_up = sun_direction.zenith_rad < 0.5 * kPi;
  SkyPatchVector out;
  out.diffuse_horizontal = Spectrum(n, 0.0);
  out.direct_normal = Spectrum(n, 0.0);

  const PatchQuadrature q = patch_quadrature(scheme, order, sun_direction);
  out.directions = q.views.size();
  if (sun_up) {
    const SpectralSample direct = model.sun_irradiance(sun, viewpoint);
    if (direct.status != SampleStatus::ok) {
      out.status = direct.status;
      return out;
    }
    out.direct_normal = direct.value;
  }

  const auto patches = scheme.sky_patches();
  out.patches.assign(scheme.patch_count(), Spectrum(n, 0.0));
  Spectrum diffuse_exact(n, 0.0);  // the quadrature's own cosine-weighted sum, for the ground
  // The radiance is queried for whole patches at a time, at most about kBatchDirections
  // directions per batch, so the memory a request holds does not grow with directions x
  // wavelengths (21,712 directions for MF 6 times up to --max-wavelengths).
  constexpr std::size_t kBatchDirections = 2048;
  SpectralBatch batch;
  std::size_t batch_first_patch = 0;
  std::size_t batch_end_patch = 0;
  for (std::size_t p = 0; p < patches.size(); ++p) {
    if (p == batch_end_patch) {
      batch_first_patch = p;
      batch_end_patch = p + 1;
      while (batch_end_patch < patches.size() &&
             q.first[batch_end_patch + 1] - q.first[p] <= kBatchDirections)
        ++batch_end_patch;
      const std::span<const ViewDirection> views(q.views.data() + q.first[p],
                                                 q.first[batch_end_patch] - q.first[p]);
      model.sky_radiance(sun, viewpoint, views, batch);
      for (SampleStatus s : batch.status) {
        if (s != SampleStatus::ok) {
          out.status = s;
          return out;
        }
      }
    }
    Spectrum& average = out.patches[p + 1];
    for (std::size_t node = q.first[p]; node < q.first[p + 1]; ++node) {
      const auto spectrum = batch.spectrum(node - q.first[batch_first_patch]);
      const double w = q.weights_sr[node];
      const double w_cos = w * std::cos(q.views[node].zenith_rad);
      for (std::size_t i = 0; i < n; ++i) {
        average[i] += w * spectrum[i];
        diffuse_exact[i] += w_cos * spectrum[i];
      }
    }
    average /= patches[p].solid_angle_sr;
    const double projected = projected_solid_angle_sr(patches[p]);
    for (std::size_t i = 0; i < n; ++i) out.diffuse_horizontal[i] += average[i] * projected;
  }

  if (sun_up) {
    out.sun_patch =
        scheme.patch_of(0.5 * kPi - sun_direction.zenith_rad, sun_direction.azimuth_rad);
    if (handling == SunHandling::separate) {
      const double omega = sun_disk_solid_angle_sr();
      Spectrum radiance = out.direct_normal;
      radiance /= omega;
      out.sun = SunSource{sun_direction, omega, std::move(radiance)};
    } else {
      Spectrum added = out.direct_normal;
      added /= patches[out.sun_patch - 1].solid_angle_sr;
      out.patches[out.sun_patch] += added;
    }
  }

  Spectrum global = out.direct_normal;
  global *= sun_up ? std::cos(sun_direction.zenith_rad) : 0.0;
  global += diffuse_exact;
  global *= ground_reflectance / kPi;
  out.patches[0] = std::move(global);
  return out;
}

}  // namespace clearsky::api
