// Box-in-box mesh refinement in r: a hierarchy of nested cell-centred levels and the
// Berger-Oliger time stepping that advances it.
//
// Layout. Level l = 0 ... L-1 covers 0 <= r <= rmax / 2^l with the same N cells (uniform map),
// so each coarse cell holds exactly two fine cells and N alone refines every level. Each level
// is an ordinary Grid (ghost cells at the origin by parity, three outer ghost cells); the
// point-wise right-hand side runs on it unchanged and never learns that levels exist.
//
// The operations, each named once (the names follow AMReX's FillPatchTwoLevels and
// average_down; the methods follow Carpet and BAM):
//  - prolongation (coarse -> fine, `prolongate`): 6-point Lagrange interpolation in r, 5th
//    order, at the fine centres, which lie a quarter of a coarse cell either side of a coarse
//    centre; near r = 0 the coarse origin ghosts hold each variable's parity image, so the
//    stencil respects the symmetry as the single grid's derivatives do;
//  - the fine boundary zone (`fill_boundary_zone`): the outer ghost cells and a buffer of
//    `buffer_cells` interior cells of every fine level are refilled from the coarser level at
//    the end of each fine step, so that every level is valid everywhere between its steps.
//    Within a step the outer ghosts' own right-hand side is not the fine solution's; each of
//    RK4's later three stages carries that one stencil radius (3 cells) further in, so 3 ghosts
//    + 9 buffer cells = stages x radius = 12 cells are refilled and the rest of the level is
//    exact (Schnetter, Hawley & Hawke 2004, CQG 21, 1465: buffer zones);
//  - time interpolation of the coarse level to a fine step's start: `dense`, the cubic Hermite
//    interpolant of the coarse step's ends and their time derivatives (RK4's dense output,
//    error O(dt^4), consistent with the scheme), or `quadratic`, the parabola through three
//    coarse time levels (error O(dt^3): Carpet's and BAM's default second-order choice);
//  - restriction (fine -> coarse, `restrict_to_coarse`): at each coarse centre inside the
//    fine level's exact region, the 6-point Lagrange value of the fine solution at the
//    midpoint of two fine centres (weights (3, -25, 150, 150, -25, 3)/256, 6th order). A
//    two-cell average would be only 2nd order for the point values finite differences carry;
//  - Berger-Oliger subcycling (`BergerOliger::step`): level l steps with dt_l = cfl dr_l, two
//    fine steps per coarse step, coarse first, then the finer levels, then restriction; or,
//    for comparison, every level steps with the finest dt (no time interpolation is then
//    needed: each fine step starts where the coarse one did).
// A one-level hierarchy is the single grid: its RK4 step does exactly what Boost.Odeint's
// runge_kutta4 does, operation for operation.
#pragma once

#include "gbssn/state.hpp"
#include "grid/grid.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace gbssn1d {

/// Interior cells of a fine level refilled from the coarser level after each fine step: with
/// the 3 outer ghosts, RK4's 4 stages x the stencil radius 3.
inline constexpr std::size_t buffer_cells = 3 * Grid::n_ghost;

enum class TimeInterpolation {
  dense,     ///< cubic Hermite of the coarse step (RK4's dense output), O(dt^4)
  quadratic, ///< parabola through three coarse time levels, O(dt^3)
};

struct HierarchySpec {
  std::size_t levels = 1;
  std::size_t N = 32; ///< cells of every level
  double rmax = 128.0;
  bool subcycling = true; ///< false: every level steps with the finest dt
  TimeInterpolation time_interpolation = TimeInterpolation::dense;
};

/// The level grids of `spec`; throws std::invalid_argument naming what is wrong (odd N, too
/// few cells for the buffer and the prolongation stencil).
std::vector<Grid> make_levels(const HierarchySpec& spec);

/// Lagrange weights of the nodes `nodes` (distinct) for the value at `x`.
std::vector<double> lagrange_weights(const std::vector<double>& nodes, double x);

