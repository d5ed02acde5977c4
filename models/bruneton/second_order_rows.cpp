// The single-scattering rows that the second order reads.
#include "models/bruneton/second_order_rows.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "models/core/numeric.h"

namespace clearsky::bruneton {

std::vector<double> zenith_cosines(int count, int n) {
  const double dtheta = kPi / n;
  std::vector<double> cos_t(count);
  for (int i = 0; i < count; ++i) cos_t[i] = std::cos((i + 0.5) * dtheta);
  return cos_t;
}

std::vector<char> rows_read_by_second_order(const Resolution& res, const ShellGeometry& g) {
  std::vector<char> needed(static_cast<std::size_t>(res.r) * res.mu, 0);
  // The r and mu axes of a lookup do not depend on mu_s or nu.
  auto mark = [&](double r, const std::vector<double>& cos_t) {
    for (const double mu : cos_t) {
      const Coord4 c = coordinates_4d(r, mu, 0.0, 0.0, res, g);
      for (const int layer : {c.r.i0, c.r.i1})
        for (const int row : {c.mu.i0, c.mu.i1})
          needed[static_cast<std::size_t>(layer) * res.mu + row] = 1;
    }
  };
  // J at each layer's radius, clamped to the shell as the density's profiles are.
  const std::vector<double> sphere = zenith_cosines(res.sphere_samples, res.sphere_samples);
  for (int layer = 0; layer < res.r; ++layer)
    mark(std::clamp(layer_geometry(layer, res.r, g).r, g.bottom_m, g.top_m), sphere);
  // The irradiance at each of its table's radii.
  const std::vector<double> hemisphere =
      zenith_cosines(res.irradiance_samples / 2, res.irradiance_samples);
  for (int j = 0; j < res.irradiance_r; ++j)
    mark(irradiance_texel_r(j, res.irradiance_r, g), hemisphere);
  return needed;
}

}  // namespace clearsky::bruneton
