// Box-in-box mesh refinement: a hierarchy of levels and its Berger-Oliger stepper.
//
// Design note. Everything that knows about refinement lives in src/mesh/; the point-wise RHS
// (GbssnRhs) and a level's Grid do not: each level is an ordinary Grid with its own GbssnRhs,
// and the stepper sees a level only through a State and a right-hand-side functor
// void(const State&, State&, double t). One level is the single grid (any map), stepped by the
// same RK4 as Boost.Odeint's runge_kutta4, bit for bit (tests/mesh/test_hierarchy.cpp; the
// tableau's zero terms left out, which changes no finite sum).
//
//  - Layout (layout.hpp): level l covers 0 <= r <= rmax/2^l with N cells, cell-centred, so that
//    each coarse cell holds two fine cells; origin ghosts by parity, as on the single grid.
//  - Prolongation (transfer.hpp): 6-point Lagrange interpolation in r from coarse centres to the
//    fine centres at +-1/4 coarse spacing, 6th order (exact for degree 5), every variable
//    through the registry with its parity at r = 0 (Carpet's and BAM's 5th-order operators:
//    Schnetter, Hawley & Hawke 2004, CQG 21:1465; Bruegmann et al. 2008, PRD 77:024027).
//  - Restriction (transfer.hpp): 6-point centred Lagrange interpolation to the coarse centre,
//    the midpoint of two fine centres, 6th order; the 2-point average would be 2nd order for
//    point values. Applied after every pair of fine steps (or every fine step without
//    subcycling) to the coarse cells whose stencil lies in the fine level's valid region (the
//    fine interior less the buffer). Berger & Oliger 1984 (JCP 53:484), Berger & Colella 1989.
//  - Time (time_interpolation.hpp), selectable:
//      rk_stages: the fine ghosts get, at every RK4 stage, the stage values of the fine step
//        reconstructed from the coarse step's four stage derivatives (McCorquodale & Colella
//        2011, CAMCoS 6:1; Mongwane 2015, GRG 47:60): consistent, 4th order, no buffer;
//      dense_output: every stage gets the coarse step's RK4 dense output at the stage time
//        (accurate values, inconsistent with the stages);
//      quadratic: ghosts and a buffer of stages x stencil radius points (12 at 4th order,
//        16 at 6th; Schnetter, Hawley & Hawke 2004) are filled once per fine step by quadratic
//        interpolation in time through three coarse time levels (Carpet's and BAM's default),
//        2nd/3rd order in time.
//  - Stepper: Berger-Oliger recursion (Berger & Oliger 1984): level l takes one RK4 step of dt_l
//    (= cfl dr_l), then level l+1 two steps of dt_l / 2, then restriction l+1 -> l; or, without
//    subcycling, every level steps with the finest dt. The coarsest level's outer ghosts keep
//    GbssnRhs's Sommerfeld condition; every finer level's outer ghosts come from its parent
//    (the RHS the functor writes there is ignored). Kreiss-Oliger dissipation and upwinding are
//    those of GbssnRhs on each level, scaled with that level's spacing. A parent need not evolve
//    the cells under its child that restriction overwrites and nothing reads before
//    (first_needed_cell; the evolution skips them, every result bit for bit the same).
//  - Start: initialise() restricts from the finest level down and fills every fine boundary;
//    for `quadratic` it also makes each parent's level at t - dt_l by one RK4 step backwards
//    (like Carpet's init_3_timelevels), since a linear first step leaves an O(dt^2) error that
//    focuses at r = 0 and stops convergence. Every step() ends with each fine level's ghosts
//    and buffer prolongated from its parent, so each State is complete between steps.
//
// Measured (tests/mesh/test_hierarchy.cpp; flat-space lapse pulse crossing the refinement
// boundaries, RMS over 15 times of all levels and variables, cfl 0.25, N = 32 ... 1024):
// rk_stages converges at 4.0 (pair orders -> 4.01) with 2 and 3 levels, with and without
// subcycling; dense_output at 4 with 2 levels but falls to about 2 with 3 levels at high
// resolution; quadratic at 4-5 while the space error dominates, then, subcycled with 3 levels,
// 3.8 -> 2.8 (2.2 at cfl 0.5): the time interpolation limits it. RHS evaluations per coarse
// step: 4 x 2^l on level l with subcycling, 4 per level per (finest) step without.
//
// State a checkpoint of the hierarchy needs: every level's State and time; for `quadratic` the
// stored coarse time levels of every level but the finest (history()); the rk_stages and
// dense_output choices need nothing beyond the states (a coarse step's stages are used within
// that step only).
#pragma once

