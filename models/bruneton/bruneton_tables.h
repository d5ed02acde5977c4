// The precomputed tables of Bruneton and Neyret 2008 (Algorithm 4.1), as the 2016 study
// built them: transmittance T (2D), sky irradiance E (2D, orders 1..3 of the light reaching a
// horizontal plane, the direct sun excluded), single scattering without phase function kept as
// separate Rayleigh and Mie 4D tables, and the sum of orders 2..4 (4D). All values are per
// unit extraterrestrial solar irradiance: queries multiply by the solar spectrum.
//
// Storage: the 2D tables in float; the 4D tables in binary16 with a power-of-two scale per
// (r, mu) row (value = half * row_scale), so that the three resident 4D tables of 1,048,576
// texels x 40 wavelengths take 252 MB instead of 504 MB in float. The intermediate tables of
// the precomputation (density J, per-order scattering) use the same storage, and at most three
// 4D tables are held at once (the single-scattering tables are built again after the later
// orders), so the precomputation peaks near 273 MB (docs/tables-and-memory.md). Geometry and
// integration weights are computed in double, spectral arithmetic in float.
//
// Immutable once built; thread-safe for concurrent reads.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "models/atmosphere/atmosphere_spectra.h"
#include "models/atmosphere/phase_functions.h"
#include "models/atmosphere/tabulated_phase_function.h"
#include "models/bruneton/bruneton_functions.h"
#include "models/bruneton/spectral_rows.h"
#include "models/core/precompute_context.h"

namespace clearsky::bruneton {

// A 2D table of spectra in float: texel (x, y) at values[(y * width + x) * stride].
struct FloatTable2D {
  int width = 0, height = 0, stride = 0;
  std::vector<float> values;

  void allocate(int w, int h, int s);
  const float* texel(int x, int y) const {
    return values.data() + (static_cast<std::size_t>(y) * width + x) * stride;
  }
  float* texel(int x, int y) {
    return values.data() + (static_cast<std::size_t>(y) * width + x) * stride;
  }
};

// A 4D table of spectra in binary16, indexed (r, mu, nu, mu_s) with mu_s fastest (the 2008
// code's 3D texture with x = nu * RES_MU_S + mu_s). Row (r, mu) holds res_nu * res_mu_s texels
// and one scale.
struct HalfTable4D {
  int res_r = 0, res_mu = 0, res_nu = 0, res_mu_s = 0, stride = 0;
  std::vector<std::uint16_t> values;
  std::vector<float> row_scale;  // per (r, mu)

  void allocate(const Resolution& res, int s);
  bool empty() const { return values.empty(); }
  std::size_t row_texels() const { return static_cast<std::size_t>(res_nu) * res_mu_s; }
  std::size_t row_index(int r, int mu) const { return static_cast<std::size_t>(r) * res_mu + mu; }
  const std::uint16_t* texel(int r, int mu, int nu, int mu_s) const {
    return values.data() + ((row_index(r, mu) * res_nu + nu) * res_mu_s + mu_s) * stride;
  }
  // Converts a row of row_texels() * stride floats (texel (nu, mu_s) at (nu * res_mu_s + mu_s) *
  // stride), choosing the row's scale from its largest magnitude.
  void store_row(int r, int mu, const float* row);
  void load_row(int r, int mu, float* row) const;
  std::size_t bytes() const {
    return values.size() * sizeof(std::uint16_t) + row_scale.size() * sizeof(float);
  }
};

// The rows and weights of one lookup, summed by sum_rows().
template <typename T>
struct RowList {
  std::vector<const T*> rows;
  std::vector<float> weights;
  void clear() {
    rows.clear();
    weights.clear();
  }
  void add(const T* row, double weight) {
    if (weight == 0.0) return;
    rows.push_back(row);
    weights.push_back(static_cast<float>(weight));
  }
  void sum(int stride, float* out) const {
    sum_rows(rows.data(), weights.data(), static_cast<int>(rows.size()), stride, out);
  }
};

// At most `Capacity` rows, without allocation: the query path.
template <typename T, int Capacity>
struct FixedRowList {
  const T* rows[Capacity];
  float weights[Capacity];
  int count = 0;
  void add(const T* row, double weight) {
    if (weight == 0.0) return;
    rows[count] = row;
    weights[count++] = static_cast<float>(weight);
  }
  void sum(int stride, float* out) const { sum_rows(rows, weights, count, stride, out); }
};

// The two neighbouring texel indices of each coordinate of a 4D lookup and their linear
// interpolation weights (1 - f, f), as gather_4d() and its same-texel variant read them.
struct LookupCorners4 {
  int r_index[2];
  double r_weight[2];
  int mu_index[2];
  double mu_weight[2];
  int ms_index[2];
  double ms_weight[2];
  int nu_index[2];
  double nu_weight[2];

