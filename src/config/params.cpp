#include "config/params.hpp"

#include "config/numbers.hpp"
#include "fd/stencils.hpp"
#include "io/table.hpp"
#include "mesh/hierarchy.hpp"

#include <boost/math/interpolators/cardinal_cubic_b_spline.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include <filesystem>
#include <limits>
#include <memory>
#include <new>
#include <string_view>
#include <unistd.h>
#include <utility>

namespace gbssn1d {

namespace {

/// Largest CFL factor accepted: RK4 with 4th-order centred differences is stable for
/// c dt/dr < 2.06; the fastest characteristic speeds are the 1+log gauge speed sqrt(2) plus
/// the shift, so 1 keeps a margin. (dt = cfl * smallest spacing.)
constexpr double cfl_max = 1.0;
/// Smallest CFL factor accepted: below it a run only accumulates round-off in t (and a value
/// such as 4.9e-324 would otherwise be reported as too many steps for --tmax).
constexpr double cfl_min = 1e-4;
/// The smallest cell accepted, relative to rmax: below it double precision cannot tell the
/// cell's faces apart well enough for 4th-order differences.
constexpr double min_spacing_over_rmax = 1e-10;
/// The horizon's radius must be found well within one cell: at most this fraction of the
/// smallest cell width (a loose tolerance returns a point of the bracket, not the root).
constexpr double ah_tol_over_spacing_max = 1e-3;
/// RK4 stability limit of the Gamma-driver damping term, eta dt < 2.78 (Schnetter 2010).
constexpr double eta_dt_max = 2.78;
/// Largest grid accepted: 9 fields on about 6 state-sized buffers (state, RK4 stages, output).
constexpr int N_max = 10'000'000;
/// Most time steps accepted in one run (a typo in --tmax or --dt-series, not a real run).
constexpr double steps_max = 1e9;
constexpr double rows_max = 1e7;
constexpr double rmax_over_M_max = 1e6; ///< rows of timeseries.dat (at most about 3 GB)

/// The names a choice flag accepts and what each stands for: one table serves the validation,
/// its message and the conversion, so they cannot drift apart.
template <class E>
using Choices = std::initializer_list<std::pair<std::string_view, E>>;

const Choices<ShiftProfile> profile_choices{{"auto", ShiftProfile::automatic},
                                            {"rational", ShiftProfile::rational},
                                            {"rational3", ShiftProfile::rational3},
                                            {"gauss", ShiftProfile::gauss},
                                            {"gauss3", ShiftProfile::gauss3}};
const Choices<Taper> taper_choices{{"quartic", Taper::quartic}, {"step", Taper::step}};
const Choices<ShiftNormal> normal_choices{{"conformal", ShiftNormal::conformal},
                                          {"unit", ShiftNormal::unit},
                                          {"smooth", ShiftNormal::smooth}};
const Choices<mesh::TimeInterpolation> time_interp_choices{
    {"rk-stages", mesh::TimeInterpolation::rk_stages},
    {"dense", mesh::TimeInterpolation::dense_output},
    {"quadratic", mesh::TimeInterpolation::quadratic}};
const Choices<AdvectionStencil> stencil_choices{{"upwind-gd", AdvectionStencil::upwind_gd},
                                                {"upwind-full", AdvectionStencil::upwind_full},
                                                {"centred", AdvectionStencil::centred}};
/// B's driver term also takes `matched` (gbssn/rhs.hpp).
const Choices<AdvectionStencil> driver_stencil_choices{
    {"matched", AdvectionStencil::matched},
    {"upwind-gd", AdvectionStencil::upwind_gd},
    {"upwind-full", AdvectionStencil::upwind_full},
    {"centred", AdvectionStencil::centred}};

/// The value `name` stands for; ParamError naming `flag` and the accepted names otherwise.
template <class E>
E choice(const std::string& flag, const std::string& name, const Choices<E>& choices) {
  std::string list;
  for (const auto& [n, value] : choices) {
    if (n == name)
      return value;
    list += (list.empty() ? "" : ", ") + std::string(n);
  }
  throw ParamError(flag, name, "must be one of " + list);
}

/// The name of `value` among `choices` (each value has one).
template <class E>
std::string_view choice_name(const Choices<E>& choices, E value) {
  for (const auto& [n, v] : choices)
    if (v == value)
      return n;
  throw std::logic_error("a choice without a name");
}

std::string num(double v) {
  return fmt::format("{}", v);
}

void require_finite(const std::string& flag, double v) {
  if (!std::isfinite(v))
    throw ParamError(flag, num(v), "must be a finite number");
}

void require_positive(const std::string& flag, double v) {
  require_finite(flag, v);
  if (!(v > 0.0))
    throw ParamError(flag, num(v), "must be > 0");
}

} // namespace

std::string printable(const std::string& s) {
  std::string out;
  for (unsigned char c : s)
    out += (c >= 0x20 && c < 0x7f) ? std::string(1, static_cast<char>(c))
                                   : fmt::format("\\x{:02x}", c);
  return out;
}

bool shrinks_wormhole(const Params& p) {
  return p.id == "wormhole" && p.rahA > 0.0 && p.rah0 < standard_horizon_radius * p.M;
}

int levels_rule(double rmax, double M) {
  const double levels = 1.0 + std::floor(std::log2(rmax / (4.0 * M)));
  return std::isfinite(levels) ? static_cast<int>(std::clamp(levels, 2.0, 30.0)) : 2;
}

double dt_max_of_damping(double eta) {
  return eta > 0.0 ? 1.0 / eta : std::numeric_limits<double>::infinity();
}

namespace {

/// Most levels accepted: with 30 the finest box is 1e-9 of the outer one.
constexpr int levels_max = 30;

/// The refinement hierarchy of validated box parameters (one level for the single grids).
mesh::MeshLayout mesh_layout(const Params& p) {
  if (p.grid != "boxes")
    return mesh::MeshLayout(make_grid(grid_spec(p)).map(), static_cast<std::size_t>(p.N), 1);
  return mesh::MeshLayout(p.rmax, static_cast<std::size_t>(p.N),
                          static_cast<std::size_t>(p.levels.value_or(1)));
}

mesh::StepperOptions stepper_options(const Params& p) {
  mesh::StepperOptions o;
  o.time = choice("--time-interp", p.time_interp, time_interp_choices);
  o.subcycling = !p.no_subcycling;
  o.cfl = p.cfl.value();
  if (p.grid == "boxes")
    o.dt_max = dt_max_of_damping(p.eta.value_or(2.0 / p.M));
  return o;
}

} // namespace

void resolve_defaults(Params& p) {
  // a number of steps in its one spelling (05 and 5 are the same run, as 0.25 and 0.250 are)
  if (const auto n = parse_decimal<long>(p.ah_every))
    p.ah_every = std::to_string(*n);
  if (p.grid == "boxes" && !p.levels)
    p.levels = levels_rule(p.rmax, p.M);
  // M and rmax are validated afterwards: a bad M gives a non-finite eta
  if (!p.eta)
    p.eta = (shrinks_wormhole(p) ? 1.0 : 2.0) / p.M;
  // docs/horizon-shift-study.md Sec. 11: on single grids every error measured is the same at
  // cfl 0.25 ... 0.8 (spatial errors dominate) and runs became unstable from 0.8 (8th order)
  // or 0.9; on boxes the time interpolation of fine boundaries makes the error depend on it
  if (!p.cfl)
    p.cfl = p.grid == "boxes" ? 0.25 : 0.5;
  if (!p.norm_rmax)
    p.norm_rmax = std::min(10.0 * p.M, 0.5 * p.rmax);
  if (p.rahA != 0.0) {
    if (!p.rah_rcut)
      p.rah_rcut = 0.5 * p.rmax;
    if (!p.rah_taper)
      p.rah_taper = std::string(choice_name(taper_choices, HorizonShiftParams{}.taper));
    // `auto` is written to config.toml as the profile and width it stands for, so that a
    // checkpoint or a sweep member made when auto meant another width is told apart (not
    // resumed with the new one); M is validated afterwards
    if (p.rah_profile == "auto" && std::isfinite(p.M) && p.M > 0.0) {
      HorizonShiftParams hs;
      hs.profile = ShiftProfile::automatic;
      hs.h = p.rah0;
      resolve_automatic_profile(hs, p.M);
      p.rah_profile = hs.profile == ShiftProfile::gauss ? "gauss" : "rational";
      p.rah_width = hs.width;
    }
  }
}

std::vector<std::string> warnings(const Params& p) {
  std::vector<std::string> w;
  // docs/horizon-shift-study.md Sec. 4: with eta = 2/M the Gamma-driver never settles on
  // wormhole data (its horizon drifts outwards to 1000 M), a shrunk horizon has to be held
  // against that drift, and the runs went non-finite at 137-201 M; eta <= 1/M settled them.
  if (shrinks_wormhole(p) && p.eta.value_or(1.0 / p.M) > 1.0 / p.M)
    w.push_back(fmt::format(
        "--rah0 {} shrinks the horizon of wormhole data with --eta {} > 1/M: the Gamma-driver "
        "then drifts and such runs went non-finite after 100-200 M; eta = 1/M, their default, "
        "held them to 1000 M (docs/horizon-shift-study.md, Sec. 4.2 and Sec. 9)",
        num(p.rah0), num(p.eta.value_or(1.0 / p.M))));
  // The outer boundary's influence comes in at the fastest characteristic speed, the 1+log
  // gauge speed sqrt(2) (light: 1): after (rmax - r) / sqrt(2) it reaches radius r, and every
  // number measured there after it holds boundary reflections.
  const double speed = std::sqrt(2.0);
  const double window = std::max(p.norm_rmax.value_or(0.0), p.norm_Rmax * p.M);
  const double t_window = (p.rmax - window) / speed, t_horizon = (p.rmax - 2.0 * p.M) / speed;
  if (p.tmax > t_window && p.rmax > window)
    w.push_back(fmt::format(
        "--tmax {} lets the outer boundary (--rmax {}) reach the norm windows (r <= {} M) from "
        "t ~ {:.0f} M and the horizon from t ~ {:.0f} M (at the gauge speed sqrt(2)): norms, "
        "M_AH and r_AH after that include its reflections; for a clean late-time figure rerun "
        "with --rmax > {:.0f}",
        num(p.tmax), num(p.rmax), num(window), t_window, std::max(t_horizon, 0.0),
        std::ceil(window + speed * p.tmax)));
  // Boxes: the horizon belongs on the finest box, well inside its edge, where the finder and
  // the horizon shift see the finest spacing.
  if (p.grid == "boxes" && p.levels && *p.levels > 1 && p.N > 0) {
    const double finest_extent = std::ldexp(p.rmax, -(*p.levels - 1));
    const double trusted = finest_extent * (1.0 - RefinementSettings::horizon_margin_cells / p.N);
    const double horizon = std::max(standard_horizon_radius * p.M, p.rahA != 0.0 ? p.rah0 : 0.0);
    if (horizon > trusted)
      w.push_back(fmt::format(
          "the horizon (r ~ {} M{}) lies outside the finest box's inner part (r <= {:.4g} M of "
          "its {:.4g} M with --N {}): it will be found on a coarser box; use fewer --levels or "
          "a larger --N",
          num(horizon), p.rahA != 0.0 ? ", --rah0" : "", trusted, finest_extent, p.N));
  }
  // Boxes and wormhole data: the collapse's outgoing gauge pulse comes back from where the
  // boxes end, at about (1/sqrt 2 + 1) R_b, in bursts of H and M_AH that fall with N
  // (docs/horizon-shift-study.md, Sec. 7: 6e-3 in M_AH at N = 96, 7e-4 at 128, 1e-4 at 200).
  if (p.grid == "boxes" && p.levels && *p.levels > 1 && p.id == "wormhole" && p.N < 200) {
    const double back = 1.0 / std::sqrt(2.0) + 1.0;
    for (int l = *p.levels - 1; l >= 1; --l) { // the box ends from the inside out
      const double end = std::ldexp(p.rmax, -l);
      if (end >= 50.0 * p.M && back * end <= p.tmax) {
        w.push_back(fmt::format(
            "wormhole data on boxes with --N {} < 200: the collapse's gauge pulse comes back from "
            "where the boxes end (first from r = {:.4g} M at t ~ {:.0f} M), in bursts of H and "
            "M_AH (6e-3 in M_AH at N = 96, 7e-4 at N = 128: docs/horizon-shift-study.md, Sec. 7); "
            "use --N 200 or more, the sinh grid, or trumpet data",
            p.N, end, back * end));
        break;
      }
    }
  }
  // The horizon-shift flags act only with a strength: given with --rahA 0 they change nothing,
  // which a user who forgot --rahA would not otherwise learn.
  if (p.rahA == 0.0) {
    const Params d;
    std::vector<std::string> idle;
    if (p.rah0 != d.rah0)
      idle.push_back("--rah0 " + num(p.rah0));
    if (p.rah_profile != d.rah_profile)
      idle.push_back("--rah-profile " + p.rah_profile);
    if (p.rah_width != d.rah_width)
      idle.push_back("--rah-width " + num(p.rah_width));
    if (p.rah_rcut)
      idle.push_back("--rah-rcut " + num(*p.rah_rcut));
    if (p.rah_taper)
      idle.push_back("--rah-taper " + *p.rah_taper);
    if (p.rah_ramp != d.rah_ramp)
      idle.push_back("--rah-ramp " + num(p.rah_ramp));
    if (p.rah_normal != d.rah_normal)
      idle.push_back("--rah-normal " + p.rah_normal);
    if (!p.rah_hAH_file.empty())
      idle.push_back("--rah-hAH-file " + p.rah_hAH_file);
    if (p.rah_variant != d.rah_variant)
      idle.push_back("--rah-variant " + p.rah_variant);
    if (!idle.empty())
      w.push_back(fmt::format("{} {} nothing with --rahA 0: the horizon-adjusting shift is off "
                              "(give --rahA A, e.g. 0.5, to move the horizon)",
                              fmt::join(idle, ", "), idle.size() == 1 ? "does" : "do"));
  }
  return w;
}

void validate(const Params& p) {
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
  if (p.grid != "uniform" && p.grid != "sinh" && p.grid != "boxes")
    throw ParamError("--grid", p.grid, "must be 'uniform', 'sinh' or 'boxes'");
  (void)choice("--time-interp", p.time_interp, time_interp_choices);
  if (p.grid != "boxes") {
    // the refinement flags mean nothing on a single grid: refused rather than ignored
    if (p.levels)
      throw ParamError("--levels", std::to_string(*p.levels), "needs --grid boxes");
    if (p.time_interp != Params{}.time_interp)
      throw ParamError("--time-interp", p.time_interp, "needs --grid boxes");
    if (p.no_subcycling)
      throw ParamError("--no-subcycling", "needs --grid boxes");
  } else {
    if (!p.levels)
      throw std::logic_error("validate() before resolve_defaults()");
    if (*p.levels < 1 || *p.levels > levels_max)
      throw ParamError("--levels", std::to_string(*p.levels),
                       fmt::format("must lie in 1 ... {}", levels_max));
    if (*p.levels > 1 && p.N % 2 != 0)
      throw ParamError("--N", std::to_string(p.N),
                       "must be even with --grid boxes: each coarse cell holds two fine cells, "
                       "so that a fine box's edge is a coarse cell's face");
  }
  if (!fd::valid_order(p.fd_order))
    throw ParamError("--fd-order", std::to_string(p.fd_order), "must be 2, 4, 6 or 8");
  if (p.grid == "boxes" && p.levels && *p.levels > 1 && !mesh::boxes_order(p.fd_order))
    throw ParamError("--fd-order", std::to_string(p.fd_order),
                     "must be 2, 4 or 6 with --grid boxes: the boxes' prolongation and "
                     "restriction are 6th order");
  if (p.grid == "boxes" && p.levels && *p.levels > 1 && mesh::boxes_order(p.fd_order)
      && p.N < static_cast<int>(mesh::min_cells(p.fd_order)))
    throw ParamError("--N", std::to_string(p.N),
                     fmt::format("must be at least {} with --grid boxes at --fd-order {} (a "
                                 "fine box's buffer and the transfer stencils)",
                                 mesh::min_cells(p.fd_order), p.fd_order));
  if (p.grid == "sinh") {
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
  if (p.id != "wormhole" && p.id != "maximal-trumpet" && p.id != "1log-trumpet")
    throw ParamError("--id", p.id, "must be one of wormhole, maximal-trumpet, 1log-trumpet");
  if (p.lapse0 != "one" && p.lapse0 != "precollapsed")
    throw ParamError("--lapse0", p.lapse0, "must be 'one' or 'precollapsed'");

  if (!p.eta || !p.norm_rmax)
    throw std::logic_error("validate() before resolve_defaults()");
  const double eta = *p.eta, norm_rmax = *p.norm_rmax;
  require_finite("--eta", eta);
  if (eta < 0.0)
    throw ParamError("--eta", num(eta), "must be >= 0");
  if (!p.cfl)
    throw std::logic_error("validate() before resolve_defaults()");
  const double cfl = *p.cfl;
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

  require_finite("--rahA", p.rahA);
  require_positive("--rah0", p.rah0);
  require_positive("--rah-width", p.rah_width);
  if (p.rah_rcut) {
    require_positive("--rah-rcut", *p.rah_rcut);
    // the shift must act at the horizon: the taper begins (at rcut/2) outside twice its radius
    if (p.rahA != 0.0 && !(*p.rah_rcut >= 4.0 * std::max(p.rah0, p.M)))
      throw ParamError("--rah-rcut", num(*p.rah_rcut),
                       fmt::format("must be at least 4 max(rah0, M) = {}: beta_H would be cut "
                                   "near the horizon it moves",
                                   num(4.0 * std::max(p.rah0, p.M))));
  }
  if (p.ah_every != "substage" && p.ah_every != "step") {
    const auto n = parse_decimal<long>(p.ah_every);
    if (!n || *n < 1)
      throw ParamError("--ah-every", printable(p.ah_every),
                       "must be 'substage', 'step' or a whole number of steps >= 1");
  }
  (void)choice("--rah-profile", p.rah_profile, profile_choices);
  (void)choice("--rah-normal", p.rah_normal, normal_choices);
  if (p.rah_taper)
    (void)choice("--rah-taper", *p.rah_taper, taper_choices);
  require_positive("--rah-chi-smooth", p.rah_chi_smooth);
  require_finite("--rah-ramp", p.rah_ramp);
  if (p.rah_ramp < 0.0)
    throw ParamError("--rah-ramp", num(p.rah_ramp), "must be >= 0 (0: no ramp)");
  (void)choice("--driver-advection", p.driver_advection, driver_stencil_choices);
  (void)choice("--delta-advection", p.delta_advection, stencil_choices);
  require_finite("--ah-tmin", p.ah_tmin);
  if (p.ah_tmin < 0.0)
    throw ParamError("--ah-tmin", num(p.ah_tmin), "must be >= 0");
  if (p.ah_tmax) {
    require_finite("--ah-tmax", *p.ah_tmax);
    if (*p.ah_tmax < p.ah_tmin)
      throw ParamError("--ah-tmax", num(*p.ah_tmax),
                       "must be >= --ah-tmin (leave it out for no limit)");
  }
  require_positive("--ah-tol", p.ah_tol);
  constexpr std::array<std::string_view, 7> variants{
      "consistent",        "no-shift-derivatives", "no-shift-second-derivatives",
      "delta-rhs-from-gd", "driver-full-shift",    "midstep-update",
      "box-substage"};
  if (std::find(variants.begin(), variants.end(), p.rah_variant) == variants.end())
    throw ParamError("--rah-variant", p.rah_variant,
                     "must be consistent, no-shift-derivatives, no-shift-second-derivatives, "
                     "delta-rhs-from-gd, driver-full-shift, midstep-update or box-substage");
  if (p.rah_variant == "box-substage" && (p.grid != "boxes" || p.ah_every != "substage"))
    throw ParamError("--rah-variant", p.rah_variant, "needs --grid boxes and --ah-every substage");
  if (p.rah_variant == "midstep-update" && p.ah_every == "substage")
    throw ParamError("--rah-variant", p.rah_variant,
                     "needs searches every n steps (--ah-every step or a number)");

  // The grid itself: a map whose cells are not finite, increasing and resolvable in double
  // precision is refused here, before anything is written, naming the flag that shapes it (the
  // sinh grid's innermost width, the uniform grid's N).
  const std::string grid_flag = p.grid == "sinh"    ? "--dr-inner"
                                : p.grid == "boxes" ? "--levels"
                                                    : "--N";
  const std::string grid_value = p.grid == "sinh"    ? num(p.dr_inner)
                                 : p.grid == "boxes" ? std::to_string(p.levels.value_or(1))
                                                     : std::to_string(p.N);
  const mesh::MeshLayout layout = [&] {
    try {
      return mesh_layout(p);
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
  if (p.ah_tol > ah_tol_over_spacing_max * grid.min_spacing())
    throw ParamError("--ah-tol", num(p.ah_tol),
                     fmt::format("must be at most {} x the smallest cell width ({:.3g}), so that "
                                 "the horizon is found well within one cell",
                                 ah_tol_over_spacing_max, grid.min_spacing()));
  // The Gamma-driver's damping term limits the step independently of the spacing.
  const double dt = mesh::hierarchy_dt(layout, stepper_options(p)); // the whole step
  const double dt_finest = time_step(p.cfl.value(), grid);
  if (p.checkpoint_every > 0.0 && p.checkpoint_every < dt)
    throw ParamError("--checkpoint-every", num(p.checkpoint_every),
                     fmt::format("is shorter than the time step dt = {:.6g} (checkpoints are "
                                 "written between steps; 0: only on a signal)",
                                 dt));
  // The step count (the step is the CFL step whatever the output cadence) and the row counts.
  const double n_steps = std::ceil(p.tmax / dt - 1e-9);
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
    throw ParamError("--cfl", num(p.cfl.value()),
                     fmt::format("unstable with --eta = {}: eta dt = {} exceeds {} (RK4 limit of "
                                 "the Gamma-driver damping)",
                                 eta, eta * dt_finest, eta_dt_max));
  if (p.grid == "boxes" && p.rah_variant == "midstep-update")
    throw ParamError("--rah-variant", p.rah_variant,
                     "is a single-grid study variant (its searches count one grid's RHS calls)");
}

void validate_output_dir(const Params& p) {
  namespace fs = std::filesystem;
  if (p.out.empty())
    throw ParamError("--out", "''", "an output directory is required");
  check_path("--out", p.out);
  std::error_code ec;
  const fs::path dir(p.out);
  if (fs::exists(dir, ec)) {
    if (!fs::is_directory(dir, ec))
      throw ParamError("--out", p.out, "exists and is not a directory");
    if (!fs::is_empty(dir, ec) && !p.force)
      throw ParamError("--out", p.out, "exists and is not empty (use --force to overwrite)");
    if (::access(dir.c_str(), W_OK | X_OK) != 0)
      throw ParamError("--out", p.out, "is not writable");
    return;
  }
  // The nearest existing ancestor must be a writable directory.
  fs::path parent = fs::absolute(dir, ec).parent_path();
  while (!parent.empty() && !fs::exists(parent, ec))
    parent = parent.parent_path();
  if (parent.empty() || !fs::is_directory(parent, ec) || ::access(parent.c_str(), W_OK | X_OK))
    throw ParamError("--out", p.out, "cannot be created: parent directory is not writable");
}

namespace {

/// A path for a message: at most 120 bytes of it, non-printable bytes escaped.
std::string shown_path(const std::string& path) {
  return path.size() <= 120
             ? printable(path)
             : fmt::format("{}... ({} bytes)", printable(path.substr(0, 100)), path.size());
}

} // namespace

void check_path(const std::string& flag, const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  const std::string text = path.string();
  if (text.size() > 4095)
    throw ParamError(flag, shown_path(text), "is longer than 4095 bytes, the system's limit");
  for (const auto& part : path)
    if (part.string().size() > 255)
      throw ParamError(
          flag, shown_path(text),
          fmt::format("has a name of {} bytes; the system's limit is 255", part.string().size()));
  std::error_code ec;
  (void)fs::status(path, ec);
  if (!ec || ec == std::errc::no_such_file_or_directory)
    return;
  if (ec == std::errc::too_many_symbolic_link_levels)
    throw ParamError(flag, shown_path(text), "leads into a loop of symbolic links");
  if (ec == std::errc::not_a_directory)
    throw ParamError(flag, shown_path(text), "has a part that is a file, not a folder");
  if (ec == std::errc::permission_denied)
    throw ParamError(flag, shown_path(text), "cannot be reached: permission denied");
  throw ParamError(flag, shown_path(text), "cannot be used: " + ec.message());
}

void check_input_file(const std::string& flag, const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  check_path(flag, path);
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (!fs::exists(st))
    throw ParamError(flag, shown_path(path.string()), "no such file");
  if (fs::is_directory(st))
    throw ParamError(flag, shown_path(path.string()), "is a folder, not a file");
  if (!fs::is_regular_file(st))
    throw ParamError(flag, shown_path(path.string()),
                     "is not a regular file (a FIFO, device or socket): give a file");
  if (::access(path.c_str(), R_OK) != 0)
    throw ParamError(flag, shown_path(path.string()), "cannot be read: permission denied");
}

void create_output_dir(const std::string& flag, const std::filesystem::path& dir) {
  check_path(flag, dir);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec)
    throw ParamError(flag, dir.string(), "cannot be created: " + ec.message());
}

GridSpec grid_spec(const Params& p) {
  GridSpec spec;
  spec.kind = p.grid == "sinh" ? GridKind::sinh : GridKind::uniform; // boxes: uniform levels
  spec.N = static_cast<std::size_t>(p.N);
  spec.rmax = p.rmax;
  spec.dr_inner = p.dr_inner;
  spec.fd_order = p.fd_order;
  return spec;
}

EvolutionConfig evolution_config(const Params& p) {
  EvolutionConfig c;
  c.grid = grid_spec(p);
  if (p.grid == "boxes") {
    const mesh::StepperOptions o = stepper_options(p);
    c.refinement.levels = static_cast<std::size_t>(p.levels.value());
    c.refinement.time = o.time;
    c.refinement.subcycling = o.subcycling;
    c.refinement.dt_max = o.dt_max;
  }
  c.initial_data = initial_data_params(p);
  c.rhs = rhs_params(p);
  c.cfl = p.cfl.value();
  c.chi_floor = p.chi_floor;
  c.tmax = p.tmax;
  c.dt_series = p.dt_series;
  c.dt_profiles = p.dt_profiles;
  c.checkpoint_every = p.checkpoint_every;
  c.norms.rmin = p.norm_rmin;
  c.norms.rmax = p.norm_rmax.value();
  c.norms.Rmin = p.norm_Rmin * p.M; // the areal windows are given in units of M
  c.norms.Rmax = p.norm_Rmax * p.M;
  c.norms.Rint = p.norm_Rint * p.M;
  c.horizon_search.every_steps = ah_every_steps(p);
  c.horizon_search.t_min = p.ah_tmin;
  c.horizon_search.t_max = p.ah_tmax.value_or(std::numeric_limits<double>::infinity());
  c.horizon_search.finder.tolerance = p.ah_tol;
  return c;
}

InitialDataParams initial_data_params(const Params& p) {
  InitialDataParams id;
  id.M = p.M;
  id.kind = p.id == "wormhole"          ? InitialDataKind::wormhole
            : p.id == "maximal-trumpet" ? InitialDataKind::maximal_trumpet
                                        : InitialDataKind::onelog_trumpet;
  id.lapse0 = p.lapse0 == "one" ? InitialLapse::one : InitialLapse::precollapsed;
  return id;
}

RhsParams rhs_params(const Params& p) {
  RhsParams r;
  r.gauge.shift.eta = p.eta.value();
  r.gauge.shift.advective = p.advective_shift;
  r.gauge.slicing.advective = !p.non_advective_lapse;
  r.ko_sigma = p.ko_sigma;
  r.horizon_shift.A = p.rahA;
  r.horizon_shift.h = p.rah0;
  r.horizon_shift.width = p.rah_width;
  r.horizon_shift.ramp = p.rah_ramp;
  r.horizon_shift.r_cut = p.rah_rcut.value_or(std::numeric_limits<double>::infinity());
  if (p.rah_taper) // unset only without the horizon shift: HorizonShiftParams' default then
    r.horizon_shift.taper = choice("--rah-taper", *p.rah_taper, taper_choices);
  r.horizon_shift.profile = choice("--rah-profile", p.rah_profile, profile_choices);
  r.horizon_shift.normal = choice("--rah-normal", p.rah_normal, normal_choices);
  r.horizon_shift.chi_smooth = p.rah_chi_smooth;
  resolve_automatic_profile(r.horizon_shift, p.M);
  if (!p.rah_hAH_file.empty() && p.rahA != 0.0)
    r.horizon_shift.prescribed_h_AH = load_prescribed_horizon(p.rah_hAH_file, p.tmax);
  r.advection.driver = choice("--driver-advection", p.driver_advection, driver_stencil_choices);
  r.advection.delta = choice("--delta-advection", p.delta_advection, stencil_choices);
  r.horizon_shift.search_every_substage = ah_every_steps(p) == 0;
  r.horizon_shift.t_min = p.ah_tmin;
  r.horizon_shift.t_max = p.ah_tmax.value_or(std::numeric_limits<double>::infinity());
  using Variant = HorizonShiftParams::Variant;
  r.horizon_shift.variant =
      p.rah_variant == "no-shift-second-derivatives" ? Variant::no_shift_second_derivatives
      : p.rah_variant == "delta-rhs-from-gd"         ? Variant::delta_rhs_from_gd
      : p.rah_variant == "no-shift-derivatives"      ? Variant::no_shift_derivatives
      : p.rah_variant == "driver-full-shift"         ? Variant::driver_full_shift
      : p.rah_variant == "midstep-update"            ? Variant::midstep_update
      : p.rah_variant == "box-substage"              ? Variant::box_substage
                                                     : Variant::consistent;
  if (r.horizon_shift.variant == Variant::midstep_update) {
    r.horizon_shift.search_every_substage = false;
    r.horizon_shift.midstep_every = ah_every_steps(p);
  }
  return r;
}

std::function<double(double)> load_prescribed_horizon(const std::string& path, double t_end) {
  const std::string flag = "--rah-hAH-file";
  // A regular file of sane size, checked before reading (/dev/zero would be read for ever).
  constexpr std::uintmax_t max_bytes = 1u << 30;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw ParamError(flag, printable(path), "is not a regular file");
  if (const auto size = std::filesystem::file_size(path, ec); ec || size > max_bytes)
    throw ParamError(flag, printable(path),
                     fmt::format("is larger than {} bytes (not a gbssn1d output file)", max_bytes));
  Table table;
  try {
    table = read_table(path);
  } catch (const std::runtime_error&) {
    throw ParamError(flag, path, "cannot be read");
  }
  const auto col_t = table.column("t"), col_r = table.column("r_ah");
  if (!col_t || !col_r)
    throw ParamError(flag, path, "needs the columns 't' and 'r_ah'");
  std::vector<double> t, r_ah;
  for (const auto& row : table.rows) {
    if (row.size() <= std::max(*col_t, *col_r))
      throw ParamError(flag, path, fmt::format("has a short data row (row {})", t.size() + 1));
    if (!std::isfinite(row[*col_r]))
      throw ParamError(flag, path,
                       fmt::format("has no horizon (r_ah = NaN) at t = {}", row[*col_t]));
    t.push_back(row[*col_t]);
    r_ah.push_back(row[*col_r]);
  }
  if (t.size() < 5)
    throw ParamError(flag, path, "needs at least 5 rows");
  const double dt = (t.back() - t.front()) / static_cast<double>(t.size() - 1);
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw ParamError(flag, printable(path),
                     fmt::format("its times must increase (t = {} ... {})", t.front(), t.back()));
  for (std::size_t k = 1; k < t.size(); ++k)
    if (std::abs(t[k] - t[0] - static_cast<double>(k) * dt) > 1e-9 * (1.0 + std::abs(t[k])))
      throw ParamError(flag, path,
                       fmt::format("its times are not equally spaced (row {}: t = {})", k, t[k]));
  if (t.front() > 0.0 || t.back() < t_end - 1e-9 * (1.0 + t_end))
    throw ParamError(
        flag, path,
        fmt::format("covers t = {} ... {}, not the run's 0 ... {}", t.front(), t.back(), t_end));
  // end slopes from 4th-order one-sided differences (Boost's default estimate is cruder)
  const std::size_t m = r_ah.size() - 1;
  const double slope_left =
      (-25.0 * r_ah[0] + 48.0 * r_ah[1] - 36.0 * r_ah[2] + 16.0 * r_ah[3] - 3.0 * r_ah[4])
      / (12.0 * dt);
  const double slope_right = (25.0 * r_ah[m] - 48.0 * r_ah[m - 1] + 36.0 * r_ah[m - 2]
                              - 16.0 * r_ah[m - 3] + 3.0 * r_ah[m - 4])
                             / (12.0 * dt);
  auto spline = std::make_shared<boost::math::interpolators::cardinal_cubic_b_spline<double>>(
      r_ah.begin(), r_ah.end(), t.front(), dt, slope_left, slope_right);
  return [spline](double time) { return (*spline)(time); };
}

long ah_every_steps(const Params& p) {
  if (p.ah_every == "substage")
    return 0;
  if (p.ah_every == "step")
    return 1;
  return parse_decimal<long>(p.ah_every).value(); // validated
}

} // namespace gbssn1d
