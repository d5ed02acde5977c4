// The byte form of the Bruneton tables for a TableCache (bruneton_tables.h):
//
//   "CSKYBRUN"                       8 bytes, magic
//   format version                   u32
//   description length, bytes        u32 + bytes (model, table version, configuration)
//   wavelengths, stride              i32 x 2
//   resolution                       i32 x 13
//   radii (bottom, top, limit)       f64 x 3
//   5 arrays                         each u64 element count + raw little-endian elements
//   checksum                         u64, word-wise FNV-1a of every byte before it
//
// A blob is trusted only if every field parses, every array has the size its resolution
// implies, the description matches exactly and the checksum agrees: a corrupt or stale blob is
// rebuilt, never used.
#include <bit>
#include <cstring>

#include "models/bruneton/bruneton_tables.h"

namespace clearsky::bruneton {

namespace {

constexpr char kMagic[8] = {'C', 'S', 'K', 'Y', 'B', 'R', 'U', 'N'};

// FNV-1a over 64-bit words (8x faster than byte-wise on the ~250 MB of tables), the tail
// byte-wise.
std::uint64_t checksum(std::string_view bytes) {
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

class Writer {
 public:
  template <typename T>
  void value(T v) {
    out_.append(reinterpret_cast<const char*>(&v), sizeof(T));
  }
  void bytes(std::string_view b) { out_.append(b.data(), b.size()); }
  template <typename T>
  void array(const std::vector<T>& v) {
    value<std::uint64_t>(v.size());
    out_.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
  }
  std::string& str() { return out_; }

 private:
  std::string out_;
};

class Reader {
 public:
  explicit Reader(std::string_view in) : in_(in) {}
  template <typename T>
  bool value(T& v) {
    if (in_.size() - pos_ < sizeof(T)) return false;
    std::memcpy(&v, in_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return true;
  }
  bool bytes(std::size_t n, std::string_view& b) {
    if (in_.size() - pos_ < n) return false;
    b = in_.substr(pos_, n);
    pos_ += n;
    return true;
  }
  template <typename T>
  bool array(std::vector<T>& v, std::size_t expected) {
    std::uint64_t n = 0;
    if (!value(n) || n != expected || (in_.size() - pos_) / sizeof(T) < n) return false;
    v.resize(n);
    // An empty array (the multiple-scattering table of one order) has no data(): memcpy must
    // not be given its null pointer, even for no bytes.
    if (n > 0) std::memcpy(v.data(), in_.data() + pos_, n * sizeof(T));
    pos_ += n * sizeof(T);
    return true;
  }
  std::size_t position() const { return pos_; }

 private:
  std::string_view in_;
  std::size_t pos_ = 0;
};

int* resolution_fields(Resolution& r, int index) {
  int* fields[13] = {&r.transmittance_mu,
                     &r.transmittance_r,
                     &r.irradiance_mu_s,
                     &r.irradiance_r,
                     &r.r,
                     &r.mu,
                     &r.mu_s,
                     &r.nu,
                     &r.transmittance_steps,
                     &r.inscatter_steps,
                     &r.sphere_samples,
                     &r.irradiance_samples,
                     &r.orders};
  return fields[index];
}

}  // namespace

std::string serialise_tables(const Tables& tables, std::string_view description) {
  static_assert(std::endian::native == std::endian::little, "the table format is little-endian");
  Writer w;
  w.bytes({kMagic, sizeof(kMagic)});
  w.value<std::uint32_t>(kTableFormatVersion);
  w.value<std::uint32_t>(static_cast<std::uint32_t>(description.size()));
  w.bytes(description);
  w.value<std::int32_t>(tables.wavelengths);
  w.value<std::int32_t>(tables.stride);
  Resolution res = tables.resolution;
  for (int i = 0; i < 13; ++i) w.value<std::int32_t>(*resolution_fields(res, i));
  w.value<double>(tables.geometry.bottom_m);
  w.value<double>(tables.geometry.top_m);
  w.value<double>(tables.geometry.limit_m);
  w.array(tables.transmittance.values);
  w.array(tables.sky_irradiance.values);
  for (const HalfTable4D* t : {&tables.single_rayleigh, &tables.single_mie, &tables.multiple}) {
    w.array(t->values);
    w.array(t->row_scale);
  }
  const std::uint64_t sum = checksum(w.str());
  w.value<std::uint64_t>(sum);
  return std::move(w.str());
}

std::optional<Tables> deserialise_tables(std::string_view bytes, std::string_view description,
                                         const SunRange& sun) {
  if (bytes.size() < sizeof(kMagic) + 8 + sizeof(std::uint64_t)) return std::nullopt;
  // The checksum first: nothing of a corrupt blob is interpreted.
  const std::string_view body = bytes.substr(0, bytes.size() - sizeof(std::uint64_t));
  std::uint64_t stored = 0;
  std::memcpy(&stored, bytes.data() + body.size(), sizeof(stored));
  if (stored != checksum(body)) return std::nullopt;

  Reader r(body);
  std::string_view magic;
  std::uint32_t version = 0, description_size = 0;
  std::string_view stored_description;
  if (!r.bytes(sizeof(kMagic), magic) || magic != std::string_view(kMagic, sizeof(kMagic)))
    return std::nullopt;
  if (!r.value(version) || version != kTableFormatVersion) return std::nullopt;
  if (!r.value(description_size) || !r.bytes(description_size, stored_description) ||
      stored_description != description) {
    return std::nullopt;
  }
  Tables t;
  std::int32_t wavelengths = 0, stride = 0;
  if (!r.value(wavelengths) || !r.value(stride)) return std::nullopt;
  if (wavelengths <= 0 || stride != padded_stride(wavelengths)) return std::nullopt;
  t.wavelengths = wavelengths;
  t.stride = stride;
  for (int i = 0; i < 13; ++i) {
    std::int32_t v = 0;
    if (!r.value(v) || v <= 0 || v > 100000) return std::nullopt;
    *resolution_fields(t.resolution, i) = v;
  }
  t.resolution.sun = sun;
  const Resolution& res = t.resolution;
  if (res.texels_4d() > (1LL << 28)) return std::nullopt;
  if (!r.value(t.geometry.bottom_m) || !r.value(t.geometry.top_m) || !r.value(t.geometry.limit_m))
    return std::nullopt;
  if (!(t.geometry.bottom_m > 0.0 && t.geometry.top_m > t.geometry.bottom_m &&
        t.geometry.limit_m > t.geometry.top_m)) {
    return std::nullopt;
  }
  t.transmittance.width = res.transmittance_mu;
  t.transmittance.height = res.transmittance_r;
  t.transmittance.stride = stride;
  t.sky_irradiance.width = res.irradiance_mu_s;
  t.sky_irradiance.height = res.irradiance_r;
  t.sky_irradiance.stride = stride;
  if (!r.array(t.transmittance.values,
               static_cast<std::size_t>(res.transmittance_mu) * res.transmittance_r * stride) ||
      !r.array(t.sky_irradiance.values,
               static_cast<std::size_t>(res.irradiance_mu_s) * res.irradiance_r * stride)) {
    return std::nullopt;
  }
  const std::size_t values_4d = static_cast<std::size_t>(res.texels_4d()) * stride;
  const std::size_t rows_4d = static_cast<std::size_t>(res.r) * res.mu;
  for (HalfTable4D* table : {&t.single_rayleigh, &t.single_mie, &t.multiple}) {
    table->res_r = res.r;
    table->res_mu = res.mu;
    table->res_nu = res.nu;
    table->res_mu_s = res.mu_s;
    table->stride = stride;
    const bool optional = table == &t.multiple && res.orders == 1;
    if (!r.array(table->values, optional ? 0 : values_4d) ||
        !r.array(table->row_scale, optional ? 0 : rows_4d)) {
      return std::nullopt;
    }
  }
  if (r.position() != body.size()) return std::nullopt;
  return t;
}

}  // namespace clearsky::bruneton
