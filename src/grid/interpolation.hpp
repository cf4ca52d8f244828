// Interpolation between grid points: 6-point Lagrange in the uniform coordinate x (6th order,
// above the scheme's 4th, so interpolated diagnostics add no error of their own).
#pragma once

#include "grid/grid.hpp"

#include <algorithm>
#include <array>
#include <span>

namespace gbssn1d {

/// 6-point Lagrange interpolation of f (values at nodes x[k0] ... x[k0+5]) at xi.
inline double lagrange6(std::span<const double> x, std::span<const double> f, std::size_t k0,
                        double xi) {
  double sum = 0.0;
  for (std::size_t j = k0; j < k0 + 6; ++j) {
    double w = 1.0;
    for (std::size_t m = k0; m < k0 + 6; ++m)
      if (m != j)
        w *= (xi - x[m]) / (x[j] - x[m]);
    sum += w * f[j];
  }
  return sum;
}

/// The same interpolant as lagrange6 in Newton's form: the divided differences of f on the six
/// nodes are formed once (15 divisions), and each evaluation is a nested product (5
/// multiplications, no division: lagrange6 takes 30). For a root-find on one stencil, which
/// evaluates it ten times or more. Agrees with lagrange6 to round-off (tests).
class Lagrange6Newton {
public:
  Lagrange6Newton(std::span<const double> x, std::span<const double> f, std::size_t k0) {
    for (std::size_t j = 0; j < 6; ++j) {
      node_[j] = x[k0 + j];
      c_[j] = f[k0 + j];
    }
    // c_[j] = f[x_0 ... x_j], in place
    for (std::size_t level = 1; level < 6; ++level)
      for (std::size_t j = 5; j >= level; --j)
        c_[j] = (c_[j] - c_[j - 1]) / (node_[j] - node_[j - level]);
  }
  double operator()(double xi) const {
    double sum = c_[5];
    for (std::size_t j = 5; j-- > 0;)
      sum = c_[j] + (xi - node_[j]) * sum;
    return sum;
  }

private:
  std::array<double, 6> node_{}, c_{};
};

/// First node of a 6-point stencil around the interval [k, k+1] of n nodes, kept in [0, n-6].
inline std::size_t lagrange6_start(std::size_t k, std::size_t n) {
  const std::size_t start = k >= 2 ? k - 2 : 0;
  return std::min(start, n - 6);
}

/// f (one value per point of the grid, ghosts included) at radius r inside the interior.
inline double interpolate_at_radius(const Grid& grid, std::span<const double> f, double r) {
  const auto& radii = grid.r();
  const auto it = std::upper_bound(radii.begin(), radii.end(), r);
  const std::size_t k =
      static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - radii.begin() - 1, 0));
  const std::size_t k0 = lagrange6_start(k, grid.n_total());
  return lagrange6(grid.x(), f, k0, grid.map().x_of_r(r));
}

} // namespace gbssn1d
