// One evolution: grid (a single grid, or box-in-box levels), initial data, right-hand side and
// the RK4 method of lines, with output at fixed cadences in time. The levels are stepped by
// mesh::MeshStepper (a single grid is its one-level case); output and norms see their
// composite (mesh/composite.hpp), the horizon finder the finest level that holds the horizon.
#pragma once

#include "diagnostics/constraints.hpp"
#include "evolution/checkpoint.hpp"
#include "evolution/evolution_config.hpp"
#include "evolution/horizon_tracker.hpp"
#include "evolution/levels.hpp"
#include "evolution/observe.hpp"
#include "evolution/output_clock.hpp"
#include "gbssn/rhs.hpp"
#include "io/output.hpp"
#include "mesh/composite.hpp"
#include "mesh/hierarchy.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace gbssn1d {

/// Thrown between steps after SIGTERM or SIGINT (core/stop_signal.hpp), once the output due
/// up to the current step is written.
class Interrupted : public std::runtime_error {
public:
  Interrupted(int signal, double t);
  int signal;
  double t;
};

class Simulation {
public:
  /// Builds the grid, the right-hand side and the initial data.
  explicit Simulation(const EvolutionConfig& config);
  // The time stepping calls this object's right-hand side: not to be copied or moved.
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  const EvolutionConfig& config() const { return config_; }
  /// Level 0's grid, state and right-hand side (the single grid's).
  const Grid& grid() const { return layout_.grid(0); }
  const GbssnRhs& rhs() const { return rhs_[0]; }
  const GbssnRhs& rhs(std::size_t level) const { return rhs_.at(level); } ///< level's
  State& state() { return levels_u_[0]; }
  const State& state() const { return levels_u_[0]; }
  /// Every level (one for a single grid) and their composite.
  const mesh::MeshLayout& layout() const { return layout_; }
  const std::vector<State>& level_states() const { return levels_u_; }
  std::vector<State>& level_states() { return levels_u_; }
  const mesh::Composite& composite() const { return composite_; }
  /// RHS evaluations of every level so far, and their point count (cells x evaluations).
  std::uint64_t evaluations() const;
  std::uint64_t point_evaluations() const;
  double time() const { return t_; }
  const Schedule& schedule() const { return schedule_; }

  /// H, M_r, G_r, R, Theta_+ on every level's interior, and their composite.
  std::vector<DerivedProfiles> level_profiles() const;
  DerivedProfiles composite_profiles(const std::vector<DerivedProfiles>& levels) const;
  DerivedProfiles composite_profiles() const { return composite_profiles(level_profiles()); }
  /// A variable at radius r (6-point Lagrange on the finest level that covers r).
  double at_radius(Var v, double r) const;
  /// H at radius r from level profiles.
  double H_at_radius(const std::vector<DerivedProfiles>& levels, double r) const;

  /// Diagnostics of the current state (evaluates the right-hand side once for d_t alpha);
  /// `d` is the composite of the derived profiles.
  SeriesRow series_row(const DerivedProfiles& d);
  /// The same, with the horizons of the current state already found.
  SeriesRow series_row(const DerivedProfiles& d, const HorizonSearch& found);

  /// Evolve to tmax (stopping between steps on SIGTERM/SIGINT: Interrupted), writing into `out`
  /// (if given) at t = k dt_series (series) and
  /// k dt_profiles (profiles) and at tmax. An output time between two steps t_n < t < t_n+1
  /// gets each level's RK4 dense output (the stages' continuous extension, error O(dt^4) per
  /// step; a fine box's over its own substep); on a step it gets the state itself. Throws
  /// NonFiniteError after writing the last finite output, leaving the files complete.
  void run(Output* out);

  /// Called after every series output (and at t = 0), e.g. to sample the state for a
  /// convergence study.
  std::function<void(Simulation&)> on_series;

  /// Called after every step, with the horizon's tracker (the extrapolated mode's pilot).
  std::function<void(const HorizonTracker&)> on_step;

  /// Progress on stderr (simulated time, speed, time left), when stderr is a terminal.
  bool show_progress = false;
  /// Put after "gbssn1d" in messages on stderr (a study names its member, e.g. " converge N=60").
  std::string label;

  /// The configuration text stored in checkpoints (config.toml of the run).
  std::string checkpoint_config;
  /// Called after each checkpoint is written (e.g. to save a study's own samples with it).
  std::function<void(const Checkpoint&)> on_checkpoint;
  /// Continue from `c` (same parameters but possibly tmax): the next run() takes up at its
  /// step, bit for bit as the uninterrupted run. Throws CheckpointError on a mismatch.
  void restore(const Checkpoint& c);
  /// The checkpoint of the current state (with the output marks of `out`).
  Checkpoint checkpoint(Output& out, const std::optional<double>& h_AH_before_rhs) const;

  /// Facts of this run for the output headers, as "key = value" lines: the time step dt, the
  /// number of steps to tmax and the smallest cell width dr-min (on boxes each level's extent,
  /// spacing and step); with matter the data's ADM mass M-ADM.
  std::string run_facts() const;

