// validate()'s checks of the grid and the steps it takes (config/validate_steps.hpp).
#include "config/validate_steps.hpp"

#include "config/param_rules.hpp"

#include <fmt/format.h>

#include "evolution/levels.hpp"
#include "mesh/level_steps.hpp"

#include <algorithm>
#include <cmath>
#include <new>
#include <string>

namespace gbssn1d {

namespace {

/// The grid itself: its layout, with cells finite, increasing and resolvable.
mesh::MeshLayout checked_layout(const ResolvedParams& p) {
  // The grid itself: a map whose cells are not finite, increasing and resolvable in double
  // precision is refused here, before anything is written, naming the flag that shapes it (the
  // sinh grid's innermost width, the uniform grid's N).
  const std::string grid_flag = p.grid == RadialGrid::sinh    ? "--dr-inner"
                                : p.grid == RadialGrid::boxes ? "--levels"
                                                              : "--N";
  const std::string grid_value = p.grid == RadialGrid::sinh    ? num(p.dr_inner)
                                 : p.grid == RadialGrid::boxes ? std::to_string(p.levels())
                                                               : std::to_string(p.N);
  const mesh::MeshLayout layout = [&] {
    try {
      return make_layout(mesh_config(p));
    } catch (const std::bad_alloc&) {
      throw; // not the grid's fault: the machine's (cli reports it)
    } catch (const std::exception& e) {
      throw ParamError(grid_flag, grid_value, fmt::format("gives no usable grid: {}", e.what()));
    }
  }();
  const Grid& grid = layout.grid(layout.levels() - 1); // the finest
  for (std::size_t l = 0; l < layout.levels(); ++l) {
    const Grid& g = layout.grid(l);
    for (std::size_t i = 0; i < g.n_total(); ++i)
      if (!std::isfinite(g.r()[i]) || !std::isfinite(g.dr()[i]) || !std::isfinite(g.inv_dr_dx()[i])
          || !std::isfinite(g.d2_fx_coeff()[i]) || (i > 0 && !(g.r()[i] > g.r()[i - 1])))
        throw ParamError(grid_flag, grid_value,
                         fmt::format("gives a grid whose radii are not finite and increasing "
                                     "(cell {})",
                                     i));
  }
  if (!(grid.min_spacing() >= min_spacing_over_rmax * p.rmax))
    throw ParamError(grid_flag, grid_value,
                     fmt::format("gives a smallest cell of {:.3g}, below {:.0e} x rmax, which "
                                 "double precision cannot difference",
                                 grid.min_spacing(), min_spacing_over_rmax));
  return layout;
}

/// Z4c's constraint damping against the finest step dt_finest: alpha kappa1 (2 + kappa2) at
/// most (alpha <= 1), and the damping near the hole.
void validate_damping_step(const ResolvedParams& p, double dt_finest) {
  const double eta = p.eta();
  // Z4c's constraint damping, alpha kappa1 (2 + kappa2) at most (alpha <= 1), likewise; the flag
  // named is the one that makes it too fast (kappa2 where kappa1 alone, at 2 kappa1, would not)
  const double kappa1_value = p.kappa1();
  const bool kappa2_decides = p.kappa2 > 0.0 && 2.0 * kappa1_value * dt_finest <= eta_dt_max;
  if (const double rate = damping_rate(p); rate > eta && rate * dt_finest > eta_dt_max)
    throw ParamError(kappa2_decides ? "--kappa2" : "--kappa1",
                     kappa2_decides ? num(p.kappa2) : num(kappa1_value),
                     fmt::format("unstable with --cfl = {}: the damping rate kappa1 max(2, 2 + "
                                 "kappa2) = {} times dt = {} exceeds {} (RK4 limit of the "
                                 "constraint damping)",
                                 num(p.cfl), rate, dt_finest, eta_dt_max));
  // the damping near the hole: at most min(kappa1-hole, 0.2/dr) at a cell of width dr, whose
  // step is at most cfl dr (a single grid: the finest step everywhere), so that its rate times a
  // step stays below max(2, 2 + kappa2) min(kappa1-hole dt, 0.2 cfl) (boxes: 0.2 cfl)
  if (z4c_on(p)) {
    const double hole = p.kappa1_hole();
    const double resolved = Z4cParams::kappa1_dr_max * p.cfl;
    const double per_step =
        std::max(2.0, 2.0 + p.kappa2)
        * (p.grid == RadialGrid::boxes ? resolved : std::min(resolved, hole * dt_finest));
    if (hole > kappa1_value && per_step > eta_dt_max)
      throw ParamError(p.kappa2 > 0.0 ? "--kappa2" : "--kappa1-hole",
                       p.kappa2 > 0.0 ? num(p.kappa2) : num(hole),
                       fmt::format("unstable with --cfl = {}: the damping near the hole, at most "
                                   "min(kappa1-hole, 0.2/dr) max(2, 2 + kappa2), times a step can "
                                   "reach {} (above {}, RK4's limit); give --kappa1-hole 0 or a "
                                   "smaller --kappa2",
                                   num(p.cfl), per_step, eta_dt_max));
  }
}

} // namespace

/// The grid and the steps it takes: the grid (checked_layout), the horizon finder's tolerance,
/// the step's limits (checkpoints, step and row counts, the Gamma-driver damping, Z4c's).
void validate_grid_and_steps(const ResolvedParams& p) {
  const double eta = p.eta();
  const mesh::MeshLayout layout = checked_layout(p);
  const Grid& grid = layout.grid(layout.levels() - 1); // the finest
  if (p.ah_tol > ah_tol_over_spacing_max * grid.min_spacing())
    throw ParamError("--ah-tol", num(p.ah_tol),
                     fmt::format("must be at most {} x the smallest cell width ({:.3g}), so that "
                                 "the horizon is found well within one cell",
                                 ah_tol_over_spacing_max, grid.min_spacing()));
  // The Gamma-driver's damping term limits the step independently of the spacing.
  const double dt = mesh::hierarchy_dt(layout, mesh_config(p).stepping); // the whole step
  const double dt_finest = time_step(p.cfl, grid);
  if (p.checkpoint_every > 0.0 && p.checkpoint_every < dt)
    throw ParamError("--checkpoint-every", num(p.checkpoint_every),
                     fmt::format("is shorter than the time step dt = {:.6g} (checkpoints are "
                                 "written between steps; 0: only on a signal)",
                                 dt));
  // The step count (the step is the CFL step whatever the output cadence) and the row counts.
  const double n_steps = std::ceil(p.tmax / dt - 1e-9);
  // a tmax within 1e-9 steps of 0 takes no step (levels.cpp, the same count): the run would
  // end "completed at t = 0" under a header saying this tmax
  if (p.tmax > 0.0 && n_steps < 1.0)
    throw ParamError("--tmax", num(p.tmax),
                     fmt::format("below 1e-9 of the time step dt = {:.6g}: the run would take "
                                 "no step and end at t = 0 (--tmax 0 writes the initial data "
                                 "only)",
                                 dt));
  if (n_steps > steps_max)
    throw ParamError(
        "--tmax", num(p.tmax),
        fmt::format("would take {:.3g} steps of dt = --cfl x smallest cell = {} (at most {:.0e})",
                    n_steps, dt, steps_max));
  if (p.tmax / p.dt_series > rows_max)
    throw ParamError("--dt-series", num(p.dt_series),
                     fmt::format("would write {:.3g} rows to --tmax = {} (at most {:.0e})",
                                 p.tmax / p.dt_series, p.tmax, rows_max));
  if (p.tmax / p.dt_profiles > rows_max / 100.0)
    throw ParamError(
        "--dt-profiles", num(p.dt_profiles),
        fmt::format("would write {:.3g} profile blocks to --tmax = {} (at most {:.0e})",
                    p.tmax / p.dt_profiles, p.tmax, rows_max / 100.0));
  if (eta * dt_finest > eta_dt_max)
    throw ParamError("--cfl", num(p.cfl),
                     fmt::format("unstable with --eta = {}: eta dt = {} exceeds {} (RK4 limit of "
                                 "the Gamma-driver damping)",
                                 eta, eta * dt_finest, eta_dt_max));
  validate_damping_step(p, dt_finest);
  if (p.grid == RadialGrid::boxes && p.rah_variant == ShiftVariant::midstep_update)
    throw ParamError("--rah-variant", p.rah_variant.name(),
                     "is a single-grid study variant (its searches count one grid's RHS calls)");
}

} // namespace gbssn1d
