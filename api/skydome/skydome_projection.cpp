// Pixel directions of the skydome projections, through OpenEXR's environment-map functions.
#include "api/skydome/skydome_projection.h"

#include <OpenEXR/ImfEnvmap.h>

#include <cmath>

namespace clearsky::api {

SkydomeProjection::SkydomeProjection(Projection projection, int size)
    : projection_(projection), size_(size), width_(size), height_(size) {
  if (projection == Projection::latlong) height_ = size / 2;
  if (projection == Projection::cubemap) {
    height_ = 6 * size;
    const IMATH_NAMESPACE::Box2i dw({0, 0}, {width_ - 1, height_ - 1});
    for (int f = 0; f < 6; ++f) {
      const auto face = static_cast<Imf::CubeMapFace>(f);
      // pixel = P0 + A * pif; invert A (a signed permutation) from three probes.
      const auto p0 = Imf::CubeMap::pixelPosition(face, dw, {0.0f, 0.0f});
      const auto px = Imf::CubeMap::pixelPosition(face, dw, {1.0f, 0.0f});
      const auto py = Imf::CubeMap::pixelPosition(face, dw, {0.0f, 1.0f});
      const double a = px.x - p0.x, c = px.y - p0.y;  // column 1 of A
      const double b = py.x - p0.x, d = py.y - p0.y;  // column 2 of A
      const double det = a * d - b * c;
      faces_[f] = {p0.x, p0.y, d / det, -b / det, -c / det, a / det};
    }
  }
}

SkyDirection SkydomeProjection::from_openexr_frame(double x, double y, double z) {
  // OpenEXR frame: +y up, +z North, +x West; local frame: x East, y North, z up.
  const Vec3 local{-x, z, y};
  return SkyDirection::from_unit_vector(normalize(local));
}

bool SkydomeProjection::direction(int x, int y, SkyDirection& out) const {
  switch (projection_) {
    case Projection::fisheye: {
      const double u = 2.0 * (x + 0.5) / size_ - 1.0;  // right
      const double v = 1.0 - 2.0 * (y + 0.5) / size_;  // up
      const double r = std::sqrt(u * u + v * v);
      if (r > 1.0) return false;
      out = {r * 0.5 * kPi, std::atan2(-u, v)};
      return true;
    }
    case Projection::latlong: {
      const IMATH_NAMESPACE::Box2i dw({0, 0}, {width_ - 1, height_ - 1});
      const auto d = Imf::LatLongMap::direction(dw, {static_cast<float>(x), static_cast<float>(y)});
      out = from_openexr_frame(d.x, d.y, d.z);
      return true;
    }
    case Projection::cubemap: {
      const IMATH_NAMESPACE::Box2i dw({0, 0}, {width_ - 1, height_ - 1});
      const int f = y / size_;
      const FaceMap& m = faces_[f];
      const double dx = x - m.origin_x, dy = y - m.origin_y;
      const IMATH_NAMESPACE::V2f pif(static_cast<float>(m.xx * dx + m.xy * dy),
                                     static_cast<float>(m.yx * dx + m.yy * dy));
      const auto d = Imf::CubeMap::direction(static_cast<Imf::CubeMapFace>(f), dw, pif);
      out = from_openexr_frame(d.x, d.y, d.z);
      return true;
    }
  }
  return false;
}

}  // namespace clearsky::api
