// When a run writes: series rows at k dt_series, profiles at k dt_profiles, both at tmax, each
// time once (to round-off), with the counters k that checkpoints keep; and the states of every
// level at the output times that fall between two steps, from each level's RK4 dense output
// (a fine box over its own substep).
#pragma once

#include "evolution/evolution_config.hpp"
#include "gbssn/state.hpp"
#include "mesh/layout.hpp"

#include <array>
#include <optional>
#include <vector>

namespace gbssn1d {

class OutputClock {
public:
  /// `dt`: the run's step; output times within 1e-9 dt are one time.
  OutputClock(const EvolutionConfig& config, double dt);

  long k_series = 1, k_profiles = 1; ///< the next output times are k dt_series, k dt_profiles
  double next_series() const;
  double next_profiles() const;

  struct Due {
    double t;
    bool series, profiles;
  };
  /// The next output time, if it is at most t (to round-off).
  std::optional<Due> due_by(double t) const;
  /// Counts `d` as written; false once it was the last output (at tmax).
  bool advance(const Due& d);
  /// Whether an output time falls before t (to round-off).
  bool before(double t) const;
  /// The output times strictly inside (t0, t1), before tmax, in order.
  std::vector<double> times_inside(double t0, double t1) const;

private:
  double dt_series_, dt_profiles_, tmax_, tol_;
};

/// The first multiple of `every` after t (infinity for every = 0): the next checkpoint time
/// (arithmetic, never a loop: it cannot stall).
double checkpoint_after(double every, double t);

/// Every level's state at the output times inside the coming step of the hierarchy, filled as
/// each level takes its (sub)step (mesh::MeshStepper::on_level_step).
class DenseOutput {
public:
  DenseOutput(const mesh::MeshLayout& layout, double chi_floor, double dt);
  /// Starts a step: the times to fill.
  void prepare(const std::vector<double>& times);
  /// Level `level` stepped from t0 by dt with stages k: its state at every time inside.
  void fill(std::size_t level, double t0, double dt, const State& u0,
            const std::array<const State*, 4>& k);
  /// Every level's state at t, which must have been filled on every level.
  std::vector<State>& at(double t);

private:
  struct Pending {
    double t;
    std::vector<State> u;     ///< one per level
    std::vector<bool> filled; ///< per level
  };
  const mesh::MeshLayout& layout_;
  double chi_floor_, tol_;
  std::vector<Pending> pending_;
};

} // namespace gbssn1d
