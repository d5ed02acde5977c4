// The byte form of a Haber sky dome (haber_tables.h) for a TableCache, so that the per-sun
// domes persist in the server's disk table cache like the model tables
// (docs/tables-and-memory.md "Per-sun states"):
//
//   "CSKYHDOM"                 8 bytes, magic
//   format version             u32
//   rings, sectors             i32 x 2
//   wavelengths                u64
//   angular step, rad          f64
//   radiance                   f64 x rings x sectors x wavelengths, native byte order
//
// The cache file around it carries the key and a checksum (server/cache/file_table_cache.h); a
// blob is used only when every field parses and matches the grid the model expects, otherwise
// the dome is computed again.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include "models/haber/haber_tables.h"

namespace clearsky::haber {

inline constexpr std::uint32_t kDomeBlobVersion = 1;

std::string dome_to_bytes(const HaberDome& dome);
// The dome, or null when the bytes are not a dome of this shape (rings x sectors x
// wavelengths, angular step).
std::shared_ptr<const HaberDome> dome_from_bytes(std::string_view bytes, int rings, int sectors,
                                                 std::size_t wavelengths, double angular_step_rad);

}  // namespace clearsky::haber
