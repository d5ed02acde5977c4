// The model's sky irradiance on one tilted plane tabulated over the sun's position, for long
// series (docs/building-energy.md "Irradiance time series"). In every model here the sky's
// radiance depends on the sun only through its zenith angle and the azimuth relative to the
// sun (a horizontally uniform atmosphere), so the sky irradiance on a plane of given tilt
// depends on the sun zenith theta_s and on |phi_s - phi_plane| (the sky is symmetric about the
// sun's vertical plane). The table holds the model's own sky_irradiance at theta_s = 0, 2, ...,
// 90 degrees and |delta phi| = 0, 10, ..., 180 degrees (46 x 19 = 874 nodes, one quadrature
// each), and answers by bilinear interpolation; a sun whose cell has a node the model did not
// answer gets nullopt (the caller queries the model). Immutable after construction; thread-safe.
#pragma once

#include <optional>
#include <vector>

#include "models/core/sky_model.h"

namespace clearsky::api {

class PlaneSkyIrradianceTable {
 public:
  static constexpr double kZenithStepDeg = 2.0;
  static constexpr double kAzimuthStepDeg = 10.0;
  static constexpr int kZenithNodes = 46;   // 0 to 90 degrees
  static constexpr int kAzimuthNodes = 19;  // 0 to 180 degrees
  static constexpr std::size_t kNodes = std::size_t{kZenithNodes} * kAzimuthNodes;
  // The nodes are computed on two threads (the machine the speed target is set for: a year on
  // three planes within 2 s on 2 cores, docs/building-energy.md).
  static constexpr unsigned kWorkers = 2;

  // Queries the model at every node (per-sun models are refused: std::logic_error).
  PlaneSkyIrradianceTable(const SkyModel& model, const Viewpoint& viewpoint,
                          const PlaneOrientation& plane);

  // The interpolated sky irradiance on the plane, W/(m2.nm), for a sun above the horizon.
  std::optional<Spectrum> at(const SunPosition& sun) const;

 private:
  const Spectrum* node(int zenith, int azimuth) const;

  PlaneOrientation plane_;
  std::vector<std::optional<Spectrum>> nodes_;  // zenith-major
};

}  // namespace clearsky::api
