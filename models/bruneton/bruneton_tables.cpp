// Precomputation of the Bruneton 2008 tables (paper Algorithm 4.1) and their lookups.
//
// Speed without changing the algorithm: every texel computes all wavelengths at once
// (spectral rows, spectral_rows.h), and the two costly steps are re-ordered sums of exactly
// the same discrete terms as the 2008 code:
//  - density J (Eq. 7, 16 x 32 directions per texel): at a table layer r and a column mu_s,
//    the incident radiance in direction w is a lookup at (r, w.z, mu_s, s.w); for the 16
//    fixed zeniths w.z the lookup is linear in the nu slices, so the sum over the 512
//    directions becomes scalar weights on 16 x 8 precomputed spectra (plus the ground term on
//    the irradiance table's columns). Same terms, same weights; only the summation order
//    differs.
//  - single scattering and orders >= 2 (Eq. 6 and 8, 50 trapezoid steps): the 32 x 8 texels
//    of a (r, mu) row share the view ray, its sample points and its transmittances.
#include "models/bruneton/bruneton_tables.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <memory>
#include <mutex>
#include <utility>

#include "models/atmosphere/phase_functions.h"
#include "models/bruneton/density_sums.h"
#include "models/bruneton/density_weights.h"
#include "models/bruneton/scattering_transport.h"
#include "models/bruneton/second_order_rows.h"
#include "models/bruneton/single_scattering_sums.h"
#include "models/core/invalid_input.h"
#include "models/core/parallel.h"

