// Values of a spectral quantity on a WavelengthGrid: one contiguous array of doubles, so that
// element-wise arithmetic over wavelengths is a simple loop the compiler vectorises. The grid
// itself is kept apart (pbrt-v4's separation of grid, values and function); a Spectrum knows
// only its length, and mixing lengths is a bug (asserted).
#pragma once

#include <cassert>
#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <vector>

namespace clearsky {

class Spectrum {
 public:
  Spectrum() = default;
  explicit Spectrum(std::size_t size, double value = 0.0) : v_(size, value) {}
  explicit Spectrum(std::vector<double> values) : v_(std::move(values)) {}
  Spectrum(std::initializer_list<double> values) : v_(values) {}

  std::size_t size() const { return v_.size(); }
  double* data() { return v_.data(); }
  const double* data() const { return v_.data(); }
  double& operator[](std::size_t i) { return v_[i]; }
  double operator[](std::size_t i) const { return v_[i]; }
  auto begin() { return v_.begin(); }
  auto end() { return v_.end(); }
  auto begin() const { return v_.begin(); }
  auto end() const { return v_.end(); }
  const std::vector<double>& values() const { return v_; }

  Spectrum& operator+=(const Spectrum& o) {
    return apply(o, [](double a, double b) { return a + b; });
  }
  Spectrum& operator-=(const Spectrum& o) {
    return apply(o, [](double a, double b) { return a - b; });
  }
  Spectrum& operator*=(const Spectrum& o) {
    return apply(o, [](double a, double b) { return a * b; });
  }
  Spectrum& operator/=(const Spectrum& o) {
    return apply(o, [](double a, double b) { return a / b; });
  }
  Spectrum& operator*=(double s) {
    for (double& x : v_) x *= s;
    return *this;
  }
  Spectrum& operator/=(double s) { return *this *= 1.0 / s; }

  friend Spectrum operator+(Spectrum a, const Spectrum& b) { return a += b; }
  friend Spectrum operator-(Spectrum a, const Spectrum& b) { return a -= b; }
  friend Spectrum operator*(Spectrum a, const Spectrum& b) { return a *= b; }
  friend Spectrum operator/(Spectrum a, const Spectrum& b) { return a /= b; }
  friend Spectrum operator*(Spectrum a, double s) { return a *= s; }
  friend Spectrum operator*(double s, Spectrum a) { return a *= s; }
  friend Spectrum operator/(Spectrum a, double s) { return a /= s; }

  // exp(-x) element-wise: transmittance from an optical depth.
  friend Spectrum exp_negative(Spectrum a) {
    for (double& x : a.v_) x = std::exp(-x);
    return a;
  }

  bool all_finite() const {
    for (double x : v_)
      if (!std::isfinite(x)) return false;
    return true;
  }
  bool operator==(const Spectrum& other) const = default;

 private:
  template <typename F>
  Spectrum& apply(const Spectrum& o, F f) {
    assert(o.v_.size() == v_.size() && "spectra of different grids");
    for (std::size_t i = 0; i < v_.size(); ++i) v_[i] = f(v_[i], o.v_[i]);
    return *this;
  }

  std::vector<double> v_;
};

}  // namespace clearsky
