#include "config/flag_table.hpp"
#include "config/params.hpp"
#include "config/validate_steps.hpp"
#include "initial_data/scalar_pulse.hpp"
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
#include <vector>

namespace gbssn1d {

namespace {

/// The refinement flags: refused on a single grid (they would mean nothing), checked on boxes.
void validate_refinement_flags(const ResolvedParams& p) {
  if (p.grid != RadialGrid::boxes) {
    // the refinement flags mean nothing on a single grid: refused rather than ignored
    if (p.flags().levels)
      throw ParamError("--levels", std::to_string(p.levels()), "needs --grid boxes");
    if (p.time_interp != Params{}.time_interp)
      throw ParamError("--time-interp", p.time_interp.name(), "needs --grid boxes");
    if (p.no_subcycling)
      throw ParamError("--no-subcycling", "needs --grid boxes");
    if (p.box_taper() != 0.0)
      throw ParamError("--box-taper", num(p.box_taper()), "needs --grid boxes");
    if (p.box_taper_from != Params{}.box_taper_from)
      throw ParamError("--box-taper-from", num(p.box_taper_from), "needs --grid boxes");
  } else {
    if (p.levels() == 1) {
      // one box is a single grid: what only fine boxes have means nothing, refused as there
      const std::string single = "needs --levels 2 or more (with --levels 1 the boxes are a "
                                 "single grid, with no fine box)";
      if (p.time_interp != Params{}.time_interp)
        throw ParamError("--time-interp", p.time_interp.name(), single);
      if (p.no_subcycling)
        throw ParamError("--no-subcycling", single);
      if (p.box_taper() != 0.0)
        throw ParamError("--box-taper", num(p.box_taper()), single);
      if (p.box_taper_from != Params{}.box_taper_from)
        throw ParamError("--box-taper-from", num(p.box_taper_from), single);
      if (p.rah_variant == ShiftVariant::box_substage)
        throw ParamError("--rah-variant", p.rah_variant.name(), single);
    }
    if (p.levels() > 1 && p.N % 2 != 0)
      throw ParamError("--N", std::to_string(p.N),
                       "must be even with --grid boxes: each coarse cell holds two fine cells, "
                       "so that a fine box's edge is a coarse cell's face");
  }
}

/// The grid's flags: N, M, rmax, the kind of grid, its boxes and the differencing order, and
/// the initial data.
void validate_grid_flags(const ResolvedParams& p) {
  if (p.N <= 0)
    throw ParamError("--N", std::to_string(p.N), "must be a positive integer");
  if (p.N < 16)
    throw ParamError("--N", std::to_string(p.N), "must be at least 16 cells");
  if (p.N > N_max)
    throw ParamError("--N", std::to_string(p.N),
                     fmt::format("needs about {:.0f} GB of memory; at most {} cells are accepted",
                                 8.0 * 9 * 6 * p.N / 1e9, N_max));
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
  validate_refinement_flags(p);
  if (!fd::valid_order(p.fd_order))
    throw ParamError("--fd-order", std::to_string(p.fd_order), "must be 2, 4, 6 or 8");
  if (p.grid == RadialGrid::boxes && p.levels() > 1 && !mesh::boxes_order(p.fd_order))
    throw ParamError("--fd-order", std::to_string(p.fd_order),
                     "must be 2, 4 or 6 with --grid boxes: the boxes' prolongation and "
                     "restriction are 6th order");
  if (p.grid == RadialGrid::boxes && p.levels() > 1 && mesh::boxes_order(p.fd_order)
      && p.N < static_cast<int>(mesh::min_cells(p.fd_order)))
    throw ParamError("--N", std::to_string(p.N),
                     fmt::format("must be at least {} with --grid boxes at --fd-order {} (a "
                                 "fine box's buffer and the transfer stencils)",
                                 mesh::min_cells(p.fd_order), p.fd_order));
  if (p.grid == RadialGrid::sinh) {
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
}

/// The step's Courant factor and the norm windows.
void validate_evolution_numbers(const ResolvedParams& p) {
  const double norm_rmax = p.norm_rmax();
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
  if (!(norm_rmax > p.norm_rmin))
    throw ParamError("--norm-rmax", num(norm_rmax), "must be > --norm-rmin");
  if (norm_rmax > p.rmax)
    throw ParamError("--norm-rmax", num(norm_rmax), "must not exceed --rmax");

  if (!(p.norm_Rmax > p.norm_Rmin))
    throw ParamError("--norm-Rmax", num(p.norm_Rmax), "must be > --norm-Rmin");
}

/// The shift: a zero shift where the data have none; the horizon-adjusting shift and its horizon
/// searches.
void validate_horizon_shift(const ResolvedParams& p) {
  // a zero shift keeps the data's: they must have none, and no horizon shift is added
  if (p.shift == ShiftCondition::zero && shift_on(p))
    throw ParamError("--shift", p.shift.name(),
                     "keeps beta = 0 for all time: not with --rahA (the horizon-adjusting shift)");
  if (p.shift == ShiftCondition::zero && p.id != InitialDataKind::flat
      && p.id != InitialDataKind::wormhole)
    throw ParamError("--shift", p.shift.name(),
                     fmt::format("needs data without a shift (--id flat or wormhole): {} carries "
                                 "one, which a zero shift would freeze",
                                 p.id.name()));
  if (shift_on(p) && !(p.rah0 < p.rmax))
    throw ParamError("--rah0", num(p.rah0),
                     fmt::format("must be below --rmax = {}: the horizon is moved to a radius on "
                                 "the grid",
                                 num(p.rmax)));
  // the shift must act at the horizon: the taper begins (at rcut/2) outside twice its radius
  if (shift_on(p) && !(p.rah_rcut() >= 4.0 * std::max(p.rah0, p.M)))
    throw ParamError("--rah-rcut", num(p.rah_rcut()),
                     fmt::format("must be at least 4 max(rah0, M) = {} (--rah0 {}): beta_H "
                                 "would be cut near the horizon it moves (its default is "
                                 "rmax/2: a larger --rmax, or a smaller --rah0)",
                                 num(4.0 * std::max(p.rah0, p.M)), num(p.rah0)));
}

/// The formulation and its differencing: the volume choice where it is offered, Z4c's damping.
void validate_formulation(const ResolvedParams& p) {
  if (z4c_on(p) && p.gbssn_volume == Volume::eulerian)
    throw ParamError("--gbssn-volume", p.gbssn_volume.name(),
                     "is offered with --formulation bssn: Z4c here takes the Lagrangian choice");
  if (p.gbssn_volume == Volume::eulerian && (p.fd_order != 4 || p.upwind != fd::Upwind::lopsided))
    throw ParamError("--gbssn-volume", p.gbssn_volume.name(),
                     fmt::format("is offered with --fd-order 4 and --upwind lopsided only (given "
                                 "{} and {})",
                                 p.fd_order, p.upwind.name()));
  const double kappa1 = p.kappa1();
  if (p.flags().kappa1_hole) {
    if (p.kappa1_hole() != 0.0 && !(p.kappa1_hole() >= kappa1))
      throw ParamError("--kappa1-hole", num(p.kappa1_hole()),
                       fmt::format("must be 0 (off) or at least --kappa1 = {} (it raises kappa1 "
                                   "near the hole)",
                                   num(kappa1)));
  }
}

/// The pulse has time-symmetric data: the conformal factor the Hamiltonian constraint gives stays
/// positive (a strong pulse drives it through 0, where no such data exist).
void validate_scalar_data(const ResolvedParams& p) {
  const ScalarPulse pulse{p.scalar_amp, p.scalar_r0, p.scalar_width};
  const double puncture = p.id == InitialDataKind::wormhole ? p.M : 0.0;
  const ScalarPulseData data(pulse, puncture);
  std::vector<double> radii;
  const double reach = p.scalar_r0 + 10.0 * p.scalar_width;
  for (int k = 1; k <= 400; ++k)
    radii.push_back(reach * k / 400.0);
  const std::vector<double> psi = data.psi(radii);
  for (std::size_t k = 0; k < radii.size(); ++k)
    if (!(psi[k] > 0.0 && std::isfinite(psi[k])))
      throw ParamError("--scalar-amp", num(p.scalar_amp),
                       fmt::format("gives no time-symmetric data: the conformal factor the "
                                   "Hamiltonian constraint gives reaches {:.3g} at r = {:.4g} (a "
                                   "smaller amplitude, or a wider pulse)",
                                   psi[k], radii[k]));
}

/// The matter: the scalar field where its loop is built (4th order, the lopsided pair, no study
/// variant) and its data are (flat, or a puncture's); flat data without a horizon to move.
void validate_matter(const ResolvedParams& p) {
  if (scalar_on(p) && (p.fd_order != 4 || p.upwind != fd::Upwind::lopsided))
    throw ParamError("--matter", p.matter.name(),
                     fmt::format("is offered with --fd-order 4 and --upwind lopsided only (given "
                                 "{} and {})",
                                 p.fd_order, p.upwind.name()));
  if (scalar_on(p) && p.id != InitialDataKind::flat && p.id != InitialDataKind::wormhole)
    throw ParamError(
        "--matter", p.matter.name(),
        fmt::format("needs --id flat or wormhole (its pulse's data), not {}", p.id.name()));
  if (scalar_on(p) && shift_on(p) && p.rah_variant != ShiftVariant::consistent
      && p.rah_variant != ShiftVariant::midstep_update
      && p.rah_variant != ShiftVariant::box_substage)
    throw ParamError("--rah-variant", p.rah_variant.name(),
                     "is a study variant of vacuum BSSN: not with --matter scalar");
  if (scalar_on(p)) {
    if (!(p.scalar_r0 < p.rmax))
      throw ParamError(
          "--scalar-r0", num(p.scalar_r0),
          fmt::format("must lie below --rmax = {}: the pulse on the grid", num(p.rmax)));
    if (!(p.scalar_width < p.rmax))
      throw ParamError("--scalar-width", num(p.scalar_width),
                       fmt::format("must lie below --rmax = {}", num(p.rmax)));
    validate_scalar_data(p);
  }
  flux_radii(p); // its refusals, wherever it is given (as every flag's bounds)
  if (p.id == InitialDataKind::flat && shift_on(p))
    throw ParamError("--rahA", num(p.rahA),
                     "moves a horizon, and --id flat has none (leave --rahA out, or give --id "
                     "wormhole)");
}

/// The horizon shift's study variants where they are built (BSSN, the lopsided pair, 4th
/// order), and the finder's tolerance.
void validate_study_variants(const ResolvedParams& p) {
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
}

/// When the horizon is searched for: --ah-every's forms, the fixed interval in time (which
/// replaces --ah-every's schedule and needs searches), the window, and the study variants that
/// change where the searches happen.
void validate_search_schedule(const ResolvedParams& p) {
  if (!p.ah_every.valid())
    throw ParamError("--ah-every", printable(p.ah_every.name()),
                     "must be 'substage', 'extrapolated', 'step' or a whole number of steps "
                     ">= 1");
  if (p.ah_interval) {
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
  if (p.ah_tmax && *p.ah_tmax < p.ah_tmin)
    throw ParamError("--ah-tmax", num(*p.ah_tmax),
                     "must be >= --ah-tmin (leave it out for no limit)");
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

void validate(const ResolvedParams& p) {
  check_bounds(p); // each flag on its own: its row of the flag table
  validate_grid_flags(p);
  validate_evolution_numbers(p);
  validate_horizon_shift(p);
  validate_formulation(p);
  validate_matter(p);
  validate_study_variants(p);
  validate_search_schedule(p);
  validate_grid_and_steps(p);
}

} // namespace gbssn1d
