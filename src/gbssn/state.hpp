// The evolved state: the registry variables of its Fields (core/registry.hpp: its formulation's
// rows, then its matter's) on all points (ghosts included), variable-major, so that each field
// is one contiguous array: u[fields.slot(v) * n_total + i]. The state carries its Fields as a
// tag, set where it is made (make_state) and passed on with its shape (fit): nothing infers
// them from a size.
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
  /// fields.size() rows of n_total points each, all `value`.
  State(Fields fields, std::size_t n_total, double value = 0.0)
      : fields_(fields), values_(fields.size() * n_total, value) {}
  /// The values as they are laid out (a checkpoint's): their count must be whole rows.
  State(Fields fields, std::vector<double> values, std::size_t n_total)
      : fields_(fields), values_(std::move(values)) {
    if (values_.size() != fields.size() * n_total)
      throw std::invalid_argument("a state's values are not its fields' rows");
  }

  Fields fields() const { return fields_; }
  Formulation formulation() const { return fields_.formulation; }
  Matter matter() const { return fields_.matter; }
  /// The registry rows this state holds, in order.
  std::span<const VarInfo> vars() const { return fields_.rows(); }

  /// The fields and size of `other`, values kept where the sizes agree (as
  /// std::vector::resize): the stepper's stages and scratch take their state's shape.
  void fit(const State& other) {
    fields_ = other.fields_;
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
  Fields fields_;
  std::vector<double> values_;
};

inline State make_state(const Grid& grid, Fields fields) {
  return State(fields, grid.n_total());
}

/// v's row of `u` (a variable the state holds).
inline std::span<double> field(State& u, const Grid& grid, Var v) {
  return {u.data() + u.fields().slot(v) * grid.n_total(), grid.n_total()};
}
inline std::span<const double> field(const State& u, const Grid& grid, Var v) {
  return {u.data() + u.fields().slot(v) * grid.n_total(), grid.n_total()};
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
