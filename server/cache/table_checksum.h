// The checksum of a table-cache payload (file_table_cache.h): XXH3, 64-bit (xxHash, Debian
// libxxhash). Not cryptographic: it detects a damaged or truncated file, it does not resist
// tampering. XXH3 reads the Bruneton table (254 MB) at memory speed, where the byte-at-a-time
// FNV-1a it replaced (format version 1) was the largest cost of a cache hit.
#pragma once

#include <cstdint>
#include <string_view>

namespace clearsky::server {

std::uint64_t table_checksum(std::string_view payload);

}  // namespace clearsky::server
