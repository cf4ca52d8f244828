#include "config/params.hpp"
#include "config/validate_steps.hpp"
#include "mesh/layout.hpp"

#include "config/param_rules.hpp"

#include <fmt/format.h>

#include "core/text.hpp"
#include "fd/stencils.hpp"
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
