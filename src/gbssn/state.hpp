// The evolved state: all registry variables on all points (ghosts included), variable-major,
// so that each field is one contiguous array: u[index(v) * n_total + i].
#pragma once

#include "core/registry.hpp"
#include "grid/grid.hpp"

#include <span>
#include <vector>

namespace gbssn1d {

using State = std::vector<double>;

inline State make_state(const Grid& grid) {
  return State(n_vars * grid.n_total(), 0.0);
}

inline std::span<double> field(State& u, const Grid& grid, Var v) {
  return {u.data() + index(v) * grid.n_total(), grid.n_total()};
}
inline std::span<const double> field(const State& u, const Grid& grid, Var v) {
  return {u.data() + index(v) * grid.n_total(), grid.n_total()};
}

/// Fill the ghost cells at the origin from their interior mirrors by each variable's parity.
inline void fill_origin_ghosts(State& u, const Grid& grid) {
  for (const auto& entry : registry) {
    auto f = field(u, grid, entry.var);
    for (std::size_t i = 0; i < Grid::n_ghost; ++i)
      f[i] = entry.parity * f[Grid::mirror(i)];
  }
}

} // namespace gbssn1d
