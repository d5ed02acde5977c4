// Quadrature rules shared by the numerical models.
#pragma once

#include <utility>
#include <vector>

namespace clearsky {

// n-point Gauss-Legendre nodes and weights on [a, b] (exact for polynomials of degree
// 2n - 1); nodes by Newton iteration on the Legendre recurrence to 1e-15.
std::vector<std::pair<double, double>> gauss_legendre(int n, double a, double b);

// Composite trapezoid weights for n >= 2 equally spaced samples over [a, b].
std::vector<double> trapezoid_weights(int n, double a, double b);

}  // namespace clearsky
