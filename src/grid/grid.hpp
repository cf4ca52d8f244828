// Cell-centred radial grid on a map x -> r(x).
//
// The computational coordinate x is uniform, x_i = (i + 1/2) dx for the interior cells
// i = 0 ... N-1 on [0, 1]; the radius is r(x), an odd function of x, so that the ghost cells
// x_{-1-j} = -x_j sit at r = -r_j and are filled by parity (equations document, Sec. 7).
// Derivatives with respect to r follow from the chain rule:
//   f_r  = f_x / r_x,
//   f_rr = f_xx / r_x^2 - f_x r_xx / r_x^3.
#pragma once

#include <cstddef>
#include <vector>

namespace gbssn1d {

enum class GridKind { uniform, sinh };

/// Radial map r(x) on x in [0, 1] with r(0) = 0 and r(1) = rmax.
///  uniform: r = rmax x;
///  sinh:    r = rmax sinh(s x) / sinh(s), with s chosen so that the innermost cell has the
///           requested width (fine near the puncture, coarse far out).
class RadialMap {
public:
  static RadialMap uniform(double rmax);
  /// The sinh map whose innermost cell of a grid of n cells is `dr_inner` wide (at r = 0:
  /// dr/dx * dx = dr_inner). Throws std::invalid_argument if that needs dr_inner >= rmax / n.
  static RadialMap sinh(double rmax, double dr_inner, std::size_t n);

  GridKind kind() const { return kind_; }
  double rmax() const { return rmax_; }
  double stretch() const { return s_; } ///< s of the sinh map (0 for uniform)

  double r(double x) const;
  /// The inverse map, in closed form: x = r / rmax, or asinh(r sinh(s) / rmax) / s.
  double x_of_r(double r) const;
  double dr_dx(double x) const;
  double d2r_dx2(double x) const;

private:
  GridKind kind_ = GridKind::uniform;
  double rmax_ = 1.0;
  double s_ = 0.0;
};

class Grid {
public:
  /// Ghosts on each side: the widest stencil of the highest order (8th-order upwind and the
  /// 10th difference of its dissipation reach 5 points); lower orders leave the outer ones unread.
  static constexpr std::size_t n_ghost = 5;

  /// N cells on `map`, differenced at `fd_order` (2, 4, 6 or 8: fd/stencils.hpp); throws
  /// std::invalid_argument for another order.
  Grid(RadialMap map, std::size_t n_interior, int fd_order = 4);
  /// Cells given by their centres and widths (increasing, positive), without a map: the
  /// composite of several grids, for output and norms. The origin ghosts mirror the first cells
  /// (r -> -r), the outer ghosts continue the last width; x, 1/r_x and the second-derivative
  /// coefficient are NaN, so that finite differences on such a grid come out non-finite. Its
  /// map() is the uniform map to the last cell's outer face.
  Grid(const std::vector<double>& r_cells, const std::vector<double>& dr_cells);

  std::size_t n_interior() const { return n_; }
  std::size_t n_total() const { return n_ + 2 * n_ghost; }
  std::size_t first_interior() const { return n_ghost; }
  std::size_t end_interior() const { return n_ghost + n_; } ///< one past the last interior
  double dx() const { return dx_; }
  const RadialMap& map() const { return map_; }
  /// The order of the finite differences on this grid: the right-hand side and every
  /// diagnostic (constraints, expansion) difference at it.
  int fd_order() const { return fd_order_; }

  // Per point (ghosts included), index 0 ... n_total()-1.
  const std::vector<double>& x() const { return x_; }
  const std::vector<double>& r() const { return r_; }
  const std::vector<double>& inv_r() const { return inv_r_; }
  const std::vector<double>& inv_dr_dx() const { return inv_rx_; }
  /// coefficient of f_x in f_rr: -r_xx / r_x^3
  const std::vector<double>& d2_fx_coeff() const { return d2_fx_coeff_; }
  /// local spacing dr_i = r_x(x_i) dx
  const std::vector<double>& dr() const { return dr_; }

  double min_spacing() const;

  /// Index of the interior mirror of ghost i at the origin (i < n_ghost).
  static constexpr std::size_t mirror(std::size_t i) { return 2 * n_ghost - 1 - i; }

private:
  RadialMap map_;
  std::size_t n_;
  double dx_;
  int fd_order_ = 4;
  std::vector<double> x_, r_, inv_r_, inv_rx_, d2_fx_coeff_, dr_;
};

/// The sinh grid is one map for every N: its innermost cell is `dr_inner` wide at this N, so
/// that at N cells every spacing is (sinh_reference_N / N) times the reference grid's.
inline constexpr std::size_t sinh_reference_N = 400;

/// A grid by its parameters.
struct GridSpec {
  GridKind kind = GridKind::sinh;
  std::size_t N = 400; ///< interior cells
  double rmax = 1000.0;
  double dr_inner = 0.02; ///< sinh: innermost cell width at N = sinh_reference_N
  int fd_order = 4;       ///< finite-difference order (2, 4, 6, 8)
};

/// The grid of `spec`; the sinh map is fixed at sinh_reference_N cells, so N alone refines.
Grid make_grid(const GridSpec& spec);

} // namespace gbssn1d