  /// Whether each parent box's point loop skips the cells under its child that no result reads
  /// (mesh::MeshStepper::first_needed_cell; every output bit for bit the same either way). On
  /// by default; off evolves every cell of every box, as a check.
  void set_skip_covered(bool skip);

  /// One step of size dt of every level (RK4, then the chi floor, apply_chi_floor).
  void step(double dt);
  /// The same with level 0's d_t u at the current state already evaluated (RK4's first stage).
  void step(double dt, const State& dudt);

  /// The horizon radius h_AH that the horizon shift uses for the current state: found on it
  /// (substage mode) or the value held since the last search. nullopt: no horizon (beta_H = 0).
  std::optional<double> horizon_radius();
  /// beta_H on every point for the current state.
  std::vector<double> horizon_shift();
  /// The horizon-adjusting shift's largest Courant number |beta_H| dt_l / dr at this time, over
  /// every level's interior (dt_l = cfl x the level's smallest spacing, the longest step a level
  /// takes), with h_AH the horizon of this state (or the prescribed h_AH(t)); where it lies
  /// and beta_H there. Nothing without the shift or a horizon.
  struct ShiftCourant {
    double number, r, beta_H, h_AH;
  };
  std::optional<ShiftCourant> horizon_shift_courant() const;
  /// Every marginal surface of the current state (each from the finest level covering it).
  HorizonSearch horizons() const;
  /// The level the horizon shift's h_AH is searched on: the finest on which the horizon (or,
  /// before one is found, the standard radius 0.8304 M) lies well inside (0 for a single grid).
  std::size_t horizon_level() const;

  /// The first non-finite value of the state, or a chi <= 0, alpha < alpha_min or
  /// alpha > alpha_max: throws NonFiniteError.
  void check_finite() const;
  /// The 1+log lapse is positive; wormhole data undershoot to about -6e-4 at the innermost cell
  /// on the default grid during the collapse and recover, so only a clear excursion stops a run.
  static constexpr double alpha_min = -0.01;
  static constexpr double alpha_max = 10.0; ///< alpha <= 1 in these spacetimes

private:
  /// Each level's first evolved cell (GbssnRhs::set_first_cell): first_needed_cell, 0 with
  /// skip_covered_ off, and 0 on the level the horizon shift's search reads every RK substage
  /// (HorizonTracker::level; a margin: that level is the finest holding the horizon, which so
  /// lies outside its child, but the search may fall back to a scan of the whole level).
  void set_first_cells();
  /// Whether run() initialises the stepper again once h_AH is known (quadratic time
  /// interpolation with the horizon shift: its earlier time levels need beta_H).
  bool reinitialises() const;
  /// Writes the series row and horizons and/or the profiles of the current state (levels_u_
  /// at t_) into `out` (if given); calls on_series after a series output.
  void write_output(Output* out, bool series, bool profiles);
  /// Writes every output time up to t_, from the levels' dense output between the steps if
  /// have_dense.
  void write_due(Output* out, bool have_dense);
  /// Writes OUT/checkpoint.bin (if `out`) and calls on_checkpoint.
  void save_checkpoint(Output* out, const std::optional<double>& h_AH_before_rhs);
  /// Say on stderr when the horizon appears or disappears.
  void report_horizon(const std::optional<MarginalSurface>& h);

  EvolutionConfig config_;
  mesh::MeshLayout layout_;       ///< the levels (one: the single grid)
  mesh::Composite composite_;     ///< their composite, for output and norms
  std::vector<GbssnRhs> rhs_;     ///< one per level
  SeriesDiagnostics diagnostics_; ///< the series row's own RHS per level
  std::vector<State> levels_u_;   ///< the state of each level
  /// h_AH for beta_H: the mode's strategy (searches, held and extrapolated values)
  std::unique_ptr<HorizonTracker> tracker_;
  State dudt_now_;    ///< level 0's d_t u at the current state: the next step's first RK4 stage
  State u_composite_; ///< the composite state, for profiles
  std::vector<std::size_t> composite_levels_; ///< the level of each composite cell
  double t_ = 0.0;
  Schedule schedule_;
  mesh::MeshStepper stepper_; ///< RK4 (Odeint's arithmetic), with the chi floor after each step
  OutputClock clock_;         ///< output times and their counters
  DenseOutput dense_;         ///< every level's state at output times between steps
  long step_ = 0;             ///< steps taken
  bool skip_covered_ = true;  ///< set_skip_covered
  bool resumed_ = false;      ///< restore() was called: run() continues, no initial output
  std::uint64_t evaluations_before_rhs_ = 0;       ///< RHS count before the current step's k1
  std::vector<std::uint64_t> initial_evaluations_; ///< per level, before the first step
  bool had_horizon_ = false; ///< for messages when the horizon appears/disappears
  bool reported_ = false;
};

} // namespace gbssn1d
