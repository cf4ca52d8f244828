// The level layout of box-in-box mesh refinement (mesh/hierarchy.hpp has the design note).
//
// Level l = 0 ... L-1 covers 0 <= r <= rmax / 2^l with the same number N of cells, on the
// uniform map r = (rmax / 2^l) x of the existing Grid (cell-centred, Grid::n_ghost ghosts on
// each side): each coarse cell i holds exactly the two fine cells 2i and 2i+1, whose centres
// lie at -1/4 and +1/4 of a coarse spacing from the coarse centre. One level is the single
// grid, on any map (uniform or sinh).
#pragma once

#include "fd/stencils.hpp"
#include "grid/grid.hpp"

#include <cstddef>
#include <vector>

namespace gbssn1d::mesh {

/// Interior fine cells next to the ghosts that are refilled from the coarser level at every
/// fine step when the stages are not filled one by one (TimeInterpolation::quadratic): the
/// region the four RK4 stages contaminate from the outer ghosts, (stages - 1) x stencil radius
/// (3 x 3 = 9 cells at 4th order, 3 x 4 = 12 at 6th); with the ghosts the stencils read that is
/// stages x radius points, the buffer width of Schnetter, Hawley & Hawke 2004 (CQG 21:1465,
/// Sec. 2.3).
inline constexpr std::size_t buffer_cells(int fd_order) {
  return 3 * fd::stencil_radius(fd_order);
}

/// Fewest cells per level with more than one level: the buffer, the restriction stencil's reach
/// (a coarse cell is restricted from fine cells 2i-2 ... 2i+3) and one restricted cell.
inline constexpr std::size_t min_cells(int fd_order) {
  return buffer_cells(fd_order) + 5;
}

/// Finite-difference orders boxes offer: 2, 4 and 6. The prolongation and restriction are
/// 6-point Lagrange operators, 6th order (transfer.hpp); 8th order would need 8-point ones.
inline constexpr bool boxes_order(int fd_order) {
  return fd_order == 2 || fd_order == 4 || fd_order == 6;
}

class MeshLayout {
public:
  /// `levels` levels of `n_cells` cells each on `map` (levels > 1: a uniform map, N even, at
  /// least min_cells). Throws std::invalid_argument naming the parameter and why.
  /// `fd_order`: every level's finite-difference order (2, 4 or 6 with more than one level).
  MeshLayout(const RadialMap& map, std::size_t n_cells, std::size_t levels, int fd_order = 4);
  /// L uniform levels on [0, rmax].
  MeshLayout(double rmax, std::size_t n_cells, std::size_t levels, int fd_order = 4)
      : MeshLayout(RadialMap::uniform(rmax), n_cells, levels, fd_order) {}

  std::size_t levels() const { return grids_.size(); }
  int fd_order() const { return grids_.front().fd_order(); }
  std::size_t n_cells() const { return grids_.front().n_interior(); }
  const Grid& grid(std::size_t level) const { return grids_.at(level); }
  /// r up to which level l is evolved: rmax / 2^l.
  double extent(std::size_t level) const { return grids_.at(level).map().rmax(); }
  /// The spacing of level l (uniform levels; for one sinh level its smallest spacing).
  double spacing(std::size_t level) const { return grids_.at(level).min_spacing(); }

  /// The finest level on which r lies at least `margin_cells` of its cells inside its outer
  /// edge (level 0 if none).
  std::size_t finest_level_covering(double r, double margin_cells) const {
    for (std::size_t l = levels(); l-- > 1;)
      if (r <= extent(l) - margin_cells * spacing(l))
        return l;
    return 0;
  }

private:
  std::vector<Grid> grids_;
};

} // namespace gbssn1d::mesh
