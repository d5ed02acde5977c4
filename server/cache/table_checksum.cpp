// XXH3 64-bit of a payload (table_checksum.h), seed 0.
#include "server/cache/table_checksum.h"

#include <xxhash.h>

namespace clearsky::server {

std::uint64_t table_checksum(std::string_view payload) {
  return XXH3_64bits(payload.data(), payload.size());
}

}  // namespace clearsky::server
