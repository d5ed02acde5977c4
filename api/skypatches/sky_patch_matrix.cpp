// One sky vector per step of a time series (sky_patch_matrix.h).
#include "api/skypatches/sky_patch_matrix.h"

namespace clearsky::api {

SkyPatchMatrix compute_sky_patch_matrix(const SkyModel& model, const TimeSteps& times,
                                        const Viewpoint& viewpoint, const SkyPatchScheme& scheme,
                                        SunHandling handling, double ground_reflectance,
                                        PatchValueEncoder& encoder) {
  SkyPatchMatrix m;
  m.patch_count = scheme.patch_count();
  m.steps = times.steps;
  m.components = encoder.components();
  m.values.assign(m.patch_count * m.steps * m.components, 0.0f);
  m.answered.assign(m.steps, true);
  m.sun_patch.assign(m.steps, 0);
  m.suns.resize(m.steps);
  const PatchQuadratureOrder order = default_patch_quadrature_order(scheme);
  for (std::size_t step = 0; step < m.steps; ++step) {
    if (times.night(step)) continue;
    const auto state = model.prepare_sun(times.sun(step));
    const SkyPatchVector vector = compute_sky_patch_vector(model, *state, viewpoint, scheme, order,
                                                           handling, ground_reflectance);
    if (vector.status != SampleStatus::ok) {
      m.answered[step] = false;
      ++m.unanswered_steps;
      continue;
    }
    for (std::size_t patch = 0; patch < m.patch_count; ++patch) {
      const std::vector<double> v = encoder.values(vector.patches[patch]);
      float* out = &m.values[(patch * m.steps + step) * m.components];
      for (std::size_t c = 0; c < m.components; ++c) out[c] = static_cast<float>(v[c]);
    }
    m.sun_patch[step] = vector.sun_patch;
    if (vector.sun) {
      const Vec3 d = vector.sun->direction.unit_vector();
      m.suns[step] = SkyMatrixSun{{d.x, d.y, d.z}, encoder.values(vector.sun->radiance)};
    }
  }
  return m;
}

}  // namespace clearsky::api
