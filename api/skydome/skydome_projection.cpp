// Pixel directions of the skydome projections, through OpenEXR's environment-map functions.
#include "api/skydome/skydome_projection.h"

#include <OpenEXR/ImfEnvmap.h>

#include <algorithm>
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

Vec3 SkydomeProjection::to_openexr_frame(const SkyDirection& d) {
  const Vec3 local = d.unit_vector();
  return {-local.x, local.z, local.y};
}

void SkydomeProjection::face_position(int x, int y, int f, double& px, double& py) const {
  const FaceMap& m = faces_[f];
  const double dx = x - m.origin_x, dy = y - m.origin_y;
  px = m.xx * dx + m.xy * dy;
  py = m.yx * dx + m.yy * dy;
}

bool SkydomeProjection::pixel(const SkyDirection& d, int& x, int& y) const {
  const auto nearest = [&](double fx, double fy) {
    x = std::clamp(static_cast<int>(std::lround(fx)), 0, width_ - 1);
    y = std::clamp(static_cast<int>(std::lround(fy)), 0, height_ - 1);
  };
  switch (projection_) {
    case Projection::fisheye: {
      const double r = d.zenith_rad / (0.5 * kPi);
      if (r > 1.0) return false;
      const double u = -r * std::sin(d.azimuth_rad), v = r * std::cos(d.azimuth_rad);
      nearest((u + 1.0) * 0.5 * size_ - 0.5, (1.0 - v) * 0.5 * size_ - 0.5);
      SkyDirection seen;
      return direction(x, y, seen);
    }
    case Projection::latlong: {
      const IMATH_NAMESPACE::Box2i dw({0, 0}, {width_ - 1, height_ - 1});
      const Vec3 e = to_openexr_frame(d);
      const auto p = Imf::LatLongMap::pixelPosition(
          dw, IMATH_NAMESPACE::V3f(static_cast<float>(e.x), static_cast<float>(e.y),
                                   static_cast<float>(e.z)));
      nearest(p.x, p.y);
      return true;
    }
    case Projection::cubemap: {
      const IMATH_NAMESPACE::Box2i dw({0, 0}, {width_ - 1, height_ - 1});
      const Vec3 e = to_openexr_frame(d);
      Imf::CubeMapFace face;
      IMATH_NAMESPACE::V2f pif;
      Imf::CubeMap::faceAndPixelPosition(
          IMATH_NAMESPACE::V3f(static_cast<float>(e.x), static_cast<float>(e.y),
                               static_cast<float>(e.z)),
          dw, face, pif);
      const auto p = Imf::CubeMap::pixelPosition(face, dw, pif);
      nearest(p.x, p.y);
      return true;
    }
  }
  return false;
}

double SkydomeProjection::pixel_solid_angle_sr(int x, int y) const {
  switch (projection_) {
    case Projection::fisheye: {
      // Equidistant: zenith = (pi/2) r, so d Omega = sin(zenith) d zenith d phi
      // = (pi/2) sin(pi r / 2) / r dA in the image's unit disc.
      const double u = 2.0 * (x + 0.5) / size_ - 1.0;
      const double v = 1.0 - 2.0 * (y + 0.5) / size_;
      const double r = std::sqrt(u * u + v * v);
      const double cell = (2.0 / size_) * (2.0 / size_);
      const double jacobian =
          r > 1e-12 ? 0.5 * kPi * std::sin(0.5 * kPi * r) / r : 0.25 * kPi * kPi;
      return cell * jacobian;
    }
    case Projection::latlong: {
      // OpenEXR's latlong map (ImfEnvmap.h): row y at latitude pi (1/2 - y/(height-1)), column
      // x at longitude 2 pi (1/2 - x/(width-1)).
      const double d_lat = kPi / (height_ - 1), d_lon = 2.0 * kPi / (width_ - 1);
      const double lat = kPi * (0.5 - static_cast<double>(y) / (height_ - 1));
      const double top = std::min(lat + 0.5 * d_lat, 0.5 * kPi);
      const double bottom = std::max(lat - 0.5 * d_lat, -0.5 * kPi);
      return d_lon * (std::sin(top) - std::sin(bottom));
    }
    case Projection::cubemap: {
      // A face spans [-1, 1]^2 at distance 1, sampled at 2 p/(size-1) - 1 (ImfEnvmap.h).
      double px = 0, py = 0;
      face_position(x, y, y / size_, px, py);
      const double a = 2.0 * px / (size_ - 1) - 1.0, b = 2.0 * py / (size_ - 1) - 1.0;
      const double step = 2.0 / (size_ - 1);
      return step * step / std::pow(1.0 + a * a + b * b, 1.5);
    }
  }
  return 0.0;
}

bool SkydomeProjection::latlong_row_below_horizon(int y) const {
  if (projection_ != Projection::latlong) return false;
  SkyDirection d;
  return direction(0, y, d) && d.zenith_rad > 0.5 * kPi;
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
      double px = 0, py = 0;
      face_position(x, y, f, px, py);
      const IMATH_NAMESPACE::V2f pif(static_cast<float>(px), static_cast<float>(py));
      const auto d = Imf::CubeMap::direction(static_cast<Imf::CubeMapFace>(f), dw, pif);
      out = from_openexr_frame(d.x, d.y, d.z);
      return true;
    }
  }
  return false;
}

}  // namespace clearsky::api