#include "gbssn/state.hpp"
#include "mesh/layout.hpp"
#include "mesh/stepper_options.hpp"
#include "mesh/time_interpolation_kind.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <limits>
#include <vector>

namespace gbssn1d::mesh {

/// One level's right-hand side d u / dt (GbssnRhs has this signature).
using LevelRhs = std::function<void(const State&, State&, double)>;

class MeshStepper {
public:
  /// One RHS per level, in level order (`layout` must outlive the stepper). Throws
  /// std::invalid_argument on a count mismatch.
  MeshStepper(const MeshLayout& layout, std::vector<LevelRhs> rhs, StepperOptions options);

  const MeshLayout& layout() const { return *layout_; }
  const StepperOptions& options() const { return options_; }

  /// The step of the whole hierarchy, level 0's step: with subcycling min(cfl dr_0, dt_max),
  /// rounded down to dt_finest x 2^k (each level l then takes steps(l) steps of dt / steps(l));
  /// without subcycling cfl dr_{L-1} (every level takes one step of it).
  double dt() const;
  /// Steps level l takes per step of the hierarchy (1 on level 0; a power of two).
  long steps(std::size_t level) const { return steps_.at(level); }
  /// The step level l takes when the hierarchy steps by `dt`: dt / steps(l).
  double level_dt(std::size_t level, double dt) const;

  /// Makes the levels consistent at time t before the first step: restriction from the finest
  /// level down, then each finer level's ghosts (and buffer) from its parent; forgets the
  /// stored time levels (for `quadratic`, stores each parent's level at t - dt_l, made by one
  /// RK4 step backwards: 4 RHS evaluations per level but the finest).
  void initialise(std::vector<State>& u, double t);
  /// Advances every level from t to t + dt (dt may be shorter than dt(), e.g. a last step);
  /// afterwards every level's outer ghosts and buffer hold the prolongation of its parent.
  void step(std::vector<State>& u, double t, double dt);
  /// The same with level 0's d_t u at t already evaluated (RK4's first stage, e.g. kept by the
  /// caller for dense output): three RHS evaluations on level 0 instead of four.
  void step(std::vector<State>& u, double t, double dt, const State& k1);
  void step(std::vector<State>& u, double t, double dt, const State* k1);
  /// Fills the outer ghosts of levels 1 ... L-1 at time t from their parents by prolongation
  /// alone (after initialise or a completed step, when all levels are at t).
  void fill_ghosts(std::vector<State>& u) const;
  /// Level l's outermost taper_cells interior cells blended towards its parent's prolongation
  /// (both at the same time): u += w (P u_parent - u), w = s^2 (3 - 2 s), s = (j - j0 + 1)/k
  /// for the k = taper_cells cells j0 ... N - 1 (StepperOptions::taper_cells).
  void taper_from_parent(std::vector<State>& u, std::size_t l);

  /// Called after every step of a level (e.g. a chi floor).
  std::function<void(std::size_t level, State& u)> after_step;
  /// Called within every forward RK4 step of a level, before its update and after_step: the
  /// level, the step's start t0 and size dt, the state u0 at t0 and the four stage derivatives.
  /// With dense_output_weights they give the level's solution at any t in [t0, t0 + dt] to the
  /// order of its own step (output between the steps of the hierarchy).
  std::function<void(std::size_t level, double t0, double dt, const State& u0,
                     const std::array<const State*, 4>& k)>
      on_level_step;

