// The open format for measured spectral sky radiance (docs/measurement-formats.md), after its
// syntax (CSV: sky_radiance_csv.h, JSON: sky_radiance_json.h): one row per measured value,
// each with its instant, site, view direction, wavelength and radiance. Rows are grouped into
// captures by instant and, within a capture, into measured directions by view zenith and
// azimuth, each direction's rows making its spectrum. Every value is checked here, and every
// refusal is a 400 invalid_body naming the member (the CSV column, or samples[i].member of the
// JSON) with the row, so that a whole upload is checked before it is accepted.
#pragma once

#include <string>
#include <vector>

#include "models/evaluation/measured_sky.h"

namespace clearsky::api {

// One value as read, before it is checked. Members are as written in the file.
struct SkyRadianceRow {
  std::string time;  // ISO 8601 with a UTC offset or Z (api/parse/iso8601_time.h)
  double latitude_deg = 0;
  double longitude_deg = 0;
  double elevation_m = 0;
  double view_zenith_deg = 0;
  double view_azimuth_deg = 0;  // clockwise from North (East 90), as the service's
  double wavelength_nm = 0;
  double radiance_w_m2_sr_nm = 0;
};

// How a row's members are named in refusals: the CSV's "radiance" with "row 12 (line 13)", or
// the JSON's "samples[11].radiance".
class SkyRadianceRowNames {
 public:
  virtual ~SkyRadianceRowNames() = default;
  virtual std::string member(std::size_t row, const std::string& name) const = 0;
  virtual std::string where(std::size_t row) const = 0;
};

// The captures of the rows, ordered by instant, each labelled with its local time
// ("2013-05-27T09:30:00-04:00"); samples in the order their direction first appears, indices
// 0, 1, ...; spectra sorted by wavelength. Refuses (400 invalid_body): a time without offset,
// values out of range (latitude [-90, 90], longitude [-180, 180], elevation_m [-500, 9000],
// view_zenith [0, 180], view_azimuth [0, 360), wavelength_nm (0, 1e6], radiance >= 0), rows of
// one instant with another site or UTC offset, a wavelength given twice for one direction,
// two instants within one second (one label), and no rows at all.
std::vector<MeasuredCapture> sky_radiance_captures(const std::vector<SkyRadianceRow>& rows,
                                                   const SkyRadianceRowNames& names);

}  // namespace clearsky::api
