// Quadrature nodes along a segment of a ray through a spherically symmetric atmosphere whose
// densities fall off exponentially with altitude. Integrands along such rays are smooth but
// not polynomial: the density changes by a factor e every scale height of altitude, and a
// ray near grazing has its density peak at the tangent point. The segment is therefore cut at
// the tangent point and wherever the altitude crosses a level of a ladder of step
// altitude_step_m anchored at the lowest point of the segment; each piece gets an n-point
// Gauss-Legendre rule. For exp(-a t) on a unit piece the Gauss-Legendre error is about
// 1.7e-23 a^16 (8 nodes): a step of one scale height is exact to rounding.
#pragma once

#include <vector>

namespace clearsky {

struct RayQuadratureOptions {
  double altitude_step_m = 2400.0;  // about twice the smallest scale height: ~1e-9 relative
  int nodes_per_piece = 6;

  // The settings of the double-precision references (step 1200 m, 10 nodes): relative error
  // at rounding level for scale heights >= 1200 m (the paper's atmosphere).
  static RayQuadratureOptions reference() { return {1200.0, 10}; }
};

// Cut points of the segment [d0_m, d1_m] of the ray (r_m, mu) (see ray_scattering.h), in
// increasing order, first d0_m and last d1_m; empty when d1_m <= d0_m.
std::vector<double> ray_breakpoints(double r_m, double mu, double d0_m, double d1_m,
                                    double altitude_step_m);

struct RayNode {
  double distance_m;
  double weight_m;
  int piece;  // index of the piece [breakpoints[piece], breakpoints[piece + 1]]
};

// Gauss-Legendre nodes on every piece of ray_breakpoints(); the weights sum to d1 - d0.
std::vector<RayNode> ray_nodes(const std::vector<double>& breakpoints, int nodes_per_piece);

}  // namespace clearsky
