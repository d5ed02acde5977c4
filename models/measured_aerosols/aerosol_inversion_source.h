// Where measured_aerosols finds an uploaded AERONET inversion by id (its option aerosols;
// models/measured_aerosols/README.md "Uploaded inversions"). The models layer reads no database:
// the server installs a source at start that returns the stored bytes of an id
// (docs/data-api.md "Aerosol inversions"); without one, only the shipped file (id 0) is known.
// Thread-safety: install and lookup may be called from any thread; the installed function is
// called without the registry's lock held, from the calling thread.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace clearsky {

// The option of measured_aerosols that names an uploaded inversion; 0: the shipped file.
inline constexpr const char* kAerosolsOption = "aerosols";

// The stored bytes of an inversion id, or nothing for an id the source does not know.
using AerosolInversionSource = std::function<std::optional<std::string>(std::int64_t id)>;

// Replaces the process-wide source (an empty function: none).
void install_aerosol_inversion_source(AerosolInversionSource source);

// The bytes of the inversion with that id; nothing without a source or for an unknown id.
std::optional<std::string> aerosol_inversion_bytes(std::int64_t id);

}  // namespace clearsky
