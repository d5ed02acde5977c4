// The byte form of a Nishita96 per-sun table set (nishita96_sun_tables_blob.h).
#include "models/nishita96/nishita96_sun_tables_blob.h"

#include <cstring>
#include <utility>
#include <vector>

namespace clearsky::nishita96 {

namespace {

constexpr char kMagic[8] = {'C', 'S', 'K', 'Y', 'N', '9', '6', 'S'};

template <class T>
void append(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof(T));
}

template <class T>
bool read(std::string_view& in, T& value) {
  if (in.size() < sizeof(T)) return false;
  std::memcpy(&value, in.data(), sizeof(T));
  in.remove_prefix(sizeof(T));
  return true;
}

void append_values(std::string& out, std::span<const float> values) {
  out.append(reinterpret_cast<const char*>(values.data()), values.size_bytes());
}

bool read_values(std::string_view& in, std::span<float> values) {
  if (in.size() < values.size_bytes()) return false;
  if (values.empty()) return true;  // an empty span's data() may be null: no memcpy from it
  std::memcpy(values.data(), in.data(), values.size_bytes());
  in.remove_prefix(values.size_bytes());
  return true;
}

}  // namespace

std::string sun_tables_to_bytes(const SunTables& tables) {
  std::string out;
  out.reserve(tables.memory_bytes() + 256);
  out.append(kMagic, sizeof(kMagic));
  append(out, kSunTablesBlobVersion);
  append(out, static_cast<std::int32_t>(tables.table(0).nodes()));
  append(out, static_cast<std::uint64_t>(tables.table(0).wavelengths()));
  append(out, tables.sun_zenith_rad());
  for (int k = 0; k < kSamplingDirections; ++k) {
    const SamplingTable& t = tables.table(k);
    append(out, t.angle_rad());
    append(out, static_cast<std::uint64_t>(t.sheared_values().size()));
    append(out, static_cast<std::uint64_t>(t.grazing_values().size()));
  }
  for (int k = 0; k < kSamplingDirections; ++k) {
    append_values(out, tables.table(k).sheared_values());
    append_values(out, tables.table(k).grazing_values());
  }
  return out;
}

std::shared_ptr<const SunTables> sun_tables_from_bytes(std::string_view bytes,
                                                       const AtmosphereSpectra& atmosphere,
                                                       double sun_zenith_rad, int nodes,
                                                       int phase_theta_cells) {
  if (bytes.size() < sizeof(kMagic) || std::memcmp(bytes.data(), kMagic, sizeof(kMagic)) != 0)
    return nullptr;
  bytes.remove_prefix(sizeof(kMagic));
  std::uint32_t version = 0;
  std::int32_t stored_nodes = 0;
  std::uint64_t stored_wavelengths = 0;
  double stored_zenith = 0;
  if (!read(bytes, version) || !read(bytes, stored_nodes) || !read(bytes, stored_wavelengths) ||
      !read(bytes, stored_zenith))
    return nullptr;
  if (version != kSunTablesBlobVersion || stored_nodes != nodes ||
      stored_wavelengths != atmosphere.grid.size() || stored_zenith != sun_zenith_rad)
    return nullptr;
  // The layouts this model builds for the sun; the stored ones must be exactly these.
  std::vector<SamplingTable> tables = empty_sampling_tables(atmosphere, sun_zenith_rad, nodes);
  for (const SamplingTable& t : tables) {
    double angle = 0;
    std::uint64_t sheared = 0;
    std::uint64_t grazing = 0;
    if (!read(bytes, angle) || !read(bytes, sheared) || !read(bytes, grazing)) return nullptr;
    if (angle != t.angle_rad() || sheared != t.sheared_values().size() ||
        grazing != t.grazing_values().size())
      return nullptr;
  }
  for (SamplingTable& t : tables) {
    if (!read_values(bytes, t.sheared_values()) || !read_values(bytes, t.grazing_values()))
      return nullptr;
  }
  if (!bytes.empty()) return nullptr;
  return std::make_shared<const SunTables>(sun_zenith_rad, std::move(tables), phase_theta_cells);
}

}  // namespace clearsky::nishita96
