#include "config/params.hpp"

#include "config/param_rules.hpp"
#include "config/same_run.hpp"
#include "evolution/levels.hpp"
#include "mesh/level_steps.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <string>
#include <vector>

namespace gbssn1d {

namespace {

/// Boxes: the horizon belongs on the finest box, well inside its edge; wormhole data's gauge
/// pulse comes back from where the boxes end.
void box_warnings(const ResolvedParams& p, std::vector<std::string>& w) {
  // Boxes: the horizon belongs on the finest box, well inside its edge, where the finder and
  // the horizon shift see the finest spacing (flat data have no horizon to place).
  if (p.grid == RadialGrid::boxes && p.levels() > 1 && p.N > 0 && p.id != InitialDataKind::flat) {
    const double finest_extent = std::ldexp(p.rmax, -(p.levels() - 1));
    const double trusted = finest_extent * (1.0 - RefinementSettings::horizon_margin_cells / p.N);
    const double horizon = std::max(standard_horizon_radius * p.M, shift_on(p) ? p.rah0 : 0.0);
    if (horizon > trusted)
      w.push_back(fmt::format(
          "the horizon (r ~ {} M{}) lies outside the finest box's inner part (r <= {:.4g} M of "
          "its {:.4g} M with --N {}): it will be found on a coarser box; use fewer --levels or "
          "a larger --N",
          num(horizon), shift_on(p) ? ", --rah0" : "", trusted, finest_extent, p.N));
  }
  // Quadratic time interpolation loses its order at the default step (Sec. 11: six boxes,
  // h = 2 M, orders 3.49, 1.76 at cfl 0.5 against 4.37, 3.92 at 0.25)
  if (p.grid == RadialGrid::boxes && p.levels() > 1
      && p.time_interp == mesh::TimeInterpolation::quadratic && p.cfl > 0.25)
    w.push_back(fmt::format(
        "--time-interp quadratic with --cfl {}: its fine boundaries lose their order above cfl "
        "0.25 (order 1.8 at M/16-M/24 measured at 0.5: docs/horizon-shift-study.md, Sec. 11); use "
        "--cfl "
        "0.25, or the default rk-stages",
        num(p.cfl)));
  // A held h_AH makes beta_H jump in time at every search; quadratic time interpolation of a
  // subcycled fine box's boundary straddles the jumps, an error that does not fall with the
  // spacing at a fixed Courant number (second order in dt at a fixed spacing) and takes over
  // under refinement (docs/horizon-shift-study.md, Sec. 13, 13.1: the published stretch to
  // 0.89 M on 7 boxes converges at 4.23 over M/12-M/16 and at 1.56 over M/24-M/32, the finer
  // run's H above the coarser one's from 2.75 M; 3.92 with h_AH at every substage)
  if (p.grid == RadialGrid::boxes && p.levels() > 1
      && p.time_interp == mesh::TimeInterpolation::quadratic && !p.no_subcycling && shift_on(p)
      && !uses_hAH_file(p)
      && (p.ah_interval
          || (p.ah_every != SearchEvery::substage && p.ah_every != SearchEvery::extrapolated)))
    w.push_back(fmt::format(
        "--time-interp quadratic with {}: h_AH held between searches makes beta_H "
        "jump in time, and the fine boxes' quadratic time interpolation across the jumps adds an "
        "error that does not fall with the spacing at a fixed Courant number (the stretch to "
        "0.89 M loses convergence from M/24-M/32: docs/horizon-shift-study.md, Sec. 13, 13.1); "
        "use --ah-every substage (the default), "
        "--time-interp rk-stages, or --no-subcycling",
        p.ah_interval ? "--ah-interval " + num(*p.ah_interval)
                      : "--ah-every " + p.ah_every.name()));
  // A taper radius given beyond every fine box: the taper acts on the boxes that reach beyond
  // it (the largest fine box ends at rmax/2), so it would taper none (the default radius, 16 M,
  // leaves the small grids of tests and short runs untapered by design: not warned about)
  if (p.grid == RadialGrid::boxes && p.levels() > 1 && p.box_taper() > 0.0
      && p.box_taper_from != Params{}.box_taper_from && !(0.5 * p.rmax > p.box_taper_from * p.M))
    w.push_back(fmt::format(
        "--box-taper-from {} (M) lies beyond every fine box (the largest ends at r = rmax/2 = "
        "{} M): --box-taper {} tapers no box; give a radius below {} to taper the boxes that "
        "reach beyond it, or --box-taper 0 to say there is no taper",
        num(p.box_taper_from), num(0.5 * p.rmax / p.M), num(p.box_taper()),
        num(0.5 * p.rmax / p.M)));
  // Boxes and wormhole data: without the tapered buffer the collapse's outgoing gauge pulse
  // comes back from where the boxes end, at about (1/sqrt 2 + 1) R_b, in bursts of H and M_AH
  // that fall with N (docs/horizon-shift-study.md, Sec. 7: 6e-3 in M_AH at N = 96, 7e-4 at
  // 128, 1e-4 at 200); the taper absorbs it (Sec. 6.6), so only untapered box ends are meant.
  if (p.grid == RadialGrid::boxes && p.levels() > 1 && p.id == InitialDataKind::wormhole
      && p.N < 200) {
    const double back = 1.0 / std::sqrt(2.0) + 1.0;
    for (int l = p.levels() - 1; l >= 1; --l) { // the box ends from the inside out
      const double end = std::ldexp(p.rmax, -l);
      const bool tapered = p.box_taper() > 0.0 && end > p.box_taper_from * p.M;
      if (!tapered && end >= 50.0 * p.M && back * end <= p.tmax) {
        w.push_back(fmt::format(
            "wormhole data on untapered boxes with --N {} < 200: the collapse's gauge pulse "
            "comes back from where the boxes end (first from r = {:.4g} M at t ~ {:.0f} M), in "
            "bursts of H and M_AH (6e-3 in M_AH at N = 96, 7e-4 at N = 128: "
            "docs/horizon-shift-study.md, Sec. 7); use {}--N 200 or more, the sinh grid, or "
            "trumpet data",
            p.N, end, back * end, "the default --box-taper, "));
        break;
      }
    }
  }
}

/// Flags given where they do nothing (each flag's table entry says where it acts): a user who
/// forgot --rahA, or gave --dr-inner to a uniform grid, would not otherwise learn it.
void idle_flag_warnings(const ResolvedParams& p, std::vector<std::string>& w) {
  for (const auto& idle : idle_flags(p))
    w.push_back(idle.warning());
}

/// The radial spacing at r = M: where the horizon and the puncture's throat are resolved.
double spacing_near_horizon(const ResolvedParams& p) {
  if (p.grid == RadialGrid::boxes)
    return std::ldexp(p.rmax, -(p.levels() - 1)) / p.N;
  if (p.grid == RadialGrid::uniform)
    return p.rmax / p.N;
  const Grid g(RadialMap::sinh(p.rmax, p.dr_inner, sinh_reference_N), static_cast<std::size_t>(p.N),
               p.fd_order);
  const auto& r = g.r();
  const auto at = std::lower_bound(r.begin(), r.end(), p.M);
  return g.dr()[static_cast<std::size_t>(std::min(at - r.begin(), std::ptrdiff_t(r.size() - 1)))];
}

/// The biased upwind stencil is worse than the lopsided one where the throat is under-resolved
/// (docs/horizon-shift-study.md, Sec. 7.4: H 7 times on the trumpet at M/8, 1.5 times on a
/// shrink to 0.6 M at M/8 to M/16; H 1.5-8 times lower from M/12 otherwise).
/// A target radius within two cells of the origin: the horizon cannot be resolved there (runs
/// lose it, or go non-finite: tests/horizon/test_horizon_tracking.cpp).
void small_target_warning(const ResolvedParams& p, std::vector<std::string>& w) {
  if (!shift_on(p) || p.N <= 0)
    return;
  const double dr = spacing_near_horizon(p);
  if (p.rah0 < 2.0 * dr)
    w.push_back(fmt::format(
        "--rah0 {} lies within two cells of the origin (spacing {:.3g} M near r = M): the "
        "horizon cannot be resolved there, and such runs lose it or go non-finite; use a finer "
        "grid or a larger --rah0",
        num(p.rah0), dr / p.M));
}

void upwind_warnings(const ResolvedParams& p, std::vector<std::string>& w) {
  if (p.upwind != fd::Upwind::biased || p.N <= 0)
    return;
  const double dr = spacing_near_horizon(p);
  if (dr > p.M / 12.0 * (1.0 + 1e-9))
    w.push_back(fmt::format(
        "--upwind biased with a spacing of {:.3g} M at r = M (coarser than M/12): it measured 7 "
        "times the default lopsided stencil's H on the 1+log trumpet at M/8, where it is 1.5-8 "
        "times better from M/12 on (docs/horizon-shift-study.md, Sec. 7.4)",
        dr / p.M));
  if (shift_on(p) && p.rah0 < standard_horizon_radius * p.M)
    w.push_back(fmt::format(
        "--upwind biased with a shrink (--rah0 {} < {} M): it measured 1.5 times the default "
        "lopsided stencil's H on a shrink to 0.6 M at M/8 to M/16 (docs/horizon-shift-study.md, "
        "Sec. 7.4)",
        num(p.rah0), num(standard_horizon_radius * p.M)));
}

} // namespace

/// Output of more than this many bytes is announced before the run (with the flag that thins it).
constexpr double large_output_bytes = 200e6;

/// The bytes a run will write, roughly: profiles.dat's blocks (one row per composite point, 19
/// columns of 17 significant digits) and timeseries.dat's rows (16 columns).
void output_size_warning(const ResolvedParams& p, std::vector<std::string>& w) {
  constexpr double bytes_per_value = 21.0; // measured: 20.4 on average
  const double levels = p.levels();
  const double points = p.N * (1.0 + 0.5 * (levels - 1.0)); // a box's outer half per parent
  const double blocks = std::floor(p.tmax / p.dt_profiles) + 1.0, rows = p.tmax / p.dt_series;
  const double profiles = blocks * points * 19.0 * bytes_per_value;
  const double bytes = profiles + rows * 16.0 * bytes_per_value;
  if (!(bytes > large_output_bytes))
    return;
  const std::string thin =
      profiles > 0.5 * bytes
          ? fmt::format("--dt-profiles (now {}: {:.0f} blocks of {:.0f} rows)", num(p.dt_profiles),
                        blocks, points)
          : fmt::format("--dt-series (now {}: {:.0f} rows)", num(p.dt_series), rows);
  w.push_back(fmt::format("this run will write about {:.0f} MB into --out; a larger {} thins it",
                          bytes / 1e6, thin));
}

/// Horizon-shift settings that make it do less than it says: a taper radius beyond the grid, or
/// no horizon search before the run ends.
void horizon_shift_warnings(const ResolvedParams& p, std::vector<std::string>& w) {
  if (!shift_on(p))
    return;
  if (p.rah_rcut() > p.rmax)
    w.push_back(fmt::format(
        "--rah-rcut {} lies beyond --rmax {}: beta_H is not tapered to zero before the outer "
        "boundary, whose condition assumes the Gamma-driver's shift alone (leave --rah-rcut out "
        "for its default rmax/2)",
        num(p.rah_rcut()), num(p.rmax)));
  // --rah-variant midstep-update and box-substage change when the horizon is searched for;
  // with --rah-hAH-file nothing is searched for (--ah-every, --ah-tmin and --ah-tmax are idle
  // flags then: config/flag_table.cpp)
  if (uses_hAH_file(p)
      && (p.rah_variant == ShiftVariant::midstep_update
          || p.rah_variant == ShiftVariant::box_substage))
    w.push_back(fmt::format(
        "--rah-variant {} does nothing with --rah-hAH-file: it changes when h_AH is searched "
        "for, and h_AH(t) comes from the file (no searches); the run is --rah-variant "
        "consistent's",
        p.rah_variant.name()));
  // --ah-interval T: a search after the first step at or past each multiple of T, so a T below
  // the step holds h_AH for a step, not for T
  if (p.ah_interval && !uses_hAH_file(p)) {
    const EvolutionConfig c = evolution_config(p);
    const double dt = mesh::hierarchy_dt(make_layout(c), c.stepping);
    if (*p.ah_interval < dt * (1.0 - 1e-9))
      w.push_back(fmt::format(
          "--ah-interval {} is shorter than the {} step, {:.6g} M: a search follows every step, "
          "so h_AH is held for {:.6g} M, not {}",
          num(*p.ah_interval), p.grid == RadialGrid::boxes ? "hierarchy's" : "time", dt, dt,
          num(*p.ah_interval)));
  }
  if (p.rah_hAH_file.empty() && p.tmax > 0.0 && p.ah_tmin >= p.tmax)
    w.push_back(fmt::format(
        "--ah-tmin {} is at or after --tmax {}: no horizon search runs, so the horizon-adjusting "
        "shift (--rahA {}) never acts",
        num(p.ah_tmin), num(p.tmax), num(p.rahA)));
}

/// The outer boundary's influence comes in at the fastest characteristic speed, the 1+log gauge
/// speed sqrt(2) (light: 1): after (rmax - r) / speed it reaches radius r, and every number
/// measured there after it holds boundary reflections.
const double boundary_speed = std::sqrt(2.0);

/// The spheres of --flux-R that the outer boundary reaches before --tmax: their mass and flux
/// then hold the constraint violation its condition lets in (docs/scalar-field.md, "The energy
/// through a sphere"). Their coordinate radius is at most their areal radius on these data
/// (psi >= 1), so the time is an early bound.
void sphere_warnings(const ResolvedParams& p, std::vector<std::string>& w) {
  if (!scalar_on(p))
    return;
  std::vector<std::string> reached;
  double first = p.tmax;
  for (const double X : flux_radii(p))
    if (const double t = std::max(0.0, (p.rmax - X * p.M) / boundary_speed); p.tmax > t) {
      reached.push_back(num(X)); // (a sphere at R >= rmax, still on a wormhole's grid: from t = 0)
      first = std::min(first, t);
    }
  if (!reached.empty())
    w.push_back(fmt::format(
        "--tmax {} lets the outer boundary (--rmax {}) reach the --flux-R spheres of areal "
        "radius {} M from t ~ {:.0f} M (at the gauge speed sqrt(2)): their m_R<X> and flux_R<X> "
        "after that "
        "hold the constraint violation its condition lets in (several % of the mass inside, "
        "docs/scalar-field.md); rerun with a larger --rmax for clean late-time numbers",
        num(p.tmax), num(p.rmax), fmt::join(reached, ","), first));
}

std::vector<std::string> warnings(const ResolvedParams& p) {
  std::vector<std::string> w;
  horizon_shift_warnings(p, w);
  small_target_warning(p, w);
  // docs/horizon-shift-study.md Sec. 4: with eta = 2/M the Gamma-driver never settles on
  // wormhole data (its horizon drifts outwards to 1000 M), a shrunk horizon has to be held
  // against that drift, and the runs went non-finite at 137-201 M; eta <= 1/M settled them.
  if (shrinks_wormhole(p) && p.eta() > 1.0 / p.M)
    w.push_back(fmt::format(
        "--rah0 {} shrinks the horizon of wormhole data with --eta {} > 1/M: the Gamma-driver "
        "then drifts and such runs went non-finite after 100-200 M; eta = 1/M, their default, "
        "held them to 1000 M (docs/horizon-shift-study.md, Sec. 4.2 and Sec. 9)",
        num(p.rah0), num(p.eta())));
  // the norm windows and the horizon (boundary_speed)
  const double window = std::max(p.norm_rmax(), p.norm_Rmax * p.M);
  const double t_window = (p.rmax - window) / boundary_speed,
               t_horizon = (p.rmax - 2.0 * p.M) / boundary_speed;
  if (p.tmax > t_window && p.rmax > window)
    w.push_back(fmt::format(
        "--tmax {} lets the outer boundary (--rmax {}) reach the norm windows (r <= {} M) from "
        "t ~ {:.0f} M and the horizon from t ~ {:.0f} M (at the gauge speed sqrt(2)): norms, "
        "M_AH and r_AH after that include its reflections; for a clean late-time figure rerun "
        "with --rmax > {:.0f}",
        num(p.tmax), num(p.rmax), num(window), t_window, std::max(t_horizon, 0.0),
        std::ceil(window + boundary_speed * p.tmax)));
  sphere_warnings(p, w);
  box_warnings(p, w);
  upwind_warnings(p, w);
  idle_flag_warnings(p, w);
  output_size_warning(p, w);
  return w;
}

} // namespace gbssn1d
