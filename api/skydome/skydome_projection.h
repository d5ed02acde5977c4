// Where each pixel of a skydome image looks (GET /v1/skydome, docs/http-api.md):
//  - fisheye: size x size, equidistant (zenith angle proportional to the distance from the
//    centre; the horizon on the inscribed circle), seen from below looking up: North at the
//    top, East on the LEFT, as on a sky chart. Pixels outside the circle see nothing.
//  - latlong: size x size/2, OpenEXR's latitude-longitude environment map (ImfEnvmap.h), with
//    OpenEXR's +y up and +z North (so +x West): North at the centre column, East to its right,
//    the zenith on the top row, the nadir on the bottom row.
//  - cubemap: size x 6 size, OpenEXR's cube map (faces +X, -X, +Y, -Y, +Z, -Z stacked
//    vertically, ImfEnvmap.h) in the same frame as latlong.
// Pixel (x, y) is sampled at its centre for fisheye and at OpenEXR's pixel position (x, y) for
// the environment maps, so that OpenEXR-aware readers look the map up consistently.
// Immutable; thread-safe.
#pragma once

#include <array>
#include <string>

#include "models/core/geometry.h"

namespace clearsky::api {

enum class Projection { fisheye, latlong, cubemap };

class SkydomeProjection {
 public:
  SkydomeProjection(Projection projection, int size);
  Projection projection() const { return projection_; }
  int width() const { return width_; }
  int height() const { return height_; }
  // The direction pixel (x, y) sees, or false when it sees none (outside the fisheye circle).
  bool direction(int x, int y, SkyDirection& out) const;

  // Latlong only (false for the other projections): whether every pixel of row y looks below
  // the horizon, i.e. has direction()'s zenith above pi/2. OpenEXR's latlong direction of a
  // pixel has the up component sin(latitude) of its row, the same float in every column, and
  // from_openexr_frame() only divides it by the vector's positive length, so the sign of the
  // zenith cosine, and with it the side of the horizon, is the row's; it is read from column 0.
  // Lets a skydome fill the rows under the horizon without a direction per pixel.
  bool latlong_row_below_horizon(int y) const;

  // The pixel whose sample position is nearest to direction d (the inverse of direction()), or
  // false when no pixel sees it (outside the fisheye circle). Used to place the solar disc.
  bool pixel(const SkyDirection& d, int& x, int& y) const;
  // Solid angle of pixel (x, y), sr: the area of the pixel's cell in the projection's own
  // coordinates times the projection's Jacobian at its sample position (fisheye: equidistant,
  // latlong: cos(latitude) with OpenEXR's spacing pi/(height-1) and 2 pi/(width-1), cubemap:
  // 1/(1 + a^2 + b^2)^(3/2) on the face with spacing 2/(size-1)). The solar disc divides its
  // irradiance by it, so that a pixel's radiance times its solid angle is the light it carries.
  double pixel_solid_angle_sr(int x, int y) const;

  static SkyDirection from_openexr_frame(double x, double y, double z);
  // The inverse: OpenEXR's frame (+y up, +z North, +x West) of a direction.
  static Vec3 to_openexr_frame(const SkyDirection& d);

 private:
  Projection projection_;
  int size_;
  int width_, height_;
  // Cube map: per face, image pixel -> position in face, as an affine map (OpenEXR lays each
  // face out with flips and swaps, so the inverse is read from its forward map).
  struct FaceMap {
    double origin_x, origin_y, xx, xy, yx, yy;
  };
  std::array<FaceMap, 6> faces_{};
  // Cube map: the position in face f of image pixel (x, y).
  void face_position(int x, int y, int f, double& px, double& py) const;
};

}  // namespace clearsky::api
