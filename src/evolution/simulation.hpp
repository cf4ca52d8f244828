// One evolution: grid, initial data, right-hand side and the RK4 method of lines
// (Boost.Odeint), with output at fixed cadences in time.
#pragma once

#include "diagnostics/constraints.hpp"
#include "evolution/checkpoint.hpp"
#include "evolution/evolution_config.hpp"
#include "gbssn/rhs.hpp"
#include "io/output.hpp"
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
Schedule make_schedule(const EvolutionConfig& config, const Grid& grid);

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
  const Grid& grid() const { return layout_.grid(0); }
  const GbssnRhs& rhs() const { return rhs_; }
  State& state() { return levels_u_[0]; }
  const State& state() const { return levels_u_[0]; }
  double time() const { return t_; }
  const Schedule& schedule() const { return schedule_; }

  /// Diagnostics of the current state (evaluates the right-hand side once for d_t alpha).
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

  /// One RK4 step of size dt, then the chi floor (apply_chi_floor).
  void step(double dt);
  /// The same with d_t u at the current state already evaluated (RK4's first stage).
  void step(double dt, const State& dudt);

  /// The horizon radius h_AH that the horizon shift uses for the current state: found on it
  /// (substage mode) or the value held since the last search. nullopt: no horizon (beta_H = 0).
  std::optional<double> horizon_radius();
  /// beta_H on every point for the current state.
  std::vector<double> horizon_shift();
  /// Every marginal surface of the current state.
  HorizonSearch horizons() const;

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
  /// Say on stderr when the horizon appears or disappears.
  void report_horizon(const std::optional<MarginalSurface>& h);

  EvolutionConfig config_;
  /// The grid as the one-level case of the refinement hierarchy (mesh/hierarchy.hpp).
  mesh::MeshLayout layout_;
  GbssnRhs rhs_;
  GbssnRhs diagnostic_rhs_; ///< separate, so RHS evaluations of the evolution stay countable
  State dudt_;
  std::vector<State> levels_u_;                 ///< the state of each level (one: the single grid)
  State& u_ = levels_u_[0];                     ///< the state of level 0
  State u_prev_, dudt_prev_, dudt_now_, u_out_; ///< for output between steps (run)
  double t_ = 0.0;
  Schedule schedule_;
  mesh::MeshStepper stepper_; ///< RK4 (Odeint's arithmetic), with the chi floor after each step
  long step_ = 0;             ///< steps taken
  long k_series_ = 1, k_profiles_ = 1; ///< next output times k dt_series, k dt_profiles
  bool resumed_ = false;               ///< restore() was called: run() continues, no initial output
  std::uint64_t evaluations_before_rhs_ = 0; ///< RHS count before the current step's k1
  bool had_horizon_ = false;                 ///< for messages when the horizon appears/disappears
  bool reported_ = false;
};

} // namespace gbssn1d