namespace clearsky::bruneton {

void FloatTable2D::allocate(int w, int h, int s) {
  width = w;
  height = h;
  stride = s;
  values.assign(static_cast<std::size_t>(w) * h * s, 0.0f);
}

void HalfTable4D::allocate(const Resolution& res, int s) {
  res_r = res.r;
  res_mu = res.mu;
  res_nu = res.nu;
  res_mu_s = res.mu_s;
  stride = s;
  values.assign(static_cast<std::size_t>(res.texels_4d()) * s, 0);
  row_scale.assign(static_cast<std::size_t>(res_r) * res_mu, 0.0f);
}

void HalfTable4D::store_row(int r, int mu, const float* row) {
  const std::size_t n = row_texels() * stride;
  float largest = 0.0f;
  for (std::size_t i = 0; i < n; ++i) largest = std::max(largest, std::abs(row[i]));
  std::uint16_t* out = values.data() + row_index(r, mu) * n;
  // Below 1e-30 (per unit solar irradiance) a row is zero for every purpose.
  if (!(largest > 1e-30f)) {
    std::fill(out, out + n, 0);
    row_scale[row_index(r, mu)] = 0.0f;
    return;
  }
  // Largest magnitude scaled below 2^14: no overflow, and values down to 2^-28 of it keep the
  // full 11-bit precision.
  int exponent = 0;
  std::frexp(largest, &exponent);
  const float to_half = std::ldexp(1.0f, 14 - exponent);
  floats_to_halves(row, to_half, out, n);
  row_scale[row_index(r, mu)] = std::ldexp(1.0f, exponent - 14);
}

void HalfTable4D::load_row(int r, int mu, float* row) const {
  const std::size_t texels = row_texels();
  const std::uint16_t* in = values.data() + row_index(r, mu) * texels * stride;
  const float scale = row_scale[row_index(r, mu)];
  for (std::size_t t = 0; t < texels; ++t) {
    const std::uint16_t* p = in + t * stride;
    sum_rows(&p, &scale, 1, stride, row + t * stride);
  }
}

namespace {

void lookup_2d(const FloatTable2D& t, double u, double v, float* out) {
  const Axis ax = texture_axis(u, t.width);
  const Axis ay = texture_axis(v, t.height);
  FixedRowList<float, 4> list;
  list.add(t.texel(ax.i0, ay.i0), (1.0 - ax.f) * (1.0 - ay.f));
  list.add(t.texel(ax.i1, ay.i0), ax.f * (1.0 - ay.f));
  list.add(t.texel(ax.i0, ay.i1), (1.0 - ax.f) * ay.f);
  list.add(t.texel(ax.i1, ay.i1), ax.f * ay.f);
  list.sum(t.stride, out);
}

}  // namespace

std::size_t Tables::bytes_for(const Resolution& resolution, int wavelengths) {
  const auto stride = static_cast<std::size_t>(padded_stride(wavelengths));
  const std::size_t table_2d =
      (static_cast<std::size_t>(resolution.transmittance_mu) * resolution.transmittance_r +
       static_cast<std::size_t>(resolution.irradiance_mu_s) * resolution.irradiance_r) *
      stride * sizeof(float);
  const std::size_t table_4d =
      static_cast<std::size_t>(resolution.texels_4d()) * stride * sizeof(std::uint16_t) +
      static_cast<std::size_t>(resolution.r) * resolution.mu * sizeof(float);
  // Single Rayleigh and Mie always; the sum of the later orders when there are any.
  return table_2d + (resolution.orders > 1 ? 3 : 2) * table_4d;
}

std::size_t Tables::bytes() const {
  return (transmittance.values.size() + sky_irradiance.values.size()) * sizeof(float) +
         single_rayleigh.bytes() + single_mie.bytes() + multiple.bytes();
}

void Tables::transmittance_to_top(double r, double mu, float* out) const {
  lookup_2d(transmittance, transmittance_u_mu(mu), transmittance_u_r(r, geometry), out);
}

void Tables::transmittance_between(double r, double mu, double d, float* out) const {
  const double r1 = std::sqrt(std::max(r * r + d * d + 2.0 * r * mu * d, 0.0));
  const double mu1 = r1 > 0.0 ? (r * mu + d) / r1 : 1.0;
  ScratchRow other(stride);
  if (mu > 0.0) {
    transmittance_to_top(r, mu, out);
    transmittance_to_top(r1, mu1, other.data());
  } else {
    transmittance_to_top(r1, -mu1, out);
    transmittance_to_top(r, -mu, other.data());
  }
  // T(x, x_d) = T(x) / T(x_d); a vanishing denominator means no light gets through.
  for (int i = 0; i < stride; ++i) {
    const float denominator = other.data()[i];
    out[i] = denominator > 1e-30f ? std::min(out[i] / denominator, 1.0f) : 0.0f;
  }
}

void Tables::irradiance(double r, double mu_s, float* out) const {
  lookup_2d(sky_irradiance, irradiance_u_mu_s(mu_s, resolution.sun), irradiance_u_r(r, geometry),
            out);
}

void Tables::scattering(double r, double mu, double mu_s, double nu, double mie_g,
                        float* out) const {
  scattering(coordinates_4d(r, mu, mu_s, nu, resolution, geometry), nu, mie_g, out);
}

namespace {

bool same_layout(const HalfTable4D& a, const HalfTable4D& b) {
  return a.res_r == b.res_r && a.res_mu == b.res_mu && a.res_nu == b.res_nu &&
         a.res_mu_s == b.res_mu_s && a.stride == b.stride;
}

// gather_4d(*tables[t], c, weights[t], list) for t = 0, 1, ... in turn, for tables of one layout
// (same_layout): the same rows with the same weights in the same order, so the same sum, with
// the texels' offsets and the (r, mu) weights computed once for all the tables instead of once
// per table (a sky view's lookup reads the same texels of its three 4D tables).
template <std::size_t N, typename List>
void gather_4d_same_texels(const std::array<const HalfTable4D*, N>& tables,
                           const std::array<double, N>& weights, const Coord4& c, List& list) {
  const HalfTable4D& layout = *tables[0];
  const LookupCorners4 corners(c);
  const auto& [r_index, r_weight, mu_index, mu_weight, ms_index, ms_weight, nu_index, nu_weight] =
      corners;
  // The (r, mu) rows with a weight, in gather_4d's order, and the offsets of their (nu, mu_s)
  // texels.
  std::size_t row_index[4];
  double w_rmu[4];
  int rows = 0;
  for (int a = 0; a < 2; ++a) {
    if (r_weight[a] == 0.0) continue;
    for (int b = 0; b < 2; ++b) {
      const double w = r_weight[a] * mu_weight[b];
      if (w == 0.0) continue;
      row_index[rows] = layout.row_index(r_index[a], mu_index[b]);
      w_rmu[rows++] = w;
    }
  }
  std::size_t texel_offset[2][2];
  for (int d = 0; d < 2; ++d) {
    for (int e = 0; e < 2; ++e)
      texel_offset[d][e] = static_cast<std::size_t>(nu_index[d] * layout.res_mu_s + ms_index[e]);
  }
  const std::size_t row_texels = layout.row_texels();
  const auto stride = static_cast<std::size_t>(layout.stride);
  for (std::size_t t = 0; t < N; ++t) {
    const HalfTable4D& table = *tables[t];
    for (int k = 0; k < rows; ++k) {
      const double w_row = weights[t] * w_rmu[k] * table.row_scale[row_index[k]];
      const std::uint16_t* row = table.values.data() + row_index[k] * row_texels * stride;
      for (int d = 0; d < 2; ++d) {
        if (nu_weight[d] == 0.0) continue;
        for (int e = 0; e < 2; ++e) {
          const double w = w_row * nu_weight[d] * ms_weight[e];
          if (w != 0.0) list.add(row + texel_offset[d][e] * stride, w);
        }
      }
    }
  }
}

}  // namespace

void Tables::scattering(const Coord4& c, double nu, double mie_g, float* out) const {
  FixedRowList<std::uint16_t, 48> list;
  const double rayleigh = rayleigh_phase(nu), mie = cornette_shanks_phase(nu, mie_g);
  if (!multiple.empty() && same_layout(single_rayleigh, single_mie) &&
      same_layout(single_rayleigh, multiple)) {
    gather_4d_same_texels<3>({&single_rayleigh, &single_mie, &multiple}, {rayleigh, mie, 1.0}, c,
                             list);
  } else {
    gather_4d(single_rayleigh, c, rayleigh, list);
    gather_4d(single_mie, c, mie, list);
    if (!multiple.empty()) gather_4d(multiple, c, 1.0, list);
  }
  list.sum(stride, out);
}

void Tables::scattering(const Coord4& c, double nu, const float* mie_phase, float* out) const {
  FixedRowList<std::uint16_t, 32> list;
  gather_4d(single_rayleigh, c, rayleigh_phase(nu), list);
  if (!multiple.empty()) gather_4d(multiple, c, 1.0, list);
  list.sum(stride, out);
  FixedRowList<std::uint16_t, 16> mie;
  gather_4d(single_mie, c, 1.0, mie);
  ScratchRow single(stride);
  mie.sum(stride, single.data());
  for (int w = 0; w < stride; ++w) out[w] += mie_phase[w] * single.data()[w];
}

namespace {

// Spectral coefficients as padded float rows.
struct Coefficients {
  std::vector<float> rayleigh, mie_scattering, mie_extinction, albedo_over_pi;
  double rayleigh_height_m = 0, mie_height_m = 0;
  MiePhase mie_phase;
};

Coefficients coefficients(const AtmosphereSpectra& s, int stride) {
  Coefficients c;
  c.rayleigh.assign(stride, 0.0f);
  c.mie_scattering.assign(stride, 0.0f);
  c.mie_extinction.assign(stride, 0.0f);
  c.albedo_over_pi.assign(stride, 0.0f);
  for (std::size_t i = 0; i < s.grid.size(); ++i) {
    c.rayleigh[i] = static_cast<float>(s.rayleigh_scattering_per_m[i]);
    c.mie_scattering[i] = static_cast<float>(s.mie_scattering_per_m[i]);
    c.mie_extinction[i] = static_cast<float>(s.mie_extinction_per_m[i]);
    c.albedo_over_pi[i] = static_cast<float>(s.ground_albedo[i] / kPi);
  }
  c.rayleigh_height_m = s.parameters.rayleigh_scale_height_m;
  c.mie_height_m = s.parameters.mie_scale_height_m;
  c.mie_phase.g = s.parameters.mie_phase_g;
  return c;
}

// Optical length (integral of exp(-h/H)) from (r, mu) to the limit sphere, trapezoid rule with
// `steps` steps; 1e9 m (opaque) for rays that hit the ground (2008 code: opticalDepth).
double optical_length(double scale_height, double r, double mu, int steps, const ShellGeometry& g) {
  const double dx = limit_distance(r, mu, g) / steps;
  double previous = std::exp(-(r - g.bottom_m) / scale_height);
  double sum = 0.0;
  for (int i = 1; i <= steps; ++i) {
    const double x = i * dx;
    const double ri = std::sqrt(r * r + x * x + 2.0 * x * r * mu);
    const double y = std::exp(-(ri - g.bottom_m) / scale_height);
    sum += (previous + y) / 2.0 * dx;
    previous = y;
  }
  return mu < horizon_mu(r, g) ? 1e9 : sum;
}

class Progress {
 public:
  Progress(const PrecomputeContext& context, double total) : context_(context), total_(total) {}
  void advance(double units, std::string_view stage) {
    std::lock_guard lock(mutex_);
    done_ += units;
    context_.report(std::min(done_ / total_, 1.0), stage);
  }

