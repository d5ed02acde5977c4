// The aerosols option of measured_aerosols (models/measured_aerosols/README.md "Uploaded
// inversions") checked where parameters are parsed, before any build is queued: a non-zero id
// must name an inversion the installed source knows (the server's aerosol_inversions table;
// docs/data-api.md "Aerosol inversions"). A query replica installs no source, so every non-zero
// id is unknown there.
// Thread-safety: as aerosol_inversion_bytes (models/measured_aerosols/aerosol_inversion_source.h).
#pragma once

#include <string>

namespace clearsky::api {

// For the option aerosols with a non-zero value: 404 unknown_aerosols naming aerosols when the
// source has no such inversion. Any other name or value: nothing.
void check_aerosols_option(const std::string& name, double value);

}  // namespace clearsky::api
