#include "mesh/layout.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace gbssn1d::mesh {

MeshLayout::MeshLayout(const RadialMap& map, std::size_t n_cells, std::size_t levels,
                       int fd_order) {
  const auto bad = [](const std::string& flag, const std::string& value, const std::string& why) {
    return std::invalid_argument(flag + " = " + value + " is invalid: " + why);
  };
  if (levels < 1)
    throw bad("--levels", std::to_string(levels), "a hierarchy needs at least one level");
  if (!(std::isfinite(map.rmax()) && map.rmax() > 0.0))
    throw bad("--rmax", std::to_string(map.rmax()), "must be positive and finite");
  if (n_cells < Grid::n_ghost)
    throw bad("--N", std::to_string(n_cells),
              "a level needs at least " + std::to_string(Grid::n_ghost)
                  + " cells (the origin's ghosts mirror them)");
  if (levels > 1) {
    if (map.kind() != GridKind::uniform)
      throw bad("--grid", "sinh",
                "box-in-box refinement needs the uniform map on every level (--grid boxes)");
    if (n_cells % 2 != 0)
      throw bad("--N", std::to_string(n_cells),
                "box-in-box refinement needs an even number of cells (each coarse cell holds "
                "two fine cells)");
    if (!boxes_order(fd_order))
      throw bad("--fd-order", std::to_string(fd_order),
                "box-in-box refinement offers 2, 4 and 6: its prolongation and restriction are "
                "6th order");
    if (n_cells < min_cells(fd_order))
      throw bad("--N", std::to_string(n_cells),
                "box-in-box refinement needs at least " + std::to_string(min_cells(fd_order))
                    + " cells per level at --fd-order " + std::to_string(fd_order)
                    + " (the fine level's buffer of " + std::to_string(buffer_cells(fd_order))
                    + " cells, the restriction and prolongation stencils)");
    // the levels' extents rmax / 2^l must stay representable and distinct
    if (levels > 60)
      throw bad("--levels", std::to_string(levels), "at most 60 levels");
  }
  grids_.reserve(levels);
  grids_.emplace_back(map, n_cells, fd_order);
  for (std::size_t l = 1; l < levels; ++l)
    grids_.emplace_back(RadialMap::uniform(std::ldexp(map.rmax(), -static_cast<int>(l))), n_cells,
                        fd_order);
}

} // namespace gbssn1d::mesh
