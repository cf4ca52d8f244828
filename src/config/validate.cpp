#include "config/params.hpp"

#include "config/param_rules.hpp"

#include <fmt/format.h>

#include "core/text.hpp"
#include "evolution/levels.hpp"
#include "fd/stencils.hpp"
#include "mesh/level_steps.hpp"
#include <algorithm>
#include <cmath>
#include <limits>

#include <filesystem>
#include <new>
#include <string>
#include <unistd.h>

namespace gbssn1d {

namespace {

/// The refinement flags: refused on a single grid (they would mean nothing), checked on boxes.
void validate_refinement_flags(const Params& p) {
  if (p.grid != RadialGrid::boxes) {
    // the refinement flags mean nothing on a single grid: refused rather than ignored
    if (p.levels)
      throw ParamError("--levels", std::to_string(*p.levels), "needs --grid boxes");
    if (p.time_interp != Params{}.time_interp)
      throw ParamError("--time-interp", p.time_interp.name(), "needs --grid boxes");
    if (p.no_subcycling)
      throw ParamError("--no-subcycling", "needs --grid boxes");
    if (p.box_taper.value() != 0.0)
      throw ParamError("--box-taper", num(*p.box_taper), "needs --grid boxes");
    if (p.box_taper_from != Params{}.box_taper_from)
      throw ParamError("--box-taper-from", num(p.box_taper_from), "needs --grid boxes");
  } else {
    if (!p.levels)
      throw std::logic_error("validate() before resolve_defaults()");
    if (*p.levels < 1 || *p.levels > levels_max)
      throw ParamError("--levels", std::to_string(*p.levels),
                       fmt::format("must lie in 1 ... {}", levels_max));
    if (!(p.box_taper.value() >= 0.0 && *p.box_taper <= 0.5))
      throw ParamError("--box-taper", num(*p.box_taper),
                       "must lie in 0 ... 0.5 (a fraction of a box's cells)");
    if (!(p.box_taper_from >= 0.0 && std::isfinite(p.box_taper_from)))
      throw ParamError("--box-taper-from", num(p.box_taper_from),
                       "must be a finite radius >= 0 (in units of M)");
    if (*p.levels == 1) {
      // one box is a single grid: what only fine boxes have means nothing, refused as there
      const std::string single = "needs --levels 2 or more (with --levels 1 the boxes are a "
                                 "single grid, with no fine box)";
      if (p.time_interp != Params{}.time_interp)
        throw ParamError("--time-interp", p.time_interp.name(), single);
      if (p.no_subcycling)
        throw ParamError("--no-subcycling", single);
      if (p.box_taper.value() != 0.0)
        throw ParamError("--box-taper", num(*p.box_taper), single);
      if (p.box_taper_from != Params{}.box_taper_from)
        throw ParamError("--box-taper-from", num(p.box_taper_from), single);
      if (p.rah_variant == ShiftVariant::box_substage)
        throw ParamError("--rah-variant", p.rah_variant.name(), single);
    }
    if (*p.levels > 1 && p.N % 2 != 0)
      throw ParamError("--N", std::to_string(p.N),
                       "must be even with --grid boxes: each coarse cell holds two fine cells, "
                       "so that a fine box's edge is a coarse cell's face");
  }
}

/// The grid's flags: N, M, rmax, the kind of grid, its boxes and the differencing order, and
/// the initial data.
void validate_grid_flags(const Params& p) {
  if (p.N <= 0)
    throw ParamError("--N", std::to_string(p.N), "must be a positive integer");
  if (p.N < 16)
    throw ParamError("--N", std::to_string(p.N), "must be at least 16 cells");
  if (p.N > N_max)
    throw ParamError("--N", std::to_string(p.N),
                     fmt::format("needs about {:.0f} GB of memory; at most {} cells are accepted",
                                 8.0 * 9 * 6 * p.N / 1e9, N_max));
  require_positive("--M", p.M);
  require_positive("--rmax", p.rmax);
  // Everything scales with M; an outer boundary beyond 1e6 M only overflows the grid's map.
  if (p.rmax > rmax_over_M_max * p.M) {
    if (p.M < 1e-3 || p.M > 1e3)
      throw ParamError("--M", num(p.M),
                       fmt::format("gives --rmax / M = {:.3g}, above {:.0e}: lengths are in units "
                                   "of M, so keep M of order 1",
                                   p.rmax / p.M, rmax_over_M_max));
    throw ParamError(
        "--rmax", num(p.rmax),
        fmt::format("is beyond {:.0e} M, where no outer boundary is needed", rmax_over_M_max));
  }
  if (!p.grid.known())
    throw ParamError("--grid", p.grid.name(), "must be 'uniform', 'sinh' or 'boxes'");
  require_choice("--time-interp", p.time_interp);
  validate_refinement_flags(p);
  if (!fd::valid_order(p.fd_order))
    throw ParamError("--fd-order", std::to_string(p.fd_order), "must be 2, 4, 6 or 8");
  if (p.grid == RadialGrid::boxes && p.levels && *p.levels > 1 && !mesh::boxes_order(p.fd_order))
    throw ParamError("--fd-order", std::to_string(p.fd_order),
                     "must be 2, 4 or 6 with --grid boxes: the boxes' prolongation and "
                     "restriction are 6th order");
  if (p.grid == RadialGrid::boxes && p.levels && *p.levels > 1 && mesh::boxes_order(p.fd_order)
      && p.N < static_cast<int>(mesh::min_cells(p.fd_order)))
    throw ParamError("--N", std::to_string(p.N),
                     fmt::format("must be at least {} with --grid boxes at --fd-order {} (a "
                                 "fine box's buffer and the transfer stencils)",
                                 mesh::min_cells(p.fd_order), p.fd_order));
  if (p.grid == RadialGrid::sinh) {
    require_positive("--dr-inner", p.dr_inner);
    const double needed = p.dr_inner * sinh_reference_N;
    if (!(p.rmax > needed))
      throw ParamError("--rmax", num(p.rmax),
                       fmt::format("too small for the grid: the sinh map with --dr-inner = {} "
                                   "(the innermost width at N = {}) needs --rmax > {}",
                                   p.dr_inner, sinh_reference_N, needed));
  }
  if (!(p.rmax >= 4.0 * p.M))
    throw ParamError("--rmax", num(p.rmax),
                     fmt::format("too small for the grid: the outer boundary must lie outside "
                                 "the black hole, --rmax >= 4 M = {}",
                                 4.0 * p.M));
  require_choice("--id", p.id);
  if (!p.lapse0.known())
    throw ParamError("--lapse0", p.lapse0.name(), "must be 'one' or 'precollapsed'");
}

/// The gauge, dissipation, floor, times, output cadences and norm windows.
void validate_evolution_numbers(const Params& p) {
  if (!p.eta || !p.norm_rmax)
    throw std::logic_error("validate() before resolve_defaults()");
  const double eta = *p.eta, norm_rmax = *p.norm_rmax;
  require_finite("--eta", eta);
  if (eta < 0.0)
    throw ParamError("--eta", num(eta), "must be >= 0");
  const double cfl = p.cfl;
  require_positive("--cfl", cfl);
  if (cfl < cfl_min)
    throw ParamError("--cfl", num(cfl),
                     fmt::format("below {}: such steps only accumulate round-off", cfl_min));
  if (cfl > cfl_max)
    throw ParamError("--cfl", num(cfl),
                     fmt::format("outside the stable range (0, {}] of RK4 with 4th-order "
                                 "differences",
                                 cfl_max));
  require_finite("--ko-sigma", p.ko_sigma);
  if (p.ko_sigma < 0.0 || p.ko_sigma > 1.0)
    throw ParamError("--ko-sigma", num(p.ko_sigma), "must lie in [0, 1]");
  require_finite("--chi-floor", p.chi_floor);
  if (p.chi_floor < 0.0 || p.chi_floor >= 1.0)
    throw ParamError("--chi-floor", num(p.chi_floor), "must lie in [0, 1)");

  require_finite("--tmax", p.tmax);
  if (p.tmax < 0.0)
    throw ParamError("--tmax", num(p.tmax), "must be >= 0");
  require_positive("--dt-series", p.dt_series);
  require_positive("--dt-profiles", p.dt_profiles);
  require_finite("--checkpoint-every", p.checkpoint_every);
  if (p.checkpoint_every < 0.0)
    throw ParamError("--checkpoint-every", num(p.checkpoint_every), "must be >= 0 (0: off)");

  require_finite("--norm-rmin", p.norm_rmin);
  require_finite("--norm-rmax", norm_rmax);
  if (p.norm_rmin < 0.0)
    throw ParamError("--norm-rmin", num(p.norm_rmin), "must be >= 0");
  if (!(norm_rmax > p.norm_rmin))
    throw ParamError("--norm-rmax", num(norm_rmax), "must be > --norm-rmin");
  if (norm_rmax > p.rmax)
    throw ParamError("--norm-rmax", num(norm_rmax), "must not exceed --rmax");

  require_positive("--norm-Rmin", p.norm_Rmin);
  require_finite("--norm-Rmax", p.norm_Rmax);
  if (!(p.norm_Rmax > p.norm_Rmin))
    throw ParamError("--norm-Rmax", num(p.norm_Rmax), "must be > --norm-Rmin");
  require_positive("--norm-Rint", p.norm_Rint);
}

/// The horizon-adjusting shift and its horizon searches.
void validate_horizon_shift(const Params& p) {
  require_finite("--rahA", p.rahA);
  if (p.rahA < 0.0)
    throw ParamError("--rahA", num(p.rahA),
                     "must be >= 0: beta_H = f A (h_AH - h) s^r with A < 0 drives the horizon "
                     "away from --rah0, not towards it");
  require_positive("--rah0", p.rah0);
  require_positive("--rah-width", p.rah_width);
  if (shift_on(p) && !(p.rah0 < p.rmax))
    throw ParamError("--rah0", num(p.rah0),
                     fmt::format("must be below --rmax = {}: the horizon is moved to a radius on "
                                 "the grid",
                                 num(p.rmax)));
  if (p.rah_rcut) {
    require_positive("--rah-rcut", *p.rah_rcut);
    // the shift must act at the horizon: the taper begins (at rcut/2) outside twice its radius
    if (shift_on(p) && !(*p.rah_rcut >= 4.0 * std::max(p.rah0, p.M)))
      throw ParamError("--rah-rcut", num(*p.rah_rcut),
                       fmt::format("must be at least 4 max(rah0, M) = {} (--rah0 {}): beta_H "
                                   "would be cut near the horizon it moves (its default is "
                                   "rmax/2: a larger --rmax, or a smaller --rah0)",
                                   num(4.0 * std::max(p.rah0, p.M)), num(p.rah0)));
  }
  require_choice("--rah-profile", p.rah_profile);
  require_choice("--rah-normal", p.rah_normal);
  if (p.rah_taper)
    require_choice("--rah-taper", *p.rah_taper);
  require_positive("--rah-chi-smooth", p.rah_chi_smooth);
  require_finite("--rah-ramp", p.rah_ramp);
  if (p.rah_ramp < 0.0)
    throw ParamError("--rah-ramp", num(p.rah_ramp), "must be >= 0 (0: no ramp)");
  require_choice("--driver-advection", p.driver_advection);
  require_choice("--delta-advection", p.delta_advection);
}

/// The formulation and its differencing: the volume choice where it is offered, Z4c's damping.
void validate_formulation(const Params& p) {
  require_choice("--upwind", p.upwind);
  require_choice("--formulation", p.formulation);
  require_choice("--gbssn-volume", p.gbssn_volume);
  if (z4c_on(p) && p.gbssn_volume == Volume::eulerian)
    throw ParamError("--gbssn-volume", p.gbssn_volume.name(),
                     "is offered with --formulation bssn: Z4c here takes the Lagrangian choice");
  if (p.gbssn_volume == Volume::eulerian && (p.fd_order != 4 || p.upwind != fd::Upwind::lopsided))
    throw ParamError("--gbssn-volume", p.gbssn_volume.name(),
                     fmt::format("is offered with --fd-order 4 and --upwind lopsided only (given "
                                 "{} and {})",
                                 p.fd_order, p.upwind.name()));
  const double kappa1 = p.kappa1.value_or(kappa1_rule(p));
  require_finite("--kappa1", kappa1);
  if (kappa1 < 0.0)
    throw ParamError("--kappa1", num(kappa1),
                     "must be >= 0 (a negative kappa1 makes the constraints grow)");
  if (p.kappa1_hole) {
    require_finite("--kappa1-hole", *p.kappa1_hole);
    if (*p.kappa1_hole != 0.0 && !(*p.kappa1_hole >= kappa1))
      throw ParamError("--kappa1-hole", num(*p.kappa1_hole),
                       fmt::format("must be 0 (off) or at least --kappa1 = {} (it raises kappa1 "
                                   "near the hole)",
                                   num(kappa1)));
  }
  require_finite("--kappa2", p.kappa2);
  if (!(p.kappa2 > -1.0))
    throw ParamError("--kappa2", num(p.kappa2),
                     "must be > -1 (the damping of Theta in Z4c's constraint subsystem needs it)");
}

/// The horizon shift's study variants where they are built (BSSN, the lopsided pair, 4th
/// order), and the finder's tolerance.
void validate_study_variants(const Params& p) {
  if (z4c_on(p) && shift_on(p) && p.rah_variant != ShiftVariant::consistent
      && p.rah_variant != ShiftVariant::midstep_update
      && p.rah_variant != ShiftVariant::box_substage)
    throw ParamError("--formulation", p.formulation.name(),
                     fmt::format("--rah-variant {} is a study variant of the BSSN equations; with "
                                 "z4c take consistent, midstep-update or box-substage",
                                 p.rah_variant.name()));
  if (p.upwind == fd::Upwind::biased && shift_on(p) && p.rah_variant != ShiftVariant::consistent
      && p.rah_variant != ShiftVariant::midstep_update
      && p.rah_variant != ShiftVariant::box_substage)
    throw ParamError("--upwind", p.upwind.name(),
                     fmt::format("is offered with --rah-variant consistent, midstep-update and "
                                 "box-substage; --rah-variant {} is a study variant, built with "
                                 "the lopsided stencil only",
                                 p.rah_variant.name()));
  if (p.fd_order != 4 && shift_on(p) && p.rah_variant != ShiftVariant::consistent
      && p.rah_variant != ShiftVariant::midstep_update
      && p.rah_variant != ShiftVariant::box_substage)
    throw ParamError("--fd-order", std::to_string(p.fd_order),
                     fmt::format("is offered with --rah-variant consistent, midstep-update and "
                                 "box-substage; --rah-variant {} is a study variant of the "
                                 "published study's equations, built at --fd-order 4 only",
                                 p.rah_variant.name()));
  require_positive("--ah-tol", p.ah_tol);
  require_choice("--rah-variant", p.rah_variant);
}

/// When the horizon is searched for: --ah-every's forms, the fixed interval in time (which
/// replaces --ah-every's schedule and needs searches), the window, and the study variants that
/// change where the searches happen.
void validate_search_schedule(const Params& p) {
  if (!p.ah_every.valid())
    throw ParamError("--ah-every", printable(p.ah_every.name()),
                     "must be 'substage', 'extrapolated', 'step' or a whole number of steps "
                     ">= 1");
  if (p.ah_interval) {
    require_positive("--ah-interval", *p.ah_interval);
    if (p.ah_every != SearchEvery::substage)
      throw ParamError("--ah-interval", num(*p.ah_interval),
                       fmt::format("sets when the horizon is searched for, as --ah-every {} "
                                   "does: give one of the two",
                                   p.ah_every.name()));
    if (uses_hAH_file(p))
      throw ParamError("--ah-interval", num(*p.ah_interval),
                       "schedules horizon searches, and with --rah-hAH-file h_AH(t) comes from "
                       "the file (no searches): give one of the two");
  }
  require_finite("--ah-tmin", p.ah_tmin);
  if (p.ah_tmin < 0.0)
    throw ParamError("--ah-tmin", num(p.ah_tmin), "must be >= 0");
  if (p.ah_tmax) {
    require_finite("--ah-tmax", *p.ah_tmax);
    if (*p.ah_tmax < p.ah_tmin)
      throw ParamError("--ah-tmax", num(*p.ah_tmax),
                       "must be >= --ah-tmin (leave it out for no limit)");
  }
  if (p.rah_variant == ShiftVariant::box_substage
      && (p.grid != RadialGrid::boxes || p.ah_every != SearchEvery::substage || p.ah_interval))
    throw ParamError("--rah-variant", p.rah_variant.name(),
                     "needs --grid boxes and --ah-every substage (no --ah-interval)");
  if (p.rah_variant == ShiftVariant::midstep_update
      && (p.ah_every == SearchEvery::substage || p.ah_every == SearchEvery::extrapolated))
    throw ParamError("--rah-variant", p.rah_variant.name(),
                     "needs searches every n steps (--ah-every step or a number)");
}

/// The grid itself: its layout, with cells finite, increasing and resolvable.
mesh::MeshLayout checked_layout(const Params& p) {
  // The grid itself: a map whose cells are not finite, increasing and resolvable in double
  // precision is refused here, before anything is written, naming the flag that shapes it (the
  // sinh grid's innermost width, the uniform grid's N).
  const std::string grid_flag = p.grid == RadialGrid::sinh    ? "--dr-inner"
                                : p.grid == RadialGrid::boxes ? "--levels"
                                                              : "--N";
  const std::string grid_value = p.grid == RadialGrid::sinh ? num(p.dr_inner)
                                 : p.grid == RadialGrid::boxes
                                     ? std::to_string(p.levels.value_or(1))
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
void validate_damping_step(const Params& p, double dt_finest) {
  const double eta = p.eta.value();
  // Z4c's constraint damping, alpha kappa1 (2 + kappa2) at most (alpha <= 1), likewise; the flag
  // named is the one that makes it too fast (kappa2 where kappa1 alone, at 2 kappa1, would not)
  const double kappa1_value = p.kappa1.value_or(kappa1_rule(p));
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
    const double hole = p.kappa1_hole.value_or(kappa1_hole_rule(p));
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

/// The grid and the steps it takes: the grid (checked_layout), the horizon finder's tolerance,
/// the step's limits (checkpoints, step and row counts, the Gamma-driver damping, Z4c's).
void validate_grid_and_steps(const Params& p) {
  const double eta = p.eta.value();
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

} // namespace

void validate(const Params& p) {
  validate_grid_flags(p);
  validate_evolution_numbers(p);
  validate_horizon_shift(p);
  validate_formulation(p);
  validate_study_variants(p);
  validate_search_schedule(p);
  validate_grid_and_steps(p);
}

} // namespace gbssn1d