 private:
  const PrecomputeContext& context_;
  double total_;
  double done_ = 0;
  std::mutex mutex_;
};

struct Builder {
  const Resolution& res;
  const ShellGeometry& g;
  const Coefficients& k;
  const PrecomputeContext& context;
  Tables& t;
  Progress& progress;
  int stride;

  void for_each(std::size_t count, const std::function<void(std::size_t)>& body) const {
    parallel_for(
        count,
        [&](std::size_t i) {
          context.check_cancelled();
          body(i);
        },
        context.threads);
  }

  void build_transmittance() {
    t.transmittance.allocate(res.transmittance_mu, res.transmittance_r, stride);
    for_each(static_cast<std::size_t>(res.transmittance_r), [&](std::size_t j) {
      const double r = transmittance_texel_r(static_cast<int>(j), res.transmittance_r, g);
      for (int i = 0; i < res.transmittance_mu; ++i) {
        const double mu = transmittance_texel_mu(i, res.transmittance_mu);
        const double tau_r = optical_length(k.rayleigh_height_m, r, mu, res.transmittance_steps, g);
        const double tau_m = optical_length(k.mie_height_m, r, mu, res.transmittance_steps, g);
        float* out = t.transmittance.texel(i, static_cast<int>(j));
        for (int w = 0; w < t.wavelengths; ++w) {
          out[w] =
              static_cast<float>(std::exp(-(k.rayleigh[w] * tau_r + k.mie_extinction[w] * tau_m)));
        }
      }
    });
  }

  // Delta E of order 1: the direct sun on a horizontal plane, T(r, mu_s) max(mu_s, 0).
  FloatTable2D direct_irradiance() {
    FloatTable2D e;
    e.allocate(res.irradiance_mu_s, res.irradiance_r, stride);
    for (int j = 0; j < res.irradiance_r; ++j) {
      const double r = irradiance_texel_r(j, res.irradiance_r, g);
      for (int i = 0; i < res.irradiance_mu_s; ++i) {
        const double mu_s = irradiance_texel_mu_s(i, res.irradiance_mu_s, res.sun);
        float* out = e.texel(i, j);
        t.transmittance_to_top(r, mu_s, out);
        const float cosine = static_cast<float>(std::max(mu_s, 0.0));
        for (int w = 0; w < stride; ++w) out[w] *= cosine;
      }
    }
    return e;
  }

  // Samples of the view ray of a (r, mu) row: distance, trapezoid weight, transmittance from
  // the origin.
  struct RaySamples {
    std::vector<double> t, weight;
    std::vector<float> transmittance;  // (steps + 1) x stride
  };

  RaySamples ray_samples(double r, double mu) const {
    RaySamples s;
    const int n = res.inscatter_steps;
    const double dx = limit_distance(r, mu, g) / n;
    s.t.resize(n + 1);
    s.weight.resize(n + 1);
    s.transmittance.resize(static_cast<std::size_t>(n + 1) * stride);
    for (int i = 0; i <= n; ++i) {
      s.t[i] = i * dx;
      s.weight[i] = (i == 0 || i == n) ? dx / 2.0 : dx;
      t.transmittance_between(r, mu, s.t[i],
                              s.transmittance.data() + static_cast<std::size_t>(i) * stride);
    }
    return s;
  }

  // Single scattering, Eq. 6 without phase functions (2008 code: inscatter1). With `only`, the
  // rows it marks (the others stay zero); every row is computed as without it.
  void build_single_scattering(const std::vector<char>* only = nullptr) {
    t.single_rayleigh.allocate(res, stride);
    t.single_mie.allocate(res, stride);
    const std::size_t rows = static_cast<std::size_t>(res.r) * res.mu;
    for_each(rows, [&](std::size_t row) {
      const int layer = static_cast<int>(row / res.mu);
      const int j = static_cast<int>(row % res.mu);
      if (only != nullptr && (*only)[row] == 0) {
        if (j == res.mu - 1) progress.advance(1.0 / res.r, "single scattering");
        return;
      }
      const Layer l = layer_geometry(layer, res.r, g);
      const double r = l.r;
      const double mu = texel_mu(j, res.mu, l, g);
      const RaySamples s = ray_samples(r, mu);
      const int n = res.inscatter_steps;
      std::vector<double> radius(n + 1), clamped(n + 1), density_r(n + 1), density_m(n + 1),
          horizon(n + 1);
      std::vector<Axis> r_axis(n + 1);
      for (int i = 0; i <= n; ++i) {
        radius[i] = std::sqrt(r * r + s.t[i] * s.t[i] + 2.0 * r * mu * s.t[i]);
        clamped[i] = std::max(g.bottom_m, radius[i]);
        density_r[i] = std::exp(-(clamped[i] - g.bottom_m) / k.rayleigh_height_m);
        density_m[i] = std::exp(-(clamped[i] - g.bottom_m) / k.mie_height_m);
        horizon[i] = -safe_sqrt(1.0 - g.bottom_m * g.bottom_m / (clamped[i] * clamped[i]));
        r_axis[i] = texture_axis(transmittance_u_r(clamped[i], g), res.transmittance_r);
      }
      const std::size_t texels = t.single_rayleigh.row_texels();
      std::vector<float> out_r(texels * stride, 0.0f), out_m(texels * stride, 0.0f);
      std::vector<SunlitSample> lit(n + 1);
      for (int knu = 0; knu < res.nu; ++knu) {
        const double nu = texel_nu(knu, res.nu);
        for (int ms = 0; ms < res.mu_s; ++ms) {
          const double mu_s = texel_mu_s(ms, res.mu_s, res.sun);
          float* acc_r = out_r.data() + (static_cast<std::size_t>(knu) * res.mu_s + ms) * stride;
          float* acc_m = out_m.data() + (static_cast<std::size_t>(knu) * res.mu_s + ms) * stride;
          int count = 0;
          for (int i = 0; i <= n; ++i) {
            const double mu_s_i = (nu * s.t[i] + mu_s * r) / radius[i];
            if (!(mu_s_i >= horizon[i])) continue;  // the sample is in the Earth's shadow
            const Axis ax = texture_axis(transmittance_u_mu(mu_s_i), res.transmittance_mu);
            const Axis& ay = r_axis[i];
            FixedRowList<float, 4> list;
            list.add(t.transmittance.texel(ax.i0, ay.i0), (1.0 - ax.f) * (1.0 - ay.f));
            list.add(t.transmittance.texel(ax.i1, ay.i0), ax.f * (1.0 - ay.f));
            list.add(t.transmittance.texel(ax.i0, ay.i1), (1.0 - ax.f) * ay.f);
            list.add(t.transmittance.texel(ax.i1, ay.i1), ax.f * ay.f);
            SunlitSample& sample = lit[count++];
            sample.count = list.count;
            for (int q = 0; q < list.count; ++q) {
              sample.rows[q] = list.rows[q];
              sample.weights[q] = list.weights[q];
            }
            sample.view = s.transmittance.data() + static_cast<std::size_t>(i) * stride;
            sample.weight_r = static_cast<float>(s.weight[i] * density_r[i]);
            sample.weight_m = static_cast<float>(s.weight[i] * density_m[i]);
          }
          add_sunlit_samples(lit.data(), count, stride, acc_r, acc_m);
          for (int w = 0; w < stride; ++w) {
            acc_r[w] *= k.rayleigh[w];
            acc_m[w] *= k.mie_scattering[w];
          }
        }
      }
      t.single_rayleigh.store_row(layer, j, out_r.data());
      t.single_mie.store_row(layer, j, out_m.data());
      if (j == res.mu - 1) progress.advance(1.0 / res.r, "single scattering");
    });
  }

