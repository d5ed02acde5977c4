// The table cache's reader (server/cache/file_table_cache.h) and what reads its payload, the
// Bruneton tables' byte form (models/bruneton/bruneton_tables.h), with lookups in tables read
// that way. The first byte of an input chooses what the rest is:
//   even: a cache file as found on disk (header, key, checksum, payload);
//   odd:  a Bruneton table blob, stored through the cache (so its header and checksum are
//         right) with its own trailing checksum recomputed, so that the fuzzer reaches the
//         fields behind both checksums rather than stopping at them.
//
// Invariants (docs/fuzzing.md): nothing escapes load() or deserialise_tables(), no sanitizer
// report; a loaded payload is the file's bytes after its header; a stored payload loads back
// unchanged; lookups in any tables that deserialise stay inside them.
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>

#include "fuzz/support/fuzz_check.h"
#include "fuzz/support/scratch_dir.h"
#include "models/bruneton/bruneton_tables.h"
#include "server/cache/file_table_cache.h"

namespace clearsky::fuzz {
namespace {

const std::string kKey = "bruneton-fuzz";

// The blob's trailing checksum (models/bruneton/bruneton_table_blob.cpp): FNV-1a over
// little-endian 64-bit words, then the tail bytes.
std::uint64_t blob_checksum(std::string_view bytes) {
  std::uint64_t h = 14695981039346656037ull;
  const std::size_t words = bytes.size() / 8;
  for (std::size_t i = 0; i < words; ++i) {
    std::uint64_t w;
    std::memcpy(&w, bytes.data() + i * 8, 8);
    h ^= w;
    h *= 1099511628211ull;
  }
  for (std::size_t i = words * 8; i < bytes.size(); ++i) {
    h ^= static_cast<unsigned char>(bytes[i]);
    h *= 1099511628211ull;
  }
  return h;
}

// The description a blob says it was built for (it is compared, not interpreted).
std::string description_of(std::string_view blob) {
  if (blob.size() < 16) return {};
  std::uint32_t size = 0;
  std::memcpy(&size, blob.data() + 12, sizeof size);
  return std::string(blob.substr(16, size));
}

void look_up(const bruneton::Tables& t) {
  std::vector<float> out(static_cast<std::size_t>(t.stride) + 16);
  const double bottom = t.geometry.bottom_m, top = t.geometry.top_m;
  for (const double r : {bottom, 0.5 * (bottom + top), top}) {
    for (const double mu : {-1.0, -0.1, 0.0, 0.3, 1.0}) {
      t.transmittance_to_top(r, mu, out.data());
      t.transmittance_between(r, mu, 0.25 * (top - bottom), out.data());
      t.irradiance(r, mu, out.data());
      for (const double nu : {-1.0, 0.0, 1.0}) t.scattering(r, mu, mu, nu, 0.8, out.data());
    }
  }
}

}  // namespace
}  // namespace clearsky::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace clearsky;
  using namespace clearsky::fuzz;
  static ScratchDir scratch("table_cache");
  static server::FileTableCache cache(scratch.path / "cache");
  if (size == 0) return 0;
  const std::string_view rest(reinterpret_cast<const char*>(data) + 1, size - 1);

  std::optional<std::string> payload;
  if (data[0] % 2 == 0) {
    std::ofstream(cache.path_of(kKey), std::ios::binary | std::ios::trunc)
        .write(rest.data(), static_cast<std::streamsize>(rest.size()));
    payload = cache.load(kKey);
    if (!payload) return 0;
    check(rest.ends_with(*payload), "a loaded payload that is not the file's tail");
    check(rest.size() == 32 + kKey.size() + payload->size(),
          "a loaded payload with another size than the header says");
  } else {
    std::string blob(rest);
    if (blob.size() >= 8) {
      const std::uint64_t sum = blob_checksum(std::string_view(blob).substr(0, blob.size() - 8));
      std::memcpy(blob.data() + blob.size() - 8, &sum, sizeof sum);
    }
    cache.store(kKey, blob);
    payload = cache.load(kKey);
    check(payload.has_value() && *payload == blob, "a stored payload does not load back");
  }
  const std::optional<bruneton::Tables> tables =
      bruneton::deserialise_tables(*payload, description_of(*payload));
  if (tables) look_up(*tables);
  return 0;
}
