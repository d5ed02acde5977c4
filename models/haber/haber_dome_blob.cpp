// The byte form of a Haber sky dome (haber_dome_blob.h).
#include "models/haber/haber_dome_blob.h"

#include <cstdint>
#include <cstring>
#include <vector>

namespace clearsky::haber {

namespace {

constexpr char kMagic[8] = {'C', 'S', 'K', 'Y', 'H', 'D', 'O', 'M'};

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

}  // namespace

std::string dome_to_bytes(const HaberDome& dome) {
  const std::span<const double> values = dome.values();
  std::string out;
  out.reserve(sizeof(kMagic) + 32 + values.size_bytes());
  out.append(kMagic, sizeof(kMagic));
  append(out, kDomeBlobVersion);
  append(out, static_cast<std::int32_t>(dome.rings()));
  append(out, static_cast<std::int32_t>(dome.sectors()));
  append(out, static_cast<std::uint64_t>(dome.wavelengths()));
  append(out, dome.angular_step_rad());
  out.append(reinterpret_cast<const char*>(values.data()), values.size_bytes());
  return out;
}

std::shared_ptr<const HaberDome> dome_from_bytes(std::string_view bytes, int rings, int sectors,
                                                 std::size_t wavelengths, double angular_step_rad) {
  if (bytes.size() < sizeof(kMagic) || std::memcmp(bytes.data(), kMagic, sizeof(kMagic)) != 0)
    return nullptr;
  bytes.remove_prefix(sizeof(kMagic));
  std::uint32_t version = 0;
  std::int32_t stored_rings = 0;
  std::int32_t stored_sectors = 0;
  std::uint64_t stored_wavelengths = 0;
  double step = 0;
  if (!read(bytes, version) || !read(bytes, stored_rings) || !read(bytes, stored_sectors) ||
      !read(bytes, stored_wavelengths) || !read(bytes, step))
    return nullptr;
  if (version != kDomeBlobVersion || stored_rings != rings || stored_sectors != sectors ||
      stored_wavelengths != wavelengths || step != angular_step_rad)
    return nullptr;
  const std::size_t count =
      static_cast<std::size_t>(rings) * static_cast<std::size_t>(sectors) * wavelengths;
  if (bytes.size() != count * sizeof(double)) return nullptr;
  std::vector<double> radiance(count);
  std::memcpy(radiance.data(), bytes.data(), bytes.size());
  return std::make_shared<const HaberDome>(rings, sectors, angular_step_rad, wavelengths,
                                           std::move(radiance));
}

}  // namespace clearsky::haber
