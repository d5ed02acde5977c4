// The inner loop of the transport of an order's density J along the view rays (Bruneton and
// Neyret 2008, Eq. 8; the 2008 code's inscatterN): at one sample of the view ray of a (r, mu)
// row and one nu slice, every mu_s texel of the slice reads J by a 4D lookup and adds it,
// times the sample's trapezoid weight and view transmittance, to its running integral.
//
// For a given sample and slice the r, mu and nu axes of the lookup are the same for all the
// row's mu_s texels (only the sample's sun cosine differs), so the lookup's rows of J and their
// weights are computed once (TransportLookup) and each texel only adds its mu_s axis. The sums
// are those of gather_4d() and sum_rows() term for term and in the same order, so the result is
// the same bit for bit (tests/models/bruneton/scattering_transport_test.cpp); the AVX2 path
// computes two texels' lookups at once so that their chains of multiply-adds overlap.
#pragma once

#include <cstdint>

#include "models/bruneton/bruneton_functions.h"
#include "models/bruneton/bruneton_tables.h"

namespace clearsky::bruneton {

// The rows of J that one lookup reads, in gather_4d()'s order (r, then mu, then nu), each
// pointing at the row's mu_s texel 0 of the slice, with its interpolation weight in r, mu and
// nu times the row's half-precision scale (never zero: gather_4d() skips those terms).
struct TransportLookup {
  static constexpr int kCapacity = 8;
  const std::uint16_t* rows[kCapacity];
  double weights[kCapacity];
  int count = 0;
};

// The lookup of `table` at axes r, mu and nu, any mu_s: gather_4d()'s rows and weights (with
// weight 1) before its mu_s axis.
TransportLookup transport_lookup(const HalfTable4D& table, const Axis& r, const Axis& mu,
                                 const Axis& nu);

// For each mu_s texel m in [0, n_mu_s): acc[m * stride + w] += view_weight[w] * J_m[w], where
// J_m is the lookup's sum over its rows of float(weight x mu_s weight) x the row's texel at
// mu_s_axes[m] (both texels of the axis, the second skipped when its weight is zero), as
// gather_4d() and sum_rows() compute it. stride is a multiple of 8.
void add_transport_sample(const TransportLookup& lookup, const Axis* mu_s_axes, int n_mu_s,
                          const float* view_weight, int stride, float* acc);

// The same with sum_rows() (the dispatcher of spectral_rows.h) per texel: what the
// precomputation did before, kept as the path of CPUs without AVX2 and for the tests.
void add_transport_sample_reference(const TransportLookup& lookup, const Axis* mu_s_axes,
                                    int n_mu_s, const float* view_weight, int stride, float* acc);

}  // namespace clearsky::bruneton
