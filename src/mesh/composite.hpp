// The composite of a hierarchy's levels: each radius from the finest level that covers it, in
// increasing r, as one Grid of cells (mesh/hierarchy.hpp has the design note). Output and
// norms see the composite and need not know about levels; one level is its own composite.
//
// Level l covers [0, rmax / 2^l]; the finer level l+1 covers its cells 0 ... N/2 - 1 exactly
// (each coarse cell holds two fine cells), so the composite is all N cells of the finest level
// followed, from level L-2 out to level 0, by the cells N/2 ... N-1 of each: N + (L-1) N/2
// cells that tile [0, rmax] without overlap.
#pragma once

#include "gbssn/state.hpp"
#include "mesh/layout.hpp"

#include <cstddef>
#include <span>
#include <vector>

namespace gbssn1d::mesh {

class Composite {
public:
  explicit Composite(const MeshLayout& layout);

  /// The composite cells (for one level: that level's grid itself).
  const Grid& grid() const { return grid_; }
  /// Composite interior cell k: its level and its interior index on that level.
  std::size_t level(std::size_t k) const { return level_[k]; }
  std::size_t index(std::size_t k) const { return index_[k]; }
  std::size_t size() const { return level_.size(); }

  /// Values on every point of each level's grid (ghosts included; one array per level) as one
  /// array on every point of the composite grid: the interior from the levels, the origin
  /// ghosts from the finest level's, the outer ghosts from level 0's.
  std::vector<double> gather(const std::vector<std::span<const double>>& per_level) const;
  /// The same for each level's interior values (index 0 ... N-1), giving interior values.
  std::vector<double> gather_interior(const std::vector<std::span<const double>>& per_level) const;
  /// Every variable of the levels' states as one composite State.
  void gather_state(const std::vector<State>& u, State& out) const;

private:
  const MeshLayout* layout_;
  std::vector<std::size_t> level_, index_;
  Grid grid_;
};

} // namespace gbssn1d::mesh
