// Layers and layered transmittance of the Haber model (see haber_functions.h).
#include "models/haber/haber_functions.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "models/core/numeric.h"

namespace clearsky::haber {

LayeredAtmosphere::LayeredAtmosphere(double earth_radius_m, double top_height_m, int layer_count,
                                     double rayleigh_scale_height_m, double mie_scale_height_m)
    : earth_radius_m_(earth_radius_m),
      top_height_m_(top_height_m),
      layer_count_(layer_count),
      rayleigh_scale_height_m_(rayleigh_scale_height_m),
      mass_step_((1.0 - std::exp(-top_height_m / rayleigh_scale_height_m)) / layer_count) {
  boundary_radius_m_.resize(static_cast<std::size_t>(layer_count) + 1);
  for (int i = 0; i <= layer_count; ++i)
    boundary_radius_m_[i] = earth_radius_m + boundary_height_m(i);
  for (int i = 0; i < layer_count; ++i) {
    const double middle = 0.5 * (boundary_height_m(i) + boundary_height_m(i + 1));
    rayleigh_density_.push_back(std::exp(-middle / rayleigh_scale_height_m));
    mie_density_.push_back(std::exp(-middle / mie_scale_height_m));
  }
}

double LayeredAtmosphere::boundary_height_m(int i) const {
  return -rayleigh_scale_height_m_ * std::log(1.0 - i * mass_step_);
}

int LayeredAtmosphere::layer_index(double radius_m) const {
  const double height = radius_m - earth_radius_m_;
  const double index =
      std::floor((1.0 - std::exp(-height / rayleigh_scale_height_m_)) / mass_step_);
  return static_cast<int>(std::clamp(index, 0.0, static_cast<double>(layer_count_ - 1)));
}

namespace {

// Segment [p, q] along which the radius is monotonic: it crosses the boundaries between the
// layers of p and q once each. Distances along the segment to the sphere of radius r, from
// the end with the lower layer: -b + sqrt(b^2 - c + r^2).
OpticalLength monotonic_optical_length(const LayeredAtmosphere& layers, Vec3 p, Vec3 q) {
  int start = layers.layer_index(length(p));
  int end = layers.layer_index(length(q));
  const double pq = length(q - p);
  OpticalLength result;
  if (!(pq > 0.0)) return result;
  double b;
  double c;
  if (start > end) {
    std::swap(start, end);
    b = dot(q, p - q) / pq;
    c = dot(q, q);
  } else {
    b = dot(p, q - p) / pq;
    c = dot(p, p);
  }
  double previous = 0.0;
  for (int i = start; i < end; ++i) {
    const double r = layers.boundary_radius_m(i + 1);
    const double distance = std::min(-b + safe_sqrt(b * b - c + r * r), pq);
    const double piece = std::max(distance - previous, 0.0);
    result.rayleigh_m += layers.rayleigh_density(i) * piece;
    result.mie_m += layers.mie_density(i) * piece;
    previous = std::max(previous, distance);
  }
  const double last = std::max(pq - previous, 0.0);
  result.rayleigh_m += layers.rayleigh_density(end) * last;
  result.mie_m += layers.mie_density(end) * last;
  return result;
}

}  // namespace

OpticalLength optical_length(const LayeredAtmosphere& layers, Vec3 p, Vec3 q) {
  const Vec3 pq = q - p;
  const double pq2 = dot(pq, pq);
  if (!(pq2 > 0.0)) return {};
  const double t = -dot(p, pq) / pq2;
  if (t > 0.0 && t < 1.0) {
    const Vec3 closest = p + t * pq;
    if (length(closest) <= layers.earth_radius_m()) return {0.0, 0.0, true};
    const OpticalLength a = monotonic_optical_length(layers, p, closest);
    const OpticalLength b = monotonic_optical_length(layers, closest, q);
    return {a.rayleigh_m + b.rayleigh_m, a.mie_m + b.mie_m, false};
  }
  return monotonic_optical_length(layers, p, q);
}

Vec3 exit_point(const LayeredAtmosphere& layers, Vec3 p, Vec3 direction) {
  const double top = layers.earth_radius_m() + layers.top_height_m() - 1.0;
  const double b = dot(p, direction);
  const double c = dot(p, p) - top * top;
  const double d = -b + safe_sqrt(b * b - c);
  return p + d * direction;
}

}  // namespace clearsky::haber