  // The light scattered towards each direction of a texel, before the order's integral:
  // either single scattering (Rayleigh and Mie tables, phase functions applied here) or the
  // previous order's scattering table.
  struct Source {
    const HalfTable4D* rayleigh = nullptr;   // first order: single Rayleigh
    const HalfTable4D* mie = nullptr;        // first order: single Mie
    const HalfTable4D* scattered = nullptr;  // later orders
    bool first() const { return scattered == nullptr; }
  };

  // Incident light from each zenith cos_t[i], in each nu slice k: the table at
  // (r, cos_t[i], mu_s) without interpolation in nu, (i * res.nu + k) * stride. For the first
  // order, a holds single Rayleigh and b single Mie; later, a holds the previous order.
  void build_profiles(const Source& source, double r, double mu_s, const std::vector<double>& cos_t,
                      std::vector<float>& profile_a, std::vector<float>& profile_b) const {
    const int n_theta = static_cast<int>(cos_t.size());
    const std::size_t profile_size = static_cast<std::size_t>(n_theta) * res.nu * stride;
    profile_a.assign(profile_size, 0.0f);
    profile_b.assign(source.first() ? profile_size : 0, 0.0f);
    RowList<std::uint16_t> list;
    for (int i = 0; i < n_theta; ++i) {
      Coord4 c = coordinates_4d(r, cos_t[i], mu_s, 0.0, res, g);
      for (int kk = 0; kk < res.nu; ++kk) {
        c.nu = Axis{kk, kk, 0.0};
        list.clear();
        gather_4d(source.first() ? *source.rayleigh : *source.scattered, c, 1.0, list);
        list.sum(stride, profile_a.data() + (static_cast<std::size_t>(i) * res.nu + kk) * stride);
        if (source.first()) {
          list.clear();
          gather_4d(*source.mie, c, 1.0, list);
          list.sum(stride, profile_b.data() + (static_cast<std::size_t>(i) * res.nu + kk) * stride);
        }
      }
    }
  }

  // The n_theta x n_phi directions of the density's sphere (Eq. 7, the 2008 code's
  // inscatterS): unit vectors and solid angles, the same for every texel.
  struct SphereDirections {
    int n_phi = 0;
    std::vector<double> cos_t, wx, wy, wz, dw;
  };

  static SphereDirections sphere_directions(const std::vector<double>& cos_t,
                                            const std::vector<double>& sin_t,
                                            const std::vector<double>& cos_p,
                                            const std::vector<double>& sin_p) {
    SphereDirections s;
    const int n_theta = static_cast<int>(cos_t.size());
    s.n_phi = static_cast<int>(cos_p.size());
    const double dtheta = kPi / n_theta;
    const double dphi = kPi / n_theta;
    s.cos_t = cos_t;
    const std::size_t n_dir = static_cast<std::size_t>(n_theta) * s.n_phi;
    s.wx.resize(n_dir);
    s.wy.resize(n_dir);
    s.wz.resize(n_dir);
    s.dw.resize(n_dir);
    for (int i = 0; i < n_theta; ++i) {
      for (int p = 0; p < s.n_phi; ++p) {
        const std::size_t d = static_cast<std::size_t>(i) * s.n_phi + p;
        s.wx[d] = cos_p[p] * sin_t[i];
        s.wy[d] = sin_p[p] * sin_t[i];
        s.wz[d] = cos_t[i];
        s.dw[d] = dtheta * dphi * sin_t[i];
      }
    }
    return s;
  }

