// A Simulation to and from a checkpoint (evolution/checkpoint.hpp): every level's state, the
// stepper's time levels, the horizon tracker's history and the output counters, so that a
// resumed run is bit-identical to one never stopped.
#include "evolution/simulation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace gbssn1d {

void Simulation::restore(const Checkpoint& checkpoint) {
  const std::size_t n_levels = layout_.levels();
  std::vector<std::size_t> sizes;
  for (const State& u : levels_u_)
    sizes.push_back(u.size());
  const Checkpoint c =
      resumable_checkpoint(checkpoint, {config_, layout_, sizes, schedule_.dt, schedule_.n_steps,
                                        initial_evaluations_[0]});
  // the file's values in this run's fields (their count checked above)
  const Fields fields(config_.rhs.formulation, config_.rhs.matter);
  const auto state = [&](const StateValues& values, std::size_t l) {
    return State(fields, values, layout_.grid(l).n_total());
  };
  levels_u_[0] = state(c.u, 0);
  for (std::size_t l = 1; l < n_levels; ++l)
    levels_u_[l] = state(c.finer[l - 1], l);
  t_ = c.t;
  step_ = c.step;
  clock_.k_series = c.k_series;
  clock_.k_profiles = c.k_profiles;
  rhs_[0].set_horizon_radius(c.h_AH);
  rhs_[0].set_evaluations(c.evaluations);
  if (n_levels > 1) {
    tracker_->restore(c.shared_h_AH, c.h_AH_history);
    for (std::size_t l = 1; l < n_levels; ++l) {
      rhs_[l].set_horizon_radius(c.level_h_AH[l]);
      // level l takes steps(l) steps of 4 evaluations per step of the hierarchy
      const std::uint64_t n =
          initial_evaluations_[l]
          + 4 * static_cast<std::uint64_t>(c.step) * static_cast<std::uint64_t>(stepper_.steps(l));
      rhs_[l].set_evaluations(n);
      stepper_.set_evaluations(l, n);
    }
    for (std::size_t l = 0; l < n_levels; ++l) {
      std::vector<mesh::MeshStepper::TimeLevel> history;
      for (const auto& [t, u] : c.history[l])
        history.push_back({t, state(u, l)});
      stepper_.set_history(l, std::move(history));
    }
  } else {
    tracker_->restore(c.h_AH, c.h_AH_history); // a history with --ah-every extrapolated only
  }
  had_horizon_ = c.had_horizon;
  reported_ = c.reported;
  resumed_ = true;
}

Checkpoint Simulation::checkpoint(Output& out, const std::optional<double>& h_AH_before_rhs) const {
  Checkpoint c;
  c.config = checkpoint_config;
  c.step = step_;
  c.t = t_;
  c.dt = schedule_.dt;
  c.k_series = clock_.k_series;
  c.k_profiles = clock_.k_profiles;
  c.h_AH = h_AH_before_rhs;
  c.had_horizon = had_horizon_;
  c.reported = reported_;
  c.evaluations = evaluations_before_rhs_;
  c.marks = out.marks();
  c.u = levels_u_[0].values();
  c.h_AH_history = tracker_->history(); // boxes, and single grids with --ah-every extrapolated
  if (layout_.levels() > 1) {
    for (std::size_t l = 1; l < layout_.levels(); ++l)
      c.finer.push_back(levels_u_[l].values());
    c.shared_h_AH = tracker_->shared_before_rhs(); // before the next step's first RHS, as h_AH
    for (std::size_t l = 0; l < layout_.levels(); ++l) {
      c.level_h_AH.push_back(l == 0 ? h_AH_before_rhs : rhs_[l].horizon_radius());
      std::vector<Checkpoint::TimeLevel> history;
      for (const auto& [t, u] : stepper_.history(l))
        history.push_back({t, u.values()});
      c.history.push_back(std::move(history));
    }
  }
  return c;
}

} // namespace gbssn1d
