// The byte form of a Nishita96 per-sun table set (nishita96_tables.h) for a TableCache, so that
// the table sets of bucketed configurations persist in the server's disk table cache like Haber's
// domes (docs/tables-and-memory.md "Per-sun states"):
//
//   "CSKYN96S"                    8 bytes, magic
//   format version                u32
//   nodes                         i32
//   wavelengths                   u64
//   sun zenith, rad               f64
//   per table (8):
//     angle from the zenith, rad  f64
//     sheared values              u64 count
//     grazing values              u64 count
//   per table (8): its sheared values, then its grazing values, f32, native byte order
//
// The cache file around it carries the key and a checksum (server/cache/file_table_cache.h). A
// blob is used only when every field parses and matches the table set the model would build for
// that sun (the same angles, layouts and sizes, the length exact), otherwise the tables are
// built again: a damaged file is never trusted.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include "models/atmosphere/atmosphere_spectra.h"
#include "models/nishita96/nishita96_tables.h"

namespace clearsky::nishita96 {

inline constexpr std::uint32_t kSunTablesBlobVersion = 1;

std::string sun_tables_to_bytes(const SunTables& tables);
// The table set, or null when the bytes are not the one of this sun, node count and wavelength
// grid (the layouts are those empty_sampling_tables makes).
std::shared_ptr<const SunTables> sun_tables_from_bytes(std::string_view bytes,
                                                       const AtmosphereSpectra& atmosphere,
                                                       double sun_zenith_rad, int nodes,
                                                       int phase_theta_cells);

}  // namespace clearsky::nishita96