/// Fills the fine cells [i_begin, i_end) (indices of the fine grid: interior and outer ghost
/// cells, i_begin >= Grid::n_ghost) of every variable by 6-point Lagrange interpolation of the
/// coarse state, whose origin ghosts must hold the parity images. The fine grid's cells lie
/// inside coarse cells (two per coarse cell).
void prolongate(const Grid& coarse, const State& u_coarse, const Grid& fine, State& u_fine,
                std::size_t i_begin, std::size_t i_end);

/// The coarse cells whose restriction stencil lies in the fine level's exact region (interior
/// cells below its buffer): coarse interior cells 0 ... restricted_cells(N) - 1.
std::size_t restricted_cells(std::size_t N);

/// Overwrites the coarse interior cells 0 ... restricted_cells(N) - 1 with the fine solution
/// interpolated to their centres, and refreshes the coarse origin ghosts by parity.
void restrict_to_coarse(const Grid& fine, const State& u_fine, const Grid& coarse, State& u_coarse);

/// out = the cubic Hermite interpolant at t0 + theta dt (theta in [0, 1]) of u0, f0 = d_t u at
/// t0 and u1, f1 at t0 + dt: RK4's dense output, error O(dt^4).
void hermite_interpolate(const State& u0, const State& f0, const State& u1, const State& f1,
                         double dt, double theta, State& out);

/// The right-hand side of one level: d u / dt at time t (GbssnRhs has this signature).
using LevelRhs = std::function<void(const State& u, State& dudt, double t)>;
/// Called after every full step of a level (e.g. the chi floor).
using LevelHook = std::function<void(std::size_t level, State& u)>;

/// The Berger-Oliger time stepping of a hierarchy of levels.
class BergerOliger {
public:
  /// `u` holds every level's state (initial data), `rhs` one right-hand side per level.
  BergerOliger(HierarchySpec spec, double cfl, std::vector<State> u, std::vector<LevelRhs> rhs);

  std::size_t levels() const { return grids_.size(); }
  const Grid& grid(std::size_t l) const { return grids_[l]; }
  const State& state(std::size_t l) const { return levels_[l].u; }
  State& state(std::size_t l) { return levels_[l].u; }
  double time() const { return t_; }
  /// The step of level l (with subcycling dt_0 / 2^l, without it the finest dt on every level).
  double dt(std::size_t l) const;
  /// Right-hand-side evaluations of level l so far.
  std::uint64_t evaluations(std::size_t l) const { return levels_[l].evaluations; }

  LevelHook after_step;

  /// Advances every level by the coarsest level's step dt(0) (with subcycling; without it, by
  /// the finest dt).
  void step();

private:
  struct Level {
    State u;                        ///< the state at the level's current time
    State u_start, f_start;         ///< at the start of its last step, and d_t u there
    State u_end_rhs;                ///< d_t u at the end of its last step (dense)
    std::optional<State> u_earlier; ///< at the start of the step before (quadratic)
    double t_start = 0.0, t = 0.0;
    bool stepped = false; ///< has taken a step (u_start holds a time level)
    std::uint64_t evaluations = 0;
    State k2, k3, k4, tmp; ///< RK4 stages
  };

  /// One RK4 step of level l from its current time by dt (Odeint's runge_kutta4 arithmetic).
  void rk4(std::size_t l, double dt);
  /// Advances level l by one of its steps, then its finer levels, then restricts them into it.
  void advance(std::size_t l);
  /// The outer ghosts and buffer of level l (> 0) at time t from level l - 1.
  void fill_boundary_zone(std::size_t l, double t);
  /// Level l (a coarse level of a finer one) at time t within its last step.
  void coarse_at(std::size_t l, double t, State& out) const;
  void evaluate(std::size_t l, const State& u, State& dudt, double t);

  HierarchySpec spec_;
  double cfl_;
  std::vector<Grid> grids_;
  std::vector<Level> levels_;
  std::vector<LevelRhs> rhs_;
  double t_ = 0.0;
  State scratch_; ///< a coarse level in time, before prolongation
};

} // namespace gbssn1d
