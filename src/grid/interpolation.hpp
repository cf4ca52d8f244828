// Interpolation between grid points: 6-point Lagrange in the uniform coordinate x (6th order,
// above the scheme's 4th, so interpolated diagnostics add no error of their own).
#pragma once

#include "grid/grid.hpp"

#include <algorithm>
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