  /// RHS evaluations of level l so far.
  std::uint64_t evaluations(std::size_t level) const { return evaluations_.at(level); }
  void set_evaluations(std::size_t level, std::uint64_t n) {
    evaluations_.at(level) = n;
  } ///< resume
  /// Fine interior cells (next to the outer ghosts) refilled from the parent every fine step.
  std::size_t buffer() const {
    return options_.time == TimeInterpolation::quadratic ? buffer_cells(layout_->fd_order()) : 0;
  }
  /// The coarse cells [0, restricted_cells()) of a parent overwritten by restriction.
  long restricted_cells() const;
  /// The first interior cell of level l whose right-hand side any result depends on (0 for the
  /// finest level): the level's own evolution may skip the cells below it (GbssnRhs::
  /// set_first_cell). A parent's cells below its child's extent are overwritten by restriction
  /// after each of its steps; before that, the child's boundary fills read the parent's stages
  /// from about N/2 - 3 on, and the diagnostics of the parent's uncovered cells (on dense
  /// output, between steps) a little further down. A stage value is exact from R cells (the
  /// stencil radius) further in than the one before, the first stage from the first evolved
  /// cell on, so the last stage and the new state are exact from 3R cells above it: the first
  /// cell is the lowest cell read minus 3R. (The taper and the last fill of the ghosts read
  /// the parent after restriction.)
  std::size_t first_needed_cell(std::size_t l) const;
  /// Level l's RK4 stage sums start at interior cell `cell` (0: every cell, as by default); the
  /// cells below keep stale stage values and the state its value from before the step. For a
  /// level whose right-hand side skips the same cells (GbssnRhs::set_first_cell), at most
  /// first_needed_cell(l): the values there are read by no exact cell's stencil, and
  /// restriction overwrites them.
  void set_first_cell(std::size_t l, std::size_t cell);

  /// A stored time level of a parent level (for the quadratic choice).
  struct TimeLevel {
    double t;
    State u;
  };
  /// Level l's stored time levels, oldest first (at most two; empty for the finest level and
  /// for the stage choices).
  const std::vector<TimeLevel>& history(std::size_t level) const {
    return levels_.at(level).history;
  }
  void set_history(std::size_t level, std::vector<TimeLevel> h) {
    levels_.at(level).history = std::move(h);
  }

private:
  struct Level {
    State u0, tmp, scratch;         ///< step start, stage input, coarse combination scratch
    std::array<State, 4> k;         ///< stage derivatives of the current step
    double t0 = 0.0, dt = 0.0;      ///< the current (or last) step
    std::vector<TimeLevel> history; ///< quadratic: the states before the last steps
    /// The stage fills' time weights (StageWeights) of the last two steps, with the step's
    /// place theta in its parent's step, their ratio and the parent's step they were made from:
    /// a subcycled box alternates between theta = 0 and 1/2, so they are made again only when
    /// one of those changes (a shorter last step).
    struct StageWeightsMemo {
      double theta = std::numeric_limits<double>::quiet_NaN(), ratio = theta, dt = theta;
      std::array<std::array<double, 5>, 4> weights{};
    };
    std::array<StageWeightsMemo, 2> weights_memo;
    std::size_t weights_memo_next = 0; ///< the entry to replace next
  };
  /// Every level's scratch states sized as its state `u[l]` (its formulation's variables).
  void fit_scratch(const std::vector<State>& u);
  void advance(std::vector<State>& u, std::size_t l, double t, double dt,
               const State* k1 = nullptr);
  /// RK4 step of level l; `fill(stage, input)` before each RHS evaluation; `given_k1`: the
  /// first stage, if already evaluated; `start`: if given, receives the state at t (the new
  /// state is summed into a scratch array and the arrays are exchanged, instead of a copy).
  void rk4(std::size_t l, State& u, double t, double dt,
           const std::function<void(int, State&)>& fill, const State* given_k1 = nullptr,
           State* start = nullptr);
  /// Fine level l's points [j_begin, N + n_ghost) from the parent's arrays `arrays` combined with
  /// `weights` (one per array; as many as arrays).
  void fill_from_parent(std::size_t l, State& fine, std::initializer_list<const State*> arrays,
                        std::initializer_list<double> weights, long j_begin) const;
  void fill_quadratic(std::vector<State>& u, std::size_t l, double t) const;
  void restrict_level(std::vector<State>& u, std::size_t fine_level) const;

  const MeshLayout* layout_;
  std::vector<LevelRhs> rhs_;
  StepperOptions options_;
  mutable std::vector<Level> levels_;
  std::vector<std::uint64_t> evaluations_;
  std::vector<long> steps_;             ///< steps of level l per hierarchy step
  std::vector<std::size_t> first_cell_; ///< of each level's stage sums (set_first_cell)
};

} // namespace gbssn1d::mesh