  // Density J (Eq. 7) of the order after `source`, whose ground irradiance is delta_e.
  void build_density(const Source& source, const FloatTable2D& delta_e, HalfTable4D& j_table,
                     double progress_units) {
    j_table.allocate(res, stride);
    const int n_theta = res.sphere_samples;
    const int n_phi = 2 * res.sphere_samples;
    const double dtheta = kPi / n_theta;
    const double dphi = kPi / n_theta;
    const int n_e = delta_e.width;
    // The zeniths where rows_read_by_second_order() finds them.
    const std::vector<double> cos_t = zenith_cosines(n_theta, n_theta);
    std::vector<double> sin_t(n_theta), cos_p(n_phi), sin_p(n_phi);
    for (int i = 0; i < n_theta; ++i) sin_t[i] = std::sin((i + 0.5) * dtheta);
    for (int p = 0; p < n_phi; ++p) {
      cos_p[p] = std::cos((p + 0.5) * dphi);
      sin_p[p] = std::sin((p + 0.5) * dphi);
    }
    const SphereDirections sphere = sphere_directions(cos_t, sin_t, cos_p, sin_p);
    // One loop over every layer's columns instead of three loops per layer with a wait at the
    // end of each: a layer's shared part is prepared (once) when the middle column of the layer
    // before it starts, while the other workers compute columns, and the worker that finishes a
    // layer's last column stores its rows while the others go on with the next layer's columns.
    // Every value is computed as in one layer at a time; at most two layers' shared parts are
    // held at once, but for a slow worker.
    std::vector<std::unique_ptr<DensityLayer>> layers(res.r);
    for (auto& layer : layers) layer = std::make_unique<DensityLayer>();
    auto prepared = [&](int layer) -> DensityLayer& {
      DensityLayer& shared = *layers[layer];
      std::call_once(shared.ready, [&] {
        prepare_density_layer(layer, sphere, delta_e, j_table.row_texels(), shared);
        shared.columns_left.store(res.mu_s);
      });
      return shared;
    };
    for_each(static_cast<std::size_t>(res.r) * res.mu_s, [&](std::size_t item) {
      const int layer = static_cast<int>(item / res.mu_s);
      const int ms = static_cast<int>(item % res.mu_s);
      DensityLayer& shared = prepared(layer);
      if (ms == res.mu_s / 2 && layer + 1 < res.r) prepared(layer + 1);
      density_column(source, layer, ms, shared.r, shared.density_r, shared.density_m, sphere,
                     shared.phase_r, shared.phase_m, shared.ground, shared.d_ground,
                     shared.ground_light, n_e, shared.values.data());
      // The last column of the layer: every other column's values are visible here (the
      // decrements are read-modify-writes of one atomic).
      if (shared.columns_left.fetch_sub(1) != 1) return;
      for (int j = 0; j < res.mu; ++j) {
        j_table.store_row(
            layer, j,
            shared.values.data() + static_cast<std::size_t>(j) * j_table.row_texels() * stride);
      }
      shared.release();
      progress.advance(progress_units / res.r, "multiple scattering: density");
    });
  }

  // What the columns of one layer of J share.
  struct DensityLayer {
    std::once_flag ready;
    std::atomic<int> columns_left{0};
    double r = 0;
    float density_r = 0, density_m = 0;
    // The phase functions towards each view row mu times the solid angles (mu x directions).
    std::vector<double> phase_r, phase_m;
    // Per zenith: whether it sees the ground, the distance to it, and (transmittance to it) x
    // (albedo / pi) x (delta E at each column of the irradiance table's ground row).
    std::vector<char> ground;
    std::vector<double> d_ground;
    std::vector<float> ground_light;
    std::vector<float> values;  // the layer's rows of J, as store_row() takes them
    // Frees the vectors' memory once the layer is stored (`v = {}` would keep it).
    void release() {
      std::vector<double>().swap(phase_r);
      std::vector<double>().swap(phase_m);
      std::vector<char>().swap(ground);
      std::vector<double>().swap(d_ground);
      std::vector<float>().swap(ground_light);
      std::vector<float>().swap(values);
    }
  };

  void prepare_density_layer(int layer, const SphereDirections& sphere, const FloatTable2D& delta_e,
                             std::size_t row_texels, DensityLayer& out) const {
    const std::vector<double>& cos_t = sphere.cos_t;
    const int n_theta = static_cast<int>(cos_t.size());
    const int n_e = delta_e.width;
    const std::size_t n_dir = sphere.wx.size();
    const Layer l = layer_geometry(layer, res.r, g);
    // The phases: the same for every mu_s column of the layer, computed once for all of them.
    out.phase_r.resize(static_cast<std::size_t>(res.mu) * n_dir);
    out.phase_m.resize(out.phase_r.size());
    for (int jm = 0; jm < res.mu; ++jm) {
      const double mu = std::clamp(texel_mu(jm, res.mu, l, g), -1.0, 1.0);
      const double vx = std::sqrt(1.0 - mu * mu);
      double* phase_r = out.phase_r.data() + static_cast<std::size_t>(jm) * n_dir;
      double* phase_m = out.phase_m.data() + static_cast<std::size_t>(jm) * n_dir;
      for (std::size_t d = 0; d < n_dir; ++d) {
        const double nu2 = vx * sphere.wx[d] + mu * sphere.wz[d];
        phase_r[d] = rayleigh_phase(nu2) * sphere.dw[d];
        phase_m[d] = k.mie_phase(nu2) * sphere.dw[d];
      }
    }
    const double r = std::clamp(l.r, g.bottom_m, g.top_m);
    out.r = r;
    const double cos_theta_min = horizon_mu(r, g);
    out.density_r = static_cast<float>(std::exp(-(r - g.bottom_m) / k.rayleigh_height_m));
    out.density_m = static_cast<float>(std::exp(-(r - g.bottom_m) / k.mie_height_m));
    out.ground.assign(n_theta, 0);
    out.d_ground.assign(n_theta, 0.0);
    out.ground_light.assign(static_cast<std::size_t>(n_theta) * n_e * stride, 0.0f);
    std::vector<float> transmittance(stride);
    for (int i = 0; i < n_theta; ++i) {
      if (!(cos_t[i] < cos_theta_min)) continue;
      out.ground[i] = 1;
      out.d_ground[i] =
          -r * cos_t[i] - safe_sqrt(r * r * (cos_t[i] * cos_t[i] - 1.0) + g.bottom_m * g.bottom_m);
      t.transmittance_between(g.bottom_m, -(r * cos_t[i] + out.d_ground[i]) / g.bottom_m,
                              out.d_ground[i], transmittance.data());
      for (int c = 0; c < n_e; ++c) {
        const float* e = delta_e.texel(c, 0);
        float* o = out.ground_light.data() + (static_cast<std::size_t>(i) * n_e + c) * stride;
        for (int w = 0; w < stride; ++w) o[w] = transmittance[w] * k.albedo_over_pi[w] * e[w];
      }
    }
    out.values.assign(static_cast<std::size_t>(res.mu) * row_texels * stride, 0.0f);
  }