  explicit LookupCorners4(const Coord4& c)
      : r_index{c.r.i0, c.r.i1},
        r_weight{1.0 - c.r.f, c.r.f},
        mu_index{c.mu.i0, c.mu.i1},
        mu_weight{1.0 - c.mu.f, c.mu.f},
        ms_index{c.mu_s.i0, c.mu_s.i1},
        ms_weight{1.0 - c.mu_s.f, c.mu_s.f},
        nu_index{c.nu.i0, c.nu.i1},
        nu_weight{1.0 - c.nu.f, c.nu.f} {}
};

// Adds the (up to 16) texels of a 4D lookup at coordinates c, each weighted by its
// interpolation weight times `weight` times its row scale. The table's sizes and pointers are
// read into locals first: a row pointer stored into the list may alias them as far as the
// compiler knows, and it would reload them for every texel (306 instructions per table and
// lookup before, 282 after: docs/performance.md). The same products in the same order as
// texel() and row_index(), so the same rows and weights.
template <typename List>
void gather_4d(const HalfTable4D& table, const Coord4& c, double weight, List& list) {
  const std::uint16_t* const values = table.values.data();
  const float* const row_scale = table.row_scale.data();
  const auto res_mu = static_cast<std::size_t>(table.res_mu);
  const auto res_nu = static_cast<std::size_t>(table.res_nu);
  const auto res_mu_s = static_cast<std::size_t>(table.res_mu_s);
  const auto stride = static_cast<std::size_t>(table.stride);
  const LookupCorners4 corners(c);
  const auto& [r_index, r_weight, mu_index, mu_weight, ms_index, ms_weight, nu_index, nu_weight] =
      corners;
  for (int a = 0; a < 2; ++a) {
    if (r_weight[a] == 0.0) continue;
    for (int b = 0; b < 2; ++b) {
      const double w_rmu = r_weight[a] * mu_weight[b];
      if (w_rmu == 0.0) continue;
      const std::size_t row = static_cast<std::size_t>(r_index[a]) * res_mu + mu_index[b];
      const double w_row = weight * w_rmu * row_scale[row];
      for (int d = 0; d < 2; ++d) {
        if (nu_weight[d] == 0.0) continue;
        const std::size_t nu_texel = (row * res_nu + nu_index[d]) * res_mu_s;
        for (int e = 0; e < 2; ++e) {
          const double w = w_row * nu_weight[d] * ms_weight[e];
          if (w != 0.0) list.add(values + (nu_texel + ms_index[e]) * stride, w);
        }
      }
    }
  }
}

struct Tables {
  Resolution resolution;
  ShellGeometry geometry;
  int wavelengths = 0;
  int stride = 0;
  FloatTable2D transmittance;   // transmittance_mu x transmittance_r
  FloatTable2D sky_irradiance;  // irradiance_mu_s x irradiance_r, per unit solar irradiance
  HalfTable4D single_rayleigh;  // per unit solar irradiance, without phase function
  HalfTable4D single_mie;       // per unit solar irradiance, without phase function
  HalfTable4D multiple;  // orders 2..orders, 1/sr per unit solar irradiance; empty for 1 order

  std::size_t bytes() const;
  // What bytes() is for tables of this resolution on `wavelengths` wavelengths, before they
  // are built (the same arithmetic as the allocations of precompute_tables()).
  static std::size_t bytes_for(const Resolution& resolution, int wavelengths);

  // Transmittance from (r, mu) to the end of the atmosphere (bilinear in the table).
  void transmittance_to_top(double r, double mu, float* out) const;
  // Transmittance between (r, mu) and the point at distance d along the ray (the 2008 code's
  // ratio of two table values, capped at 1).
  void transmittance_between(double r, double mu, double d, float* out) const;
  // Sky irradiance on a horizontal plane at radius r for the sun at mu_s, per unit solar
  // irradiance.
  void irradiance(double r, double mu_s, float* out) const;
  // Scattered radiance of all orders (single scattering with its phase functions plus the
  // multiple-scattering table) at (r, mu, mu_s, nu), 1/sr per unit solar irradiance. r within
  // [Rg, Rt]; the caller handles views from space.
  void scattering(double r, double mu, double mu_s, double nu, double mie_g, float* out) const;
  // The same at precomputed coordinates (batches share the r and mu_s axes).
  void scattering(const Coord4& c, double nu, double mie_g, float* out) const;
  // The same with an aerosol phase function per wavelength: mie_phase holds its values at nu
  // (1/sr, one per wavelength; models/measured_aerosols).
  void scattering(const Coord4& c, double nu, const float* mie_phase, float* out) const;
};

// The aerosol phase function of the precomputation (the first order's light as the source of
// the second, and the scattering of every later order): Cornette-Shanks with the atmosphere's g,
// or, when `table` is set, a tabulated one (the same at every wavelength).
struct MiePhase {
  double g = 0.0;
  std::shared_ptr<const TabulatedPhaseFunction> table;
  double operator()(double mu) const { return table ? (*table)(mu) : cornette_shanks_phase(mu, g); }
};

// Builds every table on spectra.grid with the given resolution; all cores unless
// context.threads says otherwise. Throws PrecomputeCancelled when cancelled. The aerosol phase
// function is Cornette-Shanks with spectra.parameters.mie_phase_g unless mie_phase_table is set.
Tables precompute_tables(const AtmosphereSpectra& spectra, const Resolution& resolution,
                         const PrecomputeContext& context,
                         std::shared_ptr<const TabulatedPhaseFunction> mie_phase_table = nullptr);

// The byte form of the tables for a TableCache: magic, format version, the description the
// tables were built for (model, version, configuration), the data, and a 64-bit checksum of
// everything before it. Little-endian hosts only (the cache is bypassed elsewhere).
inline constexpr std::uint32_t kTableFormatVersion = 1;
std::string serialise_tables(const Tables& tables, std::string_view description);
// Nothing unless bytes is a complete, uncorrupted blob of this format version built for
// exactly this description. The sun range is not in the blob (the default blob layout predates
// it): the description names it, and the caller passes the one the description names.
std::optional<Tables> deserialise_tables(std::string_view bytes, std::string_view description,
                                         const SunRange& sun = SunRange::legacy());

}  // namespace clearsky::bruneton
