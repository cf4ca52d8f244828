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
  Lagrange6Newton(std::span<const double> x, std::span<const double> f, std::size_t k0)
      : node_{x[k0], x[k0 + 1], x[k0 + 2], x[k0 + 3], x[k0 + 4], x[k0 + 5]} {
    // c_j = f[x_0 ... x_j]: each level of divided differences from the one below, in named
    // registers (as a loop over an array, GCC's vectorised form stalled on forwarding its
    // stores: about a third of a substage's horizon search).
    const auto& [x0, x1, x2, x3, x4, x5] = node_;
    double c0 = f[k0], c1 = f[k0 + 1], c2 = f[k0 + 2], c3 = f[k0 + 3], c4 = f[k0 + 4],
           c5 = f[k0 + 5];
    c5 = (c5 - c4) / (x5 - x4); // level 1
    c4 = (c4 - c3) / (x4 - x3);
    c3 = (c3 - c2) / (x3 - x2);
    c2 = (c2 - c1) / (x2 - x1);
    c1 = (c1 - c0) / (x1 - x0);
    c5 = (c5 - c4) / (x5 - x3); // level 2
    c4 = (c4 - c3) / (x4 - x2);
    c3 = (c3 - c2) / (x3 - x1);
    c2 = (c2 - c1) / (x2 - x0);
    c5 = (c5 - c4) / (x5 - x2); // level 3
    c4 = (c4 - c3) / (x4 - x1);
    c3 = (c3 - c2) / (x3 - x0);
    c5 = (c5 - c4) / (x5 - x1); // level 4
    c4 = (c4 - c3) / (x4 - x0);
    c5 = (c5 - c4) / (x5 - x0); // level 5
    c_ = {c0, c1, c2, c3, c4, c5};
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