  void density_column(const Source& source, int layer, int ms, double r, float density_r,
                      float density_m, const SphereDirections& sphere,
                      const std::vector<double>& layer_phase_r,
                      const std::vector<double>& layer_phase_m, const std::vector<char>& ground,
                      const std::vector<double>& d_ground, const std::vector<float>& ground_light,
                      int n_e, float* layer_values) const {
    const std::vector<double>& cos_t = sphere.cos_t;
    const int n_theta = static_cast<int>(cos_t.size());
    const int n_nu = res.nu;
    const double mu_s = std::clamp(texel_mu_s(ms, res.mu_s, res.sun), -1.0, 1.0);
    std::vector<float> profile_a, profile_b;
    build_profiles(source, r, mu_s, cos_t, profile_a, profile_b);
    const std::size_t n_dir = sphere.wx.size();
    DensitySphere shared;
    shared.n_theta = n_theta;
    shared.n_phi = sphere.n_phi;
    shared.n_nu = n_nu;
    shared.n_e = n_e;
    shared.cos_t = cos_t.data();
    shared.wx = sphere.wx.data();
    shared.wy = sphere.wy.data();
    shared.ground = ground.data();
    shared.d_ground = d_ground.data();
    shared.r = r;
    shared.mu_s = mu_s;
    shared.bottom_m = g.bottom_m;
    shared.sun = res.sun;
    shared.mie_phase = &k.mie_phase;
    shared.first = source.first();
    // The weights of the profiles (R: with the Rayleigh phase of the scattering towards v; M:
    // with the Mie phase) and of the ground columns, for the row's nu slices at once.
    DensityWeights weights;
    const int lanes = (n_nu + 3) / 4 * 4;
    std::vector<double> sx(lanes, 0.0), sy(lanes, 0.0);
    std::vector<int> same_as(n_nu), lane(n_nu);
    std::vector<float> sum_r(stride), sum_m(stride);
    // Every profile (a and b) and every ground column of every zenith at most.
    DensityTerms terms(n_theta * (n_nu * 2 + n_e));
    const std::size_t texels_per_row = static_cast<std::size_t>(n_nu) * res.mu_s;
    for (int jm = 0; jm < res.mu; ++jm) {
      const Layer l = layer_geometry(layer, res.r, g);
      const double mu = std::clamp(texel_mu(jm, res.mu, l, g), -1.0, 1.0);
      const double vx = std::sqrt(1.0 - mu * mu);
      shared.phase_r = layer_phase_r.data() + static_cast<std::size_t>(jm) * n_dir;
      shared.phase_m = layer_phase_m.data() + static_cast<std::size_t>(jm) * n_dir;
      // Slices whose nu is clamped to the same end of its range (beyond the cosines this view
      // and this sun allow) have the same sun direction, hence the same J: each distinct
      // direction is computed once (texel `lane` of the weights) and copied to the others.
      int distinct = 0;
      for (int knu = 0; knu < n_nu; ++knu) {
        const double var = std::sqrt(1.0 - mu * mu) * std::sqrt(1.0 - mu_s * mu_s);
        const double nu = std::clamp(texel_nu(knu, n_nu), mu_s * mu - var, mu_s * mu + var);
        const double x = vx == 0.0 ? 0.0 : (nu - mu_s * mu) / vx;
        const double y = std::sqrt(std::max(0.0, 1.0 - x * x - mu_s * mu_s));
        same_as[knu] = knu;
        for (int earlier = 0; earlier < knu; ++earlier) {
          if (same_as[earlier] != earlier) continue;
          if (std::bit_cast<std::uint64_t>(sx[lane[earlier]]) == std::bit_cast<std::uint64_t>(x) &&
              std::bit_cast<std::uint64_t>(sy[lane[earlier]]) == std::bit_cast<std::uint64_t>(y)) {
            same_as[knu] = earlier;
            break;
          }
        }
        if (same_as[knu] != knu) continue;
        lane[knu] = distinct;
        sx[distinct] = x;
        sy[distinct++] = y;
      }
      for (int extra = distinct; extra < lanes; ++extra) {
        sx[extra] = 0.0;
        sy[extra] = 0.0;
      }
      weights.prepare(distinct, shared);
      density_weights(shared, sx.data(), sy.data(), distinct, weights);
      // The lanes computed beyond the distinct texels leave ground weights: cleared, since a
      // later row may use these texels (whoever reads ground weights leaves them zero).
      for (int extra = distinct; extra < (distinct + 3) / 4 * 4; ++extra) {
        for (int i = 0; i < n_theta; ++i) {
          const std::pair<int, int> range = weights.range(extra, i);
          for (int col = range.first; col <= range.second; ++col)
            weights.clear_column(weights.column(extra, i, col));
        }
      }
      for (int knu = 0; knu < n_nu; ++knu) {
        float* out = layer_values + (static_cast<std::size_t>(jm) * texels_per_row +
                                     static_cast<std::size_t>(knu) * res.mu_s + ms) *
                                        stride;
        if (same_as[knu] != knu) {
          const float* same =
              layer_values + (static_cast<std::size_t>(jm) * texels_per_row +
                              static_cast<std::size_t>(same_as[knu]) * res.mu_s + ms) *
                                 stride;
          std::copy(same, same + stride, out);
          continue;
        }
        const int texel = lane[knu];
        terms.clear();
        for (int i = 0; i < n_theta; ++i) {
          for (int kk = 0; kk < n_nu; ++kk) {
            const std::size_t s = static_cast<std::size_t>(i) * n_nu + kk;
            const std::size_t slot = weights.slot(texel, i, kk);
            terms.add(profile_a.data() + s * stride, weights.a_r(slot), weights.a_m(slot));
            if (source.first())
              terms.add(profile_b.data() + s * stride, weights.b_r(slot), weights.b_m(slot));
          }
        }
        for (int i = 0; i < n_theta; ++i) {
          const std::pair<int, int> range = weights.range(texel, i);
          for (int col = range.first; col <= range.second; ++col) {
            const std::size_t c = static_cast<std::size_t>(i) * n_e + col;
            const std::size_t w = weights.column(texel, i, col);
            terms.add(ground_light.data() + c * stride, weights.g_r(w), weights.g_m(w));
            weights.clear_column(w);
          }
        }
        terms.sum(stride, sum_r.data(), sum_m.data());
        for (int w = 0; w < stride; ++w) {
          out[w] =
              k.rayleigh[w] * density_r * sum_r[w] + k.mie_scattering[w] * density_m * sum_m[w];
        }
      }
    }
  }

