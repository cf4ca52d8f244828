#include "grid/grid.hpp"

#include "fd/stencils.hpp"

#include <boost/math/tools/roots.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace gbssn1d {

RadialMap RadialMap::uniform(double rmax) {
  RadialMap m;
  m.kind_ = GridKind::uniform;
  m.rmax_ = rmax;
  m.s_ = 0.0;
  return m;
}

RadialMap RadialMap::sinh(double rmax, double dr_inner, std::size_t n) {
  // dr/dx at x = 0 is rmax s / sinh(s), which falls monotonically from rmax (s -> 0) to 0.
  // Solve rmax s / sinh(s) * dx = dr_inner for s > 0.
  const double dx = 1.0 / static_cast<double>(n);
  const double target = dr_inner / (rmax * dx); // = s / sinh(s), must be in (0, 1)
  if (!(target > 0.0 && target < 1.0))
    throw std::invalid_argument("the sinh grid needs an innermost spacing below rmax/N");
  auto residual = [target](double s) { return std::log(s / std::sinh(s)) - std::log(target); };
  double lo = 1e-8, hi = 1.0;
  while (residual(hi) > 0.0)
    hi *= 2.0; // s/sinh(s) ~ 2 s e^{-s}: hi stays moderate
  std::uintmax_t iterations = 200;
  auto [a, b] = boost::math::tools::toms748_solve(
      residual, lo, hi, boost::math::tools::eps_tolerance<double>(52), iterations);
  RadialMap m;
  m.kind_ = GridKind::sinh;
  m.rmax_ = rmax;
  m.s_ = 0.5 * (a + b);
  return m;
}

double RadialMap::r(double x) const {
  if (kind_ == GridKind::uniform)
    return rmax_ * x;
  return rmax_ * std::sinh(s_ * x) / std::sinh(s_);
}

double RadialMap::x_of_r(double r) const {
  if (kind_ == GridKind::uniform)
    return r / rmax_;
  return std::asinh(r * std::sinh(s_) / rmax_) / s_;
}

double RadialMap::dr_dx(double x) const {
  if (kind_ == GridKind::uniform)
    return rmax_;
  return rmax_ * s_ * std::cosh(s_ * x) / std::sinh(s_);
}

double RadialMap::d2r_dx2(double x) const {
  if (kind_ == GridKind::uniform)
    return 0.0;
  return rmax_ * s_ * s_ * std::sinh(s_ * x) / std::sinh(s_);
}

Grid::Grid(RadialMap map, std::size_t n_interior, int fd_order)
    : map_(map), n_(n_interior), dx_(1.0 / static_cast<double>(n_interior)), fd_order_(fd_order) {
  if (!fd::valid_order(fd_order))
    throw std::invalid_argument("the finite-difference order must be 2, 4, 6 or 8");
  const std::size_t n = n_total();
  x_.resize(n);
  r_.resize(n);
  inv_r_.resize(n);
  inv_rx_.resize(n);
  d2_fx_coeff_.resize(n);
  dr_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double xi =
        (static_cast<double>(i) - static_cast<double>(n_ghost) + 0.5) * dx_; // cell centres
    const double rx = map_.dr_dx(xi);
    x_[i] = xi;
    r_[i] = map_.r(xi);
    inv_r_[i] = 1.0 / r_[i];
    inv_rx_[i] = 1.0 / rx;
    d2_fx_coeff_[i] = -map_.d2r_dx2(xi) / (rx * rx * rx);
    dr_[i] = rx * dx_;
  }
}

Grid::Grid(const std::vector<double>& r_cells, const std::vector<double>& dr_cells)
    : map_(RadialMap::uniform(r_cells.empty() ? 1.0 : r_cells.back() + 0.5 * dr_cells.back())),
      n_(r_cells.size()), dx_(std::numeric_limits<double>::quiet_NaN()) {
  if (r_cells.size() < n_ghost || r_cells.size() != dr_cells.size())
    throw std::invalid_argument(
        "a grid of cells needs at least as many centres as ghosts, and one width each");
  for (std::size_t k = 0; k < n_; ++k)
    if (!(dr_cells[k] > 0.0) || (k > 0 && !(r_cells[k] > r_cells[k - 1])))
      throw std::invalid_argument("a grid of cells needs increasing centres and positive widths");
  const std::size_t n = n_total();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  x_.assign(n, nan);
  inv_rx_.assign(n, nan);
  d2_fx_coeff_.assign(n, nan);
  r_.resize(n);
  dr_.resize(n);
  inv_r_.resize(n);
  for (std::size_t k = 0; k < n_; ++k) {
    r_[n_ghost + k] = r_cells[k];
    dr_[n_ghost + k] = dr_cells[k];
  }
  for (std::size_t i = 0; i < n_ghost; ++i) {
    r_[i] = -r_[mirror(i)];
    dr_[i] = dr_[mirror(i)];
    const std::size_t o = n_ghost + n_ + i; // outer ghosts continue the last width
    dr_[o] = dr_cells.back();
    r_[o] = r_[o - 1] + dr_cells.back();
  }
  for (std::size_t i = 0; i < n; ++i)
    inv_r_[i] = 1.0 / r_[i];
}

double Grid::min_spacing() const {
  return *std::min_element(dr_.begin() + static_cast<std::ptrdiff_t>(first_interior()),
                           dr_.begin() + static_cast<std::ptrdiff_t>(end_interior()));
}

Grid make_grid(const GridSpec& spec) {
  if (spec.kind == GridKind::uniform)
    return Grid(RadialMap::uniform(spec.rmax), spec.N, spec.fd_order);
  return Grid(RadialMap::sinh(spec.rmax, spec.dr_inner, sinh_reference_N), spec.N, spec.fd_order);
}

} // namespace gbssn1d
