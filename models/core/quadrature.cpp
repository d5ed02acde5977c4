// Gauss-Legendre nodes (Golub-Welsch would also do; Newton on P_n is simpler and exact enough).
#include "models/core/quadrature.h"

#include <cmath>
#include <stdexcept>

#include "models/core/numeric.h"

namespace clearsky {

std::vector<std::pair<double, double>> gauss_legendre(int n, double a, double b) {
  if (n < 1 || n > 1000) throw std::invalid_argument("gauss_legendre: n must be in [1, 1000]");
  std::vector<std::pair<double, double>> nodes(static_cast<std::size_t>(n));
  const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
  for (int i = 0; i < n; ++i) {
    double x = std::cos(kPi * (i + 0.75) / (n + 0.5));
    double derivative = 1.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      if (n == 1) p0 = 1.0;
      derivative = n * (x * p1 - p0) / (x * x - 1.0);
      const double dx = p1 / derivative;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    const double w = 2.0 / ((1.0 - x * x) * derivative * derivative);
    nodes[static_cast<std::size_t>(i)] = {mid - half * x, half * w};
  }
  return nodes;
}

std::vector<double> trapezoid_weights(int n, double a, double b) {
  if (n < 2) throw std::invalid_argument("trapezoid_weights: n must be >= 2");
  const double h = (b - a) / (n - 1);
  std::vector<double> w(static_cast<std::size_t>(n), h);
  w.front() = w.back() = 0.5 * h;
  return w;
}

}  // namespace clearsky
