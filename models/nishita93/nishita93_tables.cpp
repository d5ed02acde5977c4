// Nishita93's optical-length tables (see nishita93_tables.h).
#include "models/nishita93/nishita93_tables.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "models/core/invalid_input.h"
#include "models/core/numeric.h"
#include "models/core/parallel.h"

namespace clearsky {

namespace {

// Trapezoid rule over successive samples (distance, densities) along one ray.
struct TrapezoidLengths {
  double distance = 0, rayleigh_density = 0, mie_density = 0;
  OpticalLengths sum;

  void add(double d, double rayleigh, double mie) {
    const double half = 0.5 * (d - distance);
    sum.rayleigh_m += half * (rayleigh + rayleigh_density);
    sum.mie_m += half * (mie + mie_density);
    distance = d;
    rayleigh_density = rayleigh;
    mie_density = mie;
  }
};

// Half chord length sqrt(r^2 - c^2) without cancellation, for c <= r.
double half_chord(double r, double c) { return safe_sqrt((r - c) * (r + c)); }

}  // namespace

std::vector<double> Nishita93Tables::sphere_radii_m(const AtmosphereParameters& atmosphere,
                                                    int spheres) {
  if (spheres < 2) throw InvalidInput("spheres", "must be >= 2");
  const double r_ground = atmosphere.earth_radius_m, r_top = atmosphere.top_radius_m;
  const double h_r = atmosphere.rayleigh_scale_height_m;
  const double density_step = std::exp(-(r_top - r_ground) / h_r) - 1.0;
  const auto n_s = static_cast<std::size_t>(spheres);
  std::vector<double> radii(n_s);
  for (std::size_t i = 0; i < n_s; ++i) {
    const double x = static_cast<double>(i) / static_cast<double>(n_s - 1);
    // The end spheres exactly on the ground and the top, whatever the rounding of the log.
    radii[i] = i == 0         ? r_ground
               : i + 1 == n_s ? r_top
                              : r_ground - h_r * std::log1p(density_step * x);
  }
  return radii;
}

Nishita93Tables Nishita93Tables::build(const AtmosphereParameters& atmosphere, int spheres,
                                       int cylinders, const PrecomputeContext& context) {
  atmosphere.validate();
  if (spheres < 2) throw InvalidInput("spheres", "must be >= 2");
  if (cylinders < 2) throw InvalidInput("cylinders", "must be >= 2");
  Nishita93Tables t;
  t.sphere_count_ = spheres;
  t.cylinder_count_ = cylinders;
  t.bottom_radius_m_ = atmosphere.earth_radius_m;
  t.top_radius_m_ = atmosphere.top_radius_m;
  t.rayleigh_scale_height_m_ = atmosphere.rayleigh_scale_height_m;
  const double r_ground = t.bottom_radius_m_, r_top = t.top_radius_m_;
  const double h_r = atmosphere.rayleigh_scale_height_m, h_m = atmosphere.mie_scale_height_m;
  t.density_step_ = std::exp(-(r_top - r_ground) / h_r) - 1.0;

  const auto n_s = static_cast<std::size_t>(spheres);
  t.sphere_radius_m_ = sphere_radii_m(atmosphere, spheres);
  t.sphere_rayleigh_density_.resize(n_s);
  t.sphere_mie_density_.resize(n_s);
  for (std::size_t i = 0; i < n_s; ++i) {
    const double r = t.sphere_radius_m_[i];
    t.sphere_rayleigh_density_[i] = std::exp(-(r - r_ground) / h_r);
    t.sphere_mie_density_[i] = std::exp(-(r - r_ground) / h_m);
  }
  // Per sphere, the last cylinder inside it and that cylinder's sun zenith cosine on it: the
  // cell where along_row interpolates in |mu_s| (computed here once instead of per lookup).
  t.last_inner_cylinder_.resize(n_s);
  t.last_inner_cylinder_mu_.resize(n_s);
  const double max_v = cylinders - 1.0;
  for (std::size_t i = 0; i < n_s; ++i) {
    const double r = t.sphere_radius_m_[i];
    const int last = std::max(0, static_cast<int>(std::ceil(max_v * r / r_top)) - 1);
    const double c_last = r_top * last / max_v;
    t.last_inner_cylinder_[i] = last;
    t.last_inner_cylinder_mu_[i] = safe_sqrt(1.0 - (c_last / r) * (c_last / r));
  }

  const std::size_t size = n_s * static_cast<std::size_t>(cylinders);
  t.along_rayleigh_m_.resize(size);
  t.along_mie_m_.resize(size);
  t.against_rayleigh_m_.resize(size);
  t.against_mie_m_.resize(size);
  const auto& radius = t.sphere_radius_m_;
  parallel_for(
      n_s,
      [&](std::size_t i) {
        context.check_cancelled();
        const double r = radius[i];
        for (int j = 0; j < cylinders; ++j) {
          const std::size_t cell =
              i * static_cast<std::size_t>(cylinders) + static_cast<std::size_t>(j);
          const double cylinder = r_top * j / (cylinders - 1.0);
          // Sun along the axis: from the point up through the exits of the spheres above it.
          {
            const double c = std::min(cylinder, r);
            const double start = half_chord(r, c);
            TrapezoidLengths path{0.0, t.sphere_rayleigh_density_[i], t.sphere_mie_density_[i], {}};
            for (std::size_t k = i + 1; k < n_s; ++k) {
              path.add(half_chord(radius[k], c) - start, t.sphere_rayleigh_density_[k],
                       t.sphere_mie_density_[k]);
            }
            t.along_rayleigh_m_[cell] = path.sum.rayleigh_m;
            t.along_mie_m_[cell] = path.sum.mie_m;
          }
          // Sun against the axis: down to the tangent point (the ground-grazing one when the
          // ray meets the ground), then up to the top.
          {
            const double c = std::clamp(cylinder, r_ground, r);
            const double tangent = half_chord(r, c);
            TrapezoidLengths path{0.0, t.sphere_rayleigh_density_[i], t.sphere_mie_density_[i], {}};
            std::size_t lowest = i;  // lowest sphere above the tangent point
            for (std::size_t k = i; k-- > 0;) {
              if (radius[k] <= c) break;
              path.add(tangent - half_chord(radius[k], c), t.sphere_rayleigh_density_[k],
                       t.sphere_mie_density_[k]);
              lowest = k;
            }
            if (tangent > path.distance) {
              path.add(tangent, std::exp(-(c - r_ground) / h_r), std::exp(-(c - r_ground) / h_m));
            }
            for (std::size_t k = lowest; k < n_s; ++k) {
              if (radius[k] <= c) continue;
              const double d = tangent + half_chord(radius[k], c);
              if (d > path.distance)
                path.add(d, t.sphere_rayleigh_density_[k], t.sphere_mie_density_[k]);
            }
            t.against_rayleigh_m_[cell] = path.sum.rayleigh_m;
            t.against_mie_m_[cell] = path.sum.mie_m;
          }
        }
      },
      context.threads);
  context.report(1.0, "optical lengths");
  return t;
}

OpticalLengths Nishita93Tables::along_lookup(double u, double sin_s, double abs_mu_s) const {
  const int i = std::min(static_cast<int>(u), sphere_count_ - 2);
  const double fu = u - i;
  // A point on a sphere (fu = 0, or 1 on the top sphere) reads one row: the other row's term
  // of the interpolation is exactly 0 (its lengths are finite), so skipping it changes no bit.
  if (fu == 0.0) return along_row(i, sin_s, abs_mu_s);
  if (fu == 1.0) return along_row(i + 1, sin_s, abs_mu_s);
  const OpticalLengths below = along_row(i, sin_s, abs_mu_s);
  const OpticalLengths above = along_row(i + 1, sin_s, abs_mu_s);
  return {(1.0 - fu) * below.rayleigh_m + fu * above.rayleigh_m,
          (1.0 - fu) * below.mie_m + fu * above.mie_m};
}

std::optional<OpticalLengths> Nishita93Tables::sun_optical_lengths(double r_m, double mu_s,
                                                                   int sphere_index) const {
  double r = std::max(r_m, bottom_radius_m_);
  if (r > top_radius_m_) {
    // Above the atmosphere: nothing in the way unless the ray to the sun crosses it; then the
    // lengths are those from where it enters.
    const double c2 = r * r * (1.0 - mu_s * mu_s);
    if (mu_s >= 0.0 || c2 >= top_radius_m_ * top_radius_m_) return OpticalLengths{};
    if (c2 < bottom_radius_m_ * bottom_radius_m_) return std::nullopt;
    mu_s = -safe_sqrt(1.0 - c2 / (top_radius_m_ * top_radius_m_));
    r = top_radius_m_;
    sphere_index = sphere_count_ - 1;
  }
  if (mu_s < 0.0 && ray_hits_ground(r, mu_s, bottom_radius_m_)) return std::nullopt;
  const double max_u = sphere_count_ - 1.0;
  const double u =
      sphere_index >= 0
          ? static_cast<double>(sphere_index)
          : std::clamp(max_u * std::expm1(-(r - bottom_radius_m_) / rayleigh_scale_height_m_) /
                           density_step_,
                       0.0, max_u);
  // Each sphere of the bilinear lookup is read at the point's sun zenith angle (its cylinder
  // radius on that sphere), so that both meet the horizontal ray at mu_s = 0.
  const double sin_s = safe_sqrt(1.0 - mu_s * mu_s);
  const double abs_mu_s = std::abs(mu_s);
  const OpticalLengths along = along_lookup(u, sin_s, abs_mu_s);
  if (mu_s >= 0.0) return along;
  // The sun below the horizon. The ray to the sun goes down to its tangent point, at radius
  // c = r sin(theta_s), then up to the top; its other half from the tangent point passes through
  // the point and on to the top, and is the point's ray towards the mirrored sun (zenith
  // cosine -mu_s). Both halves from the tangent point are the horizontal ray there, so
  //   L(r, mu_s) = 2 H(c) - L(r, -mu_s),
  // exact geometry, equal to the horizontal ray's at mu_s = 0 (continuous through the horizon).
  // The against-axis table is not read here: its entries change like exp(-(c - R) / H_R) with
  // the tangent radius c, which a linear interpolation between cylinders R_top / (n_c - 1)
  // apart (12.5 km at 512 cylinders, more than a scale height) cannot follow; where it was read
  // (cylinders between the ground and the point's sphere, from 128 cylinders on) twilight skies
  // did not converge in the cylinder count (docs/performance.md "Findings"). H(c) is read along
  // the spheres, linear in Rayleigh density, which follows that dependence.
  const double c = r * sin_s;
  const OpticalLengths horizontal = horizontal_lengths(c);
  return OpticalLengths{2.0 * horizontal.rayleigh_m - along.rayleigh_m,
                        2.0 * horizontal.mie_m - along.mie_m};
}

OpticalLengths Nishita93Tables::horizontal_lengths(double r_m) const {
  // The last cylinder is outside every sphere: its column holds each sphere's horizontal ray;
  // between spheres, linear in the sphere coordinate (linear in Rayleigh density).
  const double max_u = sphere_count_ - 1.0;
  const double u = std::clamp(
      max_u * std::expm1(-(r_m - bottom_radius_m_) / rayleigh_scale_height_m_) / density_step_, 0.0,
      max_u);
  const int i = std::min(static_cast<int>(u), sphere_count_ - 2);
  const double fu = u - i;
  const auto at = [&](const std::vector<double>& table, int k) {
    return table[static_cast<std::size_t>(k) * static_cast<std::size_t>(cylinder_count_) +
                 static_cast<std::size_t>(cylinder_count_ - 1)];
  };
  return OpticalLengths{(1.0 - fu) * at(along_rayleigh_m_, i) + fu * at(along_rayleigh_m_, i + 1),
                        (1.0 - fu) * at(along_mie_m_, i) + fu * at(along_mie_m_, i + 1)};
}

OpticalLengths Nishita93Tables::node(int i, int j, bool against_axis) const {
  const std::size_t cell = static_cast<std::size_t>(i) * static_cast<std::size_t>(cylinder_count_) +
                           static_cast<std::size_t>(j);
  return against_axis ? OpticalLengths{against_rayleigh_m_[cell], against_mie_m_[cell]}
                      : OpticalLengths{along_rayleigh_m_[cell], along_mie_m_[cell]};
}

std::size_t Nishita93Tables::memory_bytes_for(int spheres, int cylinders) {
  // Per sphere: radius, two densities, the last cylinder inside it and its sun zenith cosine;
  // per (sphere, cylinder) node: four optical lengths.
  const auto n_s = static_cast<std::size_t>(std::max(spheres, 0));
  const auto nodes = n_s * static_cast<std::size_t>(std::max(cylinders, 0));
  return sizeof(Nishita93Tables) + sizeof(double) * (4 * n_s + 4 * nodes) + sizeof(int) * n_s;
}

std::size_t Nishita93Tables::memory_bytes() const {
  return sizeof(*this) +
         sizeof(double) * (4 * sphere_radius_m_.size() + 4 * along_rayleigh_m_.size()) +
         sizeof(int) * last_inner_cylinder_.size();
}

}  // namespace clearsky