  // Delta E of the order after `source` (Eq. 15): the sky irradiance it produces on a
  // horizontal plane, over irradiance_samples / 2 zeniths x 2 irradiance_samples azimuths. As
  // for J, the lookups at each fixed zenith are linear in the nu slices: the sum becomes
  // scalar weights on precomputed profiles, the same terms in another order.
  FloatTable2D build_irradiance(const Source& source) {
    FloatTable2D e;
    e.allocate(res.irradiance_mu_s, res.irradiance_r, stride);
    const int n = res.irradiance_samples;
    const double dphi = kPi / n;
    const double dtheta = kPi / n;
    // The zeniths where rows_read_by_second_order() finds them.
    const std::vector<double> cos_t = zenith_cosines(n / 2, n);
    std::vector<double> sin_t(n / 2), cos_p(2 * n);
    for (int it = 0; it < n / 2; ++it) sin_t[it] = std::sin((it + 0.5) * dtheta);
    for (int ip = 0; ip < 2 * n; ++ip) cos_p[ip] = std::cos((ip + 0.5) * dphi);
    for_each(static_cast<std::size_t>(res.irradiance_mu_s) * res.irradiance_r,
             [&](std::size_t texel) {
               const int i = static_cast<int>(texel % res.irradiance_mu_s);
               const int j = static_cast<int>(texel / res.irradiance_mu_s);
               const double r = irradiance_texel_r(j, res.irradiance_r, g);
               const double mu_s = irradiance_texel_mu_s(i, res.irradiance_mu_s, res.sun);
               // The last texel may hold mu_s one rounding above 1 (extended sun ranges).
               const double sx = safe_sqrt(1.0 - mu_s * mu_s);
               std::vector<float> profile_a, profile_b;
               build_profiles(source, r, mu_s, cos_t, profile_a, profile_b);
               const std::size_t n_profile = cos_t.size() * static_cast<std::size_t>(res.nu);
               std::vector<double> weight_a(n_profile, 0.0), weight_b(n_profile, 0.0);
               for (std::size_t it = 0; it < cos_t.size(); ++it) {
                 const double dw = dtheta * dphi * sin_t[it];
                 for (int ip = 0; ip < 2 * n; ++ip) {
                   const double nu = sx * cos_p[ip] * sin_t[it] + mu_s * cos_t[it];
                   const Axis slice = nu_axis_4d(nu, res);
                   const double w = cos_t[it] * dw;
                   const double wa = source.first() ? rayleigh_phase(nu) * w : w;
                   const std::size_t s0 = it * res.nu + slice.i0;
                   const std::size_t s1 = it * res.nu + slice.i1;
                   weight_a[s0] += (1.0 - slice.f) * wa;
                   weight_a[s1] += slice.f * wa;
                   if (source.first()) {
                     const double wb = k.mie_phase(nu) * w;
                     weight_b[s0] += (1.0 - slice.f) * wb;
                     weight_b[s1] += slice.f * wb;
                   }
                 }
               }
               RowList<float> rows;
               for (std::size_t p = 0; p < n_profile; ++p) {
                 rows.add(profile_a.data() + p * stride, weight_a[p]);
                 if (source.first()) rows.add(profile_b.data() + p * stride, weight_b[p]);
               }
               rows.sum(stride, e.texel(i, j));
             });
    return e;
  }

  // Scattering of the order whose density is j_table (Eq. 8, 2008 code: inscatterN).
  void build_scattering(const HalfTable4D& j_table, HalfTable4D& out_table, double progress_units) {
    out_table.allocate(res, stride);
    const std::size_t rows = static_cast<std::size_t>(res.r) * res.mu;
    for_each(rows, [&](std::size_t row) {
      const int layer = static_cast<int>(row / res.mu);
      const int jm = static_cast<int>(row % res.mu);
      const Layer l = layer_geometry(layer, res.r, g);
      const double r = l.r;
      const double mu = texel_mu(jm, res.mu, l, g);
      const RaySamples s = ray_samples(r, mu);
      const int n = res.inscatter_steps;
      std::vector<double> radius(n + 1);
      std::vector<Axis> r_axis(n + 1), mu_axis(n + 1);
      for (int i = 0; i <= n; ++i) {
        radius[i] =
            std::max(std::sqrt(r * r + s.t[i] * s.t[i] + 2.0 * r * mu * s.t[i]), g.bottom_m + 10.0);
        const double mu_i = (r * mu + s.t[i]) / radius[i];
        r_axis[i] = r_axis_4d(radius[i], res, g);
        mu_axis[i] = mu_axis_4d(radius[i], mu_i, res, g);
      }
      const std::size_t texels = out_table.row_texels();
      std::vector<float> values(texels * stride, 0.0f), view_weight(stride);
      std::vector<double> mu_s(res.mu_s);
      for (int ms = 0; ms < res.mu_s; ++ms) mu_s[ms] = texel_mu_s(ms, res.mu_s, res.sun);
      std::vector<Axis> mu_s_axes(res.mu_s);
      // Sun cosines at or below the lookups' clamp all read the axis of the clamp (u_mu_s
      // clamps before its atan): found once for the row.
      const Axis clamped_axis =
          texture_axis(u_mu_s(res.sun.lookup_min_mu_s, res.mu_s, res.sun), res.mu_s);
      // Samples outside, texels inside: each texel still adds its samples in order (the same
      // sums as one texel at a time), and a sample's rows of J are found once for the slice.
      for (int knu = 0; knu < res.nu; ++knu) {
        const double nu = texel_nu(knu, res.nu);
        const Axis nu_axis = nu_axis_4d(nu, res);
        float* acc = values.data() + static_cast<std::size_t>(knu) * res.mu_s * stride;
        for (int i = 0; i <= n; ++i) {
          const TransportLookup lookup = transport_lookup(j_table, r_axis[i], mu_axis[i], nu_axis);
          for (int ms = 0; ms < res.mu_s; ++ms) {
            const double mu_s_i = (nu * s.t[i] + mu_s[ms] * r) / radius[i];
            mu_s_axes[ms] = mu_s_i <= res.sun.lookup_min_mu_s
                                ? clamped_axis
                                : texture_axis(u_mu_s(mu_s_i, res.mu_s, res.sun), res.mu_s);
          }
          const float* view = s.transmittance.data() + static_cast<std::size_t>(i) * stride;
          const float weight = static_cast<float>(s.weight[i]);
          for (int w = 0; w < stride; ++w) view_weight[w] = weight * view[w];
          add_transport_sample(lookup, mu_s_axes.data(), res.mu_s, view_weight.data(), stride, acc);
        }
      }
      out_table.store_row(layer, jm, values.data());
      if (jm == res.mu - 1)
        progress.advance(progress_units / res.r, "multiple scattering: transport");
    });
  }

