// One evolution: grid (a single grid, or box-in-box levels), initial data, right-hand side and
// the RK4 method of lines, with output at fixed cadences in time. The levels are stepped by
// mesh::MeshStepper (a single grid is its one-level case); output and norms see their
// composite (mesh/composite.hpp), the horizon finder the finest level that holds the horizon.
#pragma once

#include "diagnostics/constraints.hpp"
#include "evolution/checkpoint.hpp"
#include "evolution/evolution_config.hpp"
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

/// Thrown when the state stops being finite, or chi or alpha leaves its physical range
/// (Simulation::check_finite); says what, where and when.
class NonFiniteError : public std::runtime_error {
public:
  NonFiniteError(double t, double r, const std::string& var);
  /// A finite value outside its range: "`var` = value at r, t: `why`".
  NonFiniteError(double t, double r, const std::string& var, double value, const std::string& why);
  double t, r;
  std::string var;
};

/// Thrown between steps after SIGTERM or SIGINT (core/stop_signal.hpp), once the output due
/// up to the current step is written.
class Interrupted : public std::runtime_error {
public:
  Interrupted(int signal, double t);
  int signal;
  double t;
};

/// The time stepping of a run: dt = cfl x smallest spacing, whatever the output cadence; the
/// last step is shortened to end exactly at tmax. Output between steps is interpolated
/// (Simulation::run).
struct Schedule {
  double dt;
  long n_steps;
};
Schedule make_schedule(const EvolutionConfig& config, double dt);

/// The levels of `config`'s grid: one level on its map, or --levels boxes.
mesh::MeshLayout make_layout(const EvolutionConfig& config);
/// The stepper's options of `config`.
mesh::StepperOptions stepper_options(const EvolutionConfig& config);

/// out = the cubic Hermite interpolant at t0 + theta dt (theta in [0, 1]) of u0, f0 = d_t u at
/// t0 and u1, f1 at t0 + dt: RK4's dense output, error O(dt^4).
void hermite_interpolate(const State& u0, const State& f0, const State& u1, const State& f1,
                         double dt, double theta, State& out);

/// Raises chi to at least chi_floor on every point (0: nothing). On wormhole data the innermost
/// cell's chi (about 1e-7 on the default grid) passes through zero while the lapse collapses,
/// and the (d_r chi)^2 / chi terms of (R1)-(R4) then diverge; docs/horizon-shift-study.md Sec. 4.
void apply_chi_floor(State& u, const Grid& grid, double chi_floor);

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
  /// gets the cubic Hermite interpolant of u_n, u_n+1 and their d_t u (RK4's dense output,
  /// error O(dt^4), the order of the scheme); on a step it gets the state itself. Throws
  /// NonFiniteError after writing the last finite output, leaving the files complete.
  void run(Output* out);

  /// Called after every series output (and at t = 0), e.g. to sample the state for a
  /// convergence study.
  std::function<void(Simulation&)> on_series;

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
  /// number of steps to tmax and the smallest cell width dr-min.
  std::string run_facts() const;

  /// One step of size dt of every level (RK4, then the chi floor, apply_chi_floor).
  void step(double dt);
  /// The same with level 0's d_t u at the current state already evaluated (RK4's first stage).
  void step(double dt, const State& dudt);

  /// The horizon radius h_AH that the horizon shift uses for the current state: found on it
  /// (substage mode) or the value held since the last search. nullopt: no horizon (beta_H = 0).
  std::optional<double> horizon_radius();
  /// beta_H on every point for the current state.
  std::vector<double> horizon_shift();
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
  /// Runs a horizon search; a HorizonFinderError gets the current time added.
  template <class Search>
  auto with_time(Search search) const;
  /// Held mode: search for the horizon and hold its radius for the RHS.
  void update_held_horizon();
  /// Boxes, searches every substage (the default): the one h_AH(t) that every box's RHS uses,
  /// from the radii found on the box holding the horizon at the last (up to) four steps of the
  /// hierarchy, extrapolated to each stage's time by their Lagrange polynomial (cubic: error
  /// O(dt^4), the order of the scheme). Berger-Oliger steps a coarse box before the fine box
  /// holding the horizon reaches that time, so no box can search at the others' stages.
  bool extrapolated_horizon() const;
  std::optional<double> horizon_radius_at(double t) const;
  /// After every step of the hierarchy (and at the start): a search on the box holding the
  /// horizon, for horizon_radius_at.
  void search_at_step();
  /// Whether run() initialises the stepper again once h_AH is known (quadratic time
  /// interpolation with the horizon shift: its earlier time levels need beta_H).
  bool reinitialises() const;
  /// The RHS's substage search of `level` (see extrapolated_horizon, and box_substage).
  std::optional<double> locate(std::size_t level, const State& u, const Grid& grid, double seed,
                               double t);
  /// Output between the steps of several levels: each level's state at the output times inside
  /// the coming step, from the RK4 dense output of that level's own (sub)step (mesh::
  /// MeshStepper::on_level_step), so that a fine level is interpolated over its own dt.
  struct PendingOutput {
    double t;
    std::vector<State> u;     ///< one per level
    std::vector<bool> filled; ///< per level
  };
  std::vector<PendingOutput> pending_;
  /// Collects the output times in (t0, t1) for the coming step.
  void prepare_pending(double t0, double t1);
  void fill_pending(std::size_t level, double t0, double dt, const State& u0,
                    const std::array<const State*, 4>& k);
  /// Say on stderr when the horizon appears or disappears.
  void report_horizon(const std::optional<MarginalSurface>& h);

  EvolutionConfig config_;
  mesh::MeshLayout layout_;   ///< the levels (one: the single grid)
  mesh::Composite composite_; ///< their composite, for output and norms
  std::vector<GbssnRhs> rhs_; ///< one per level
  /// per level, separate, so RHS evaluations of the evolution stay countable; it never
  /// searches for the horizon of its own (diagnostics set its h_AH)
  std::vector<GbssnRhs> diagnostic_rhs_;
  /// The horizon radius every level's horizon shift uses: found on horizon_level()'s state
  /// (substage searches there, or the held searches); the other levels read it.
  std::optional<double> shared_h_AH_;
  std::vector<std::array<double, 2>> h_AH_history_; ///< boxes: (t, h_AH) of the last searches
  std::vector<State> dudt_;                         ///< per level: diagnostic scratch
  std::vector<State> levels_u_;                     ///< the state of each level
  State dudt_now_; ///< level 0's d_t u at the current state: the next step's first RK4 stage
  /// a single grid's output between steps (boxes use each level's dense output, pending_)
  State u_prev_, dudt_prev_, u_out_;
  State u_composite_;                            ///< the composite state, for profiles
  std::vector<std::size_t> composite_levels_;    ///< the level of each composite cell
  std::optional<double> shared_h_AH_before_rhs_; ///< for checkpoints (as h_AH_before_rhs)
  double t_ = 0.0;
  Schedule schedule_;
  mesh::MeshStepper stepper_; ///< RK4 (Odeint's arithmetic), with the chi floor after each step
  long step_ = 0;             ///< steps taken
  long k_series_ = 1, k_profiles_ = 1; ///< next output times k dt_series, k dt_profiles
  bool resumed_ = false;               ///< restore() was called: run() continues, no initial output
  std::uint64_t evaluations_before_rhs_ = 0;       ///< RHS count before the current step's k1
  std::vector<std::uint64_t> initial_evaluations_; ///< per level, before the first step
  bool had_horizon_ = false; ///< for messages when the horizon appears/disappears
  bool reported_ = false;
};

} // namespace gbssn1d
