// A sky vector: the radiance of a model's sky averaged over each patch of a SkyPatchScheme
// (docs/building-energy.md), what Radiance's genskyvec and gendaymtx produce for its
// daylight-coefficient tools, from any registered model:
//  - sky patch k (Radiance's number, 1 ..): the integral of the spectral sky radiance over the
//    patch (patch_quadrature.h) divided by its solid angle, W/(m2.sr.nm);
//  - the sun: SunHandling::separate reports it as its own source (its direction, the solid
//    angle of its disk and the radiance that spreads the direct normal irradiance over it);
//    SunHandling::patch adds direct normal irradiance / patch solid angle to the patch holding
//    the sun's centre, so that the patch carries the sun's irradiance (as gendaymtx's vectors
//    carry it in patches). A sun below the horizon adds nothing;
//  - patch 0, the ground: a Lambertian ground of the given reflectance under the global
//    horizontal irradiance (direct + the sky's), rho E / pi, as gendaymtx's ground patch.
// diffuse_horizontal is the check a daylighting user makes on a sky vector: the horizontal
// irradiance of the sky the vector stands for, each patch uniformly at its value, the sum over
// the sky patches of value x projected solid angle (the integral of cos(zenith) over the
// patch), sun excluded.
// The radiance is queried a few thousand directions at a time, so the memory held is bounded by
// the answer (patches x wavelengths), not by the quadrature's nodes x wavelengths.
// Pure given the model; thread-safe (the model's queries are).
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "api/skypatches/patch_quadrature.h"
#include "api/skypatches/sky_patch_scheme.h"
#include "models/core/sky_model.h"

namespace clearsky::api {

enum class SunHandling { separate, patch };

// The integral of cos(zenith) over the patch, sr.
double projected_solid_angle_sr(const SkyPatch& patch);

// The sun's disk: mean angular radius 0.2666 degrees (the nominal solar radius, IAU 2015
// Resolution B3, at 1 au), 6.80e-5 sr.
double sun_disk_solid_angle_sr();

struct SunSource {
  SkyDirection direction;
  double solid_angle_sr = 0;
  Spectrum radiance;  // W/(m2.sr.nm): direct normal irradiance / solid angle
};

struct SkyPatchVector {
  // The first sample the model did not answer (the others then unset); ok otherwise.
  SampleStatus status = SampleStatus::ok;
  // patches[k]: Radiance's patch k (0 the ground), on the model's wavelengths, W/(m2.sr.nm).
  std::vector<Spectrum> patches;
  std::optional<SunSource> sun;  // SunHandling::separate with the sun above the horizon
  std::size_t sun_patch = 0;     // the patch holding the sun's centre; 0 below the horizon
  Spectrum diffuse_horizontal;   // W/(m2.nm), value x projected solid angle, summed
  Spectrum direct_normal;        // W/(m2.nm), 0 below the horizon
  std::size_t directions = 0;    // radiance queries made (the quadrature's nodes)
};

SkyPatchVector compute_sky_patch_vector(const SkyModel& model, const SunState& sun,
                                        const Viewpoint& viewpoint, const SkyPatchScheme& scheme,
                                        const PatchQuadratureOrder& order, SunHandling handling,
                                        double ground_reflectance);

}  // namespace clearsky::api
