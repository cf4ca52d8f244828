// The evolved state: the registry variables its formulation evolves (core/registry.hpp:
// evolved()) on all points (ghosts included), variable-major, so that each field is one
// contiguous array: u[index(v) * n_total + i]. The state carries its formulation as a tag, set
// where it is made (make_state) and passed on with its shape (fit): nothing infers it from a
// size.
#pragma once

#include "core/registry.hpp"
#include "grid/grid.hpp"

#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

namespace gbssn1d {

class State {
public:
  using value_type = double;
  using iterator = std::vector<double>::iterator;
  using const_iterator = std::vector<double>::const_iterator;

  State() = default;
  /// n_evolved(formulation) rows of n_total points each, all `value`.
  State(Formulation formulation, std::size_t n_total, double value = 0.0)
      : formulation_(formulation), values_(n_evolved(formulation) * n_total, value) {}
  /// The values as they are laid out (a checkpoint's): their count must be whole rows.
  State(Formulation formulation, std::vector<double> values, std::size_t n_total)
      : formulation_(formulation), values_(std::move(values)) {
    if (values_.size() != n_evolved(formulation) * n_total)
      throw std::invalid_argument("a state's values are not its formulation's rows");
  }

  Formulation formulation() const { return formulation_; }
  /// The registry rows this state holds, in order.
  std::span<const VarInfo> vars() const { return evolved(formulation_); }

  /// The formulation and size of `other`, values kept where the sizes agree (as
  /// std::vector::resize): the stepper's stages and scratch take their state's shape.
  void fit(const State& other) {
    formulation_ = other.formulation_;
    values_.resize(other.values_.size());
  }

  std::size_t size() const { return values_.size(); }
  bool empty() const { return values_.empty(); }
  double* data() { return values_.data(); }
  const double* data() const { return values_.data(); }
  double& operator[](std::size_t k) { return values_[k]; }
  double operator[](std::size_t k) const { return values_[k]; }
  iterator begin() { return values_.begin(); }
  iterator end() { return values_.end(); }
  const_iterator begin() const { return values_.begin(); }
  const_iterator end() const { return values_.end(); }
  const std::vector<double>& values() const { return values_; }

  friend bool operator==(const State&, const State&) = default;

private:
  Formulation formulation_ = Formulation::bssn;
  std::vector<double> values_;
};

inline State make_state(const Grid& grid, Formulation formulation) {
  return State(formulation, grid.n_total());
}

inline std::span<double> field(State& u, const Grid& grid, Var v) {
  return {u.data() + index(v) * grid.n_total(), grid.n_total()};
}
inline std::span<const double> field(const State& u, const Grid& grid, Var v) {
  return {u.data() + index(v) * grid.n_total(), grid.n_total()};
}

/// Fill the ghost cells at the origin from their interior mirrors by each variable's parity.
inline void fill_origin_ghosts(State& u, const Grid& grid) {
  for (const auto& entry : u.vars()) {
    auto f = field(u, grid, entry.var);
    for (std::size_t i = 0; i < Grid::n_ghost; ++i)
      f[i] = entry.parity * f[Grid::mirror(i)];
  }
}

} // namespace gbssn1d