  void add_into(HalfTable4D& sum, const HalfTable4D& term) {
    const std::size_t rows = static_cast<std::size_t>(res.r) * res.mu;
    for_each(rows, [&](std::size_t row) {
      const int layer = static_cast<int>(row / res.mu);
      const int jm = static_cast<int>(row % res.mu);
      const std::size_t n = sum.row_texels() * stride;
      std::vector<float> a(n), b(n);
      sum.load_row(layer, jm, a.data());
      term.load_row(layer, jm, b.data());
      for (std::size_t i = 0; i < n; ++i) a[i] += b[i];
      sum.store_row(layer, jm, a.data());
    });
  }
};

void validate(const Resolution& res) {
  // The 4D sizes and the orders are the model's options (bruneton.cpp); the others are fixed
  // by the implementation and named by their Resolution member.
  auto require = [](bool ok, const char* field, const char* reason) {
    if (!ok) throw InvalidInput(field, reason);
  };
  require(res.r >= 2, "table_r_size", "must be >= 2");
  require(res.mu >= 4 && res.mu % 2 == 0, "table_mu_size", "must be even and >= 4");
  require(res.mu_s >= 2, "table_mu_s_size", "must be >= 2");
  require(res.nu >= 2, "table_nu_size", "must be >= 2");
  require(res.orders >= 1, "scattering_orders", "must be >= 1");
  require(res.transmittance_mu >= 2, "transmittance_mu", "must be >= 2");
  require(res.transmittance_r >= 2, "transmittance_r", "must be >= 2");
  require(res.irradiance_mu_s >= 2, "irradiance_mu_s", "must be >= 2");
  require(res.irradiance_r >= 2, "irradiance_r", "must be >= 2");
  require(res.transmittance_steps >= 1, "transmittance_steps", "must be >= 1");
  require(res.inscatter_steps >= 1, "inscatter_steps", "must be >= 1");
  require(res.sphere_samples >= 1, "sphere_samples", "must be >= 1");
  require(res.irradiance_samples >= 2, "irradiance_samples", "must be >= 2");
}

}  // namespace

Tables precompute_tables(const AtmosphereSpectra& spectra, const Resolution& resolution,
                         const PrecomputeContext& context,
                         std::shared_ptr<const TabulatedPhaseFunction> mie_phase_table) {
  validate(resolution);
  Tables t;
  t.resolution = resolution;
  t.geometry.bottom_m = spectra.parameters.earth_radius_m;
  t.geometry.top_m = spectra.parameters.top_radius_m;
  t.geometry.limit_m = spectra.parameters.top_radius_m + 1000.0;
  t.wavelengths = static_cast<int>(spectra.grid.size());
  t.stride = padded_stride(t.wavelengths);
  Coefficients k = coefficients(spectra, t.stride);
  k.mie_phase.table = std::move(mie_phase_table);
  // Progress units: single scattering 1 (twice with later orders), per order density 3,
  // transport 1.5.
  const int later_orders = std::max(resolution.orders - 1, 0);
  Progress progress(context, (later_orders > 0 ? 2.0 : 1.0) + 4.5 * later_orders + 0.05);
  Builder b{resolution, t.geometry, k, context, t, progress, t.stride};

  context.report(0.0, "transmittance");
  b.build_transmittance();
  context.check_cancelled();
  FloatTable2D delta_e = b.direct_irradiance();
  // With later orders, this pass serves only the second order's density and the first sky
  // irradiance: the rows they read (second_order_rows.h; the tables are built in full at the
  // end).
  if (later_orders > 0) {
    const std::vector<char> needed = rows_read_by_second_order(resolution, t.geometry);
    b.build_single_scattering(&needed);
  } else {
    b.build_single_scattering();
  }

  Builder::Source source{&t.single_rayleigh, &t.single_mie, nullptr};
  // Sky irradiance: the orders 1 .. max(orders - 1, 1) of light reaching the ground (2008
  // code: the delta E of iterations 2 .. orders).
  FloatTable2D irradiance_sum = b.build_irradiance(source);
  // Peak memory: three 4D tables at any time, all in half precision. The single-scattering
  // tables are read only by the second order's density and irradiance: they are released
  // after them and built again, identically, once the later orders are done, so that they are
  // never held with the density, the running sum and an order's scattering (the previous
  // order is released before the next one is transported). docs/tables-and-memory.md.
  HalfTable4D density, previous;
  for (int order = 2; order <= resolution.orders; ++order) {
    b.build_density(source, delta_e, density, 3.0);
    if (order == 2) {
      t.single_rayleigh = HalfTable4D{};
      t.single_mie = HalfTable4D{};
    }
    if (order > 2) {
      FloatTable2D e = b.build_irradiance(source);
      for (std::size_t i = 0; i < e.values.size(); ++i) irradiance_sum.values[i] += e.values[i];
      delta_e = std::move(e);
    } else {
      delta_e = irradiance_sum;
    }
    previous = HalfTable4D{};
    HalfTable4D current;
    b.build_scattering(density, current, 1.5);
    if (order == 2) {
      t.multiple = std::move(current);
      source = Builder::Source{nullptr, nullptr, &t.multiple};
    } else {
      b.add_into(t.multiple, current);
      previous = std::move(current);
      source = Builder::Source{nullptr, nullptr, &previous};
    }
  }
  if (later_orders > 0) {
    density = HalfTable4D{};
    previous = HalfTable4D{};
    // Every row, each computed as in the first pass (single scattering reads only the
    // transmittance): the rows of the first pass again bit for bit, and the others.
    b.build_single_scattering();
  }
  t.sky_irradiance = std::move(irradiance_sum);
  context.report(1.0, "done");
  return t;
}

}  // namespace clearsky::bruneton
