// A measured sky: one capture of a sky-scanning spectroradiometer (Kider et al. 2014, ACM TOG
// 33(6)), as the importers produce it and the evaluation consumes it. Spectra are kept as
// measured (1 nm steps, W/(m2.sr.nm)); corrections such as the repair of the defective North
// sample are explicit steps recorded in `processing_steps`, never applied silently by a loader.
// Directions follow the project's convention (radians, azimuth clockwise from North); the
// Kider file names' counter-clockwise azimuths are converted by the importer, in one place.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "models/core/geometry.h"
#include "models/spectral/tabulated_spectrum.h"

namespace clearsky {

// Where a capture was taken: geodetic latitude/longitude (degrees, North and East positive)
// and elevation above sea level (m).
struct SiteLocation {
  double latitude_deg = 0;
  double longitude_deg = 0;
  double elevation_m = 0;
};

// The Kider et al. 2014 site: roof of Rhodes Hall, Cornell University (Kider et al. 2014).
inline SiteLocation kider_cornell_site() { return {42.443449, -76.481962, 250.0}; }

// Quality flags of a sample (bit set).
enum SampleQualityFlag : std::uint32_t {
  // Known to be wrong as measured: Kider's sample 0 (North, lowest ring) is systematically off
  // (Bruneton 2016; models/evaluation/README.md).
  kSampleKnownDefective = 1u << 0,
  // The spectrum was replaced by the mean of its two ring neighbours (repair_defective_samples).
  kSampleRepaired = 1u << 1,
};

struct MeasuredSample {
  int index = 0;       // position in the instrument's scan sequence (Kider: file index 0..80)
  ViewDirection view;  // radians, azimuth clockwise from North
  TabulatedSpectrum radiance;  // W/(m2.sr.nm) against wavelength (nm)
  std::uint32_t quality_flags = 0;
};

constexpr double kNotComputed = std::numeric_limits<double>::quiet_NaN();

struct MeasuredCapture {
  std::string label;           // e.g. "2013-05-27___09.30.00" (the Kider archive name)
  double unix_time_utc_s = 0;  // instant of the capture (seconds since 1970-01-01T00:00Z)
  int utc_offset_minutes = 0;  // local time of the site = UTC + offset (EDT: -240)
  SiteLocation site;
  std::vector<MeasuredSample> samples;  // in scan order
  // Sun position from the time and place (degrees; NaN until computed), and the sun azimuth
  // estimated from the measured sky's mirror symmetry (degrees clockwise from North).
  double sun_zenith_computed_deg = kNotComputed;
  double sun_azimuth_computed_deg = kNotComputed;
  double sun_azimuth_estimated_deg = kNotComputed;
  // Human-readable record of every correction applied since import, in order.
  std::vector<std::string> processing_steps;
};

// ISO 8601 local time with offset, e.g. "2013-05-27T09:30:00-04:00".
std::string local_time_iso8601(double unix_time_utc_s, int utc_offset_minutes);
inline std::string local_time_iso8601(const MeasuredCapture& capture) {
  return local_time_iso8601(capture.unix_time_utc_s, capture.utc_offset_minutes);
}

}  // namespace clearsky
