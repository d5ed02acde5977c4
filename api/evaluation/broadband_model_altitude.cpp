// The altitude of a model's broadband answer for a site (broadband_model_altitude.h).
#include "api/evaluation/broadband_model_altitude.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace clearsky::api {

ModelAltitude model_altitude_for_site(const ModelDescriptor& descriptor, double site_elevation_m) {
  const ModelCapabilities& caps = descriptor.capabilities;
  if (std::isfinite(site_elevation_m) && site_elevation_m >= caps.min_altitude_m &&
      site_elevation_m <= caps.max_altitude_m)
    return {site_elevation_m, true};
  return {caps.min_altitude_m, false};
}

std::string model_altitude_note(const ModelDescriptor& descriptor,
                                const std::vector<double>& site_elevations_m) {
  std::vector<double> elevations = site_elevations_m;
  std::sort(elevations.begin(), elevations.end());
  elevations.erase(std::unique(elevations.begin(), elevations.end()), elevations.end());
  std::ostringstream sites;
  for (std::size_t i = 0; i < elevations.size(); ++i) sites << (i ? ", " : "") << elevations[i];
  bool all_answered = true;
  for (double e : elevations)
    all_answered = all_answered && model_altitude_for_site(descriptor, e).at_site_elevation;
  const ModelCapabilities& caps = descriptor.capabilities;
  std::ostringstream note;
  if (all_answered) {
    note << "model at the site's elevation (altitude " << sites.str() << " m)";
  } else {
    note << "model at altitude " << caps.min_altitude_m << " m, not at the site's elevation ("
         << sites.str() << " m): " << descriptor.id << " answers altitudes " << caps.min_altitude_m
         << ".." << caps.max_altitude_m << " m only";
  }
  return note.str();
}

}  // namespace clearsky::api
