// The evolved state: the formulation's registry variables (core/registry.hpp: evolved()) on all
// points (ghosts included), variable-major, so that each field is one contiguous array:
// u[index(v) * n_total + i]. Its size tells which formulation it belongs to (state_vars()).
#pragma once

#include "core/registry.hpp"
#include "grid/grid.hpp"

#include <span>
#include <stdexcept>
#include <vector>

namespace gbssn1d {

using State = std::vector<double>;

inline State make_state(const Grid& grid, Formulation formulation) {
  return State(n_evolved(formulation) * grid.n_total(), 0.0);
}

/// The formulation whose variables `u` holds on `grid` (by its size).
inline Formulation formulation_of(const State& u, const Grid& grid) {
  const std::size_t n = grid.n_total();
  const auto f = n > 0 && u.size() % n == 0 ? formulation_with(u.size() / n) : std::nullopt;
  if (!f)
    throw std::logic_error("a state whose size is no formulation's on its grid");
  return *f;
}

/// The registry rows `u` holds, in order.
inline std::span<const VarInfo> state_vars(const State& u, const Grid& grid) {
  return evolved(formulation_of(u, grid));
}

inline std::span<double> field(State& u, const Grid& grid, Var v) {
  return {u.data() + index(v) * grid.n_total(), grid.n_total()};
}
inline std::span<const double> field(const State& u, const Grid& grid, Var v) {
  return {u.data() + index(v) * grid.n_total(), grid.n_total()};
}

/// Fill the ghost cells at the origin from their interior mirrors by each variable's parity.
inline void fill_origin_ghosts(State& u, const Grid& grid) {
  for (const auto& entry : state_vars(u, grid)) {
    auto f = field(u, grid, entry.var);
    for (std::size_t i = 0; i < Grid::n_ghost; ++i)
      f[i] = entry.parity * f[Grid::mirror(i)];
  }
}

} // namespace gbssn1d
