// The rows of the flag table (config/flag_table.hpp): every evolve flag's name, member of
// Params, --help group and text, where it acts and the values it accepts, in the order of
// --help and config.toml; and the rules its unset values stand for.
#include "config/flag_table.hpp"

#include "config/param_rules.hpp"
#include "evolution/evolution_config.hpp"

namespace gbssn1d {

namespace {

/// The grid and the initial data.
std::vector<ParamSpec> grid_and_data_specs() {
  return {
      {"N", &Params::N, "Grid", "number of cells"},
      {"rmax", &Params::rmax, "Grid", "outer radius", Acts::always, above(0.0)},
      {"grid", &Params::grid, "Grid",
       "radial grid: uniform | sinh | boxes (box-in-box mesh refinement: --levels boxes, box l "
       "covering r <= rmax/2^l with --N cells, Berger-Oliger subcycling)"},
      {"levels", &Params::levels, "Grid",
       "--grid boxes: number of boxes (refinement levels); default max(2, 1 + "
       "floor(log2(rmax/4M)))",
       Acts::on_boxes, within(1.0, levels_max)},
      {"time-interp", &Params::time_interp, "Grid",
       "--grid boxes: a fine box's boundary in time: rk-stages (RK4 stage values of the coarse "
       "step, 4th order) | dense (RK4 dense output) | quadratic (three coarse time levels with "
       "buffer zones, as Carpet and BAM)",
       Acts::on_boxes},
      {"no-subcycling", &Params::no_subcycling, "Grid",
       "--grid boxes: every box steps with the finest box's dt (no Berger-Oliger subcycling)",
       Acts::on_boxes},
      {"box-taper", &Params::box_taper, "Grid",
       "--grid boxes: the outermost fraction F of a fine box's cells (round(F N) cells) is "
       "relaxed smoothly towards its parent at every synchronisation (a tapered buffer that "
       "absorbs what the parent cannot carry), 0 ... 0.5; 0: off",
       Acts::with_tapered_boxes, within(0.0, 0.5, "a fraction of a box's cells")},
      {"box-taper-from", &Params::box_taper_from, "Grid",
       "--grid boxes: --box-taper only on the boxes that reach beyond this radius, in units "
       "of M",
       Acts::with_box_taper, at_least(0.0, "a radius in units of M")},
      {"dr-inner", &Params::dr_inner, "Grid",
       "innermost cell width of the sinh grid at N = 400; it fixes the map r(x), so at N "
       "cells every spacing is 400/N times that grid's (doubling --N halves every spacing)",
       Acts::on_sinh, above(0.0)},
      {"id", &Params::id, "Initial data",
       "wormhole | maximal-trumpet | 1log-trumpet | flat (Minkowski space; with --matter scalar "
       "the pulse alone)"},
      {"M", &Params::M, "Initial data", "black-hole mass", Acts::always, above(0.0)},
      {"lapse0", &Params::lapse0, "Initial data",
       "initial lapse of the wormhole: one | precollapsed", Acts::with_wormhole},
      {"matter", &Params::matter, "Matter",
       "none | scalar (a massless scalar field, G_ab = 8 pi T_ab: Phi and Pi = n^a d_a Phi "
       "evolved; docs/gbssn1d-equations.md Sec. 19); with --id flat or wormhole, --fd-order 4, "
       "--upwind lopsided"},
      {"scalar-amp", &Params::scalar_amp, "Matter",
       "A of the time-symmetric pulse Phi = A exp(-((r - r0)/w)^2), Pi = 0 (the conformal factor "
       "from the Hamiltonian constraint)",
       Acts::with_scalar, finite()},
      {"scalar-r0", &Params::scalar_r0, "Matter", "r0 of the pulse", Acts::with_scalar,
       at_least(0.0)},
      {"scalar-width", &Params::scalar_width, "Matter", "w of the pulse", Acts::with_scalar,
       above(0.0)},
      {"flux-R", &Params::flux_R, "Matter",
       "areal radii X (in M, comma-separated: 5,30) of spheres whose Misner-Sharp mass and "
       "outgoing energy flux the series records (columns m_R<X>, flux_R<X>; "
       "docs/gbssn1d-equations.md (S7))",
       Acts::with_scalar},
  };
}

/// The formulation, gauge, numerics, times and output cadences.
std::vector<ParamSpec> evolution_specs() {
  return {
      {"formulation", &Params::formulation, "Formulation",
       "bssn | z4c (Z4c: K-hat = K - 2 Theta and Theta evolved, constraint damping kappa1, "
       "kappa2; docs/gbssn1d-equations.md Sec. 17)"},
      {"gbssn-volume", &Params::gbssn_volume, "Formulation",
       "BSSN's volume choice (Brown 2009): lagrangian, d_t det(gbar) = 0 | eulerian, det(gbar) "
       "carried by the shift (docs/gbssn1d-equations.md Sec. 18); Z4c takes lagrangian"},
      {"kappa1", &Params::kappa1, "Formulation",
       "Z4c: constraint damping kappa1 (1/length, as --eta), >= 0: Theta and G^r decay at "
       "~ alpha kappa1; grid-scale noise grows where kappa1 x cell width > 0.3 "
       "(docs/z4c-study.md)",
       Acts::with_z4c, at_least(0.0, "a negative kappa1 makes the constraints grow")},
      {"kappa1-hole", &Params::kappa1_hole, "Formulation",
       "Z4c: kappa1 near the hole, >= --kappa1 or 0 (off): kappa1 rises towards it inside the "
       "areal radius 6 M, capped at 0.2/(cell width) (docs/z4c-study.md Sec. 9: the horizon "
       "mass's drift)",
       Acts::with_z4c, finite()},
      {"kappa2", &Params::kappa2, "Formulation",
       "Z4c: kappa2 > -1 weights Theta's damping in K-hat's equation (0: standard; it "
       "multiplies kappa1, so does nothing with --kappa1 0)",
       Acts::with_z4c_damping,
       above(-1.0, "the damping of Theta in Z4c's constraint subsystem needs it"),
       &at<&EvolutionConfig::rhs, &RhsParams::z4c, &Z4cParams::kappa2>},
      {"z4c-lapse-adm", &Params::z4c_lapse_adm, "Formulation",
       "Z4c, for the study: the 1+log lapse driven by the ADM K = K-hat + 2 Theta (BSSN's "
       "slicing) instead of K-hat",
       Acts::with_z4c, std::nullopt,
       &at<&EvolutionConfig::rhs, &RhsParams::z4c, &Z4cParams::lapse_adm_K>},
      {"eta", &Params::eta, "Gauge",
       "Gamma-driver damping eta (1/M); default 2/M, 1/M for a shrink of wormhole data "
       "(--rahA != 0, --rah0 < 0.8304 M)",
       Acts::always, at_least(0.0)},
      {"advective-shift", &Params::advective_shift, "Gauge",
       "add the advection brackets of (G2)/(G3) (moving-puncture shift)", Acts::always,
       std::nullopt,
       &at<&EvolutionConfig::rhs, &RhsParams::gauge, &Gauge::shift,
           &Gauge::GammaDriver::advective>},
      {"non-advective-lapse", &Params::non_advective_lapse, "Gauge",
       "1+log without advection: d_t alpha = -2 alpha K"},
      {"shift", &Params::shift, "Gauge",
       "the shift: gamma-driver ((G2)/(G3)) | zero (beta = 0 for all time: (G2) with xi = 0, B "
       "still driven but never reaching beta; with data of zero shift, --id flat or wormhole, "
       "and without --rahA)"},
      {"cfl", &Params::cfl, "Numerics",
       "dt = cfl * smallest spacing, in (0, 1] (measured: errors unchanged from 0.25 on every "
       "grid, boxes included; unstable from 0.8)"},
      {"ko-sigma", &Params::ko_sigma, "Numerics", "Kreiss-Oliger dissipation strength, in [0, 1]",
       Acts::always, within(0.0, 1.0), &at<&EvolutionConfig::rhs, &RhsParams::ko_sigma>},
      {"fd-order", &Params::fd_order, "Numerics",
       "order of the finite differences: 2 | 4 | 6 | 8 (derivatives, upwind advection, and "
       "dissipation of the (order+2)-th difference; boxes: 2 | 4 | 6)"},
      {"upwind", &Params::upwind, "Numerics",
       "stencil of every advection term beta d_r f: lopsided (order fd-order, as moving-puncture "
       "codes) | biased (order fd-order + 1, one point more upwind than downwind: at 4th order "
       "1.5-8 times lower errors from M/12 (horizon mass, H), but up to 7 times higher on a "
       "trumpet at M/8 and 1.5 times on a shrink to 0.6 M; docs/horizon-shift-study.md Sec. 7.4)"},
      {"chi-floor", &Params::chi_floor, "Numerics",
       "after every RK4 step chi is raised to at least this (0: off); wormhole data otherwise "
       "cross chi = 0 at the innermost cell during the lapse collapse",
       Acts::always, within_below(0.0, 1.0), &at<&EvolutionConfig::chi_floor>},
      {"tmax", &Params::tmax, "Time", "final time; 0 writes the initial data only", Acts::always,
       at_least(0.0), &at<&EvolutionConfig::tmax>},
      {"dt-series", &Params::dt_series, "Time", "time between rows of timeseries.dat", Acts::always,
       above(0.0), &at<&EvolutionConfig::dt_series>},
      {"dt-profiles", &Params::dt_profiles, "Time", "time between blocks of profiles.dat",
       Acts::always, above(0.0), &at<&EvolutionConfig::dt_profiles>},
      {"checkpoint-every", &Params::checkpoint_every, "Output",
       "simulated time between checkpoints in OUT/checkpoint.bin, for `gbssn1d resume OUT` "
       "(0: none; SIGTERM, SIGINT, SIGHUP, SIGUSR1 and SIGUSR2 always write one)",
       Acts::always, at_least(0.0, "0: off"), &at<&EvolutionConfig::checkpoint_every>},
  };
}

/// The norm windows.
std::vector<ParamSpec> diagnostics_specs() {
  return {
      {"norm-rmin", &Params::norm_rmin, "Diagnostics", "inner radius of the exterior norms",
       Acts::always, at_least(0.0), &at<&EvolutionConfig::norms, &NormWindows::rmin>},
      {"norm-rmax", &Params::norm_rmax, "Diagnostics",
       "outer radius of the exterior norms; default min(10 M, rmax/2)", Acts::always, finite()},
      {"norm-Rmin", &Params::norm_Rmin, "Diagnostics",
       "areal-radius window of the *_R norms: norm-Rmin M <= R (the same place in every gauge)",
       Acts::always, above(0.0)},
      {"norm-Rmax", &Params::norm_Rmax, "Diagnostics", "... R <= norm-Rmax M", Acts::always,
       finite()},
      {"norm-Rint", &Params::norm_Rint, "Diagnostics",
       "interior window of H_L2_int: areal radius R <= norm-Rint M, inside the horizon",
       Acts::always, above(0.0)},
  };
}

/// The horizon-adjusting shift: its strength, target, profile and stencils.
std::vector<ParamSpec> horizon_shift_specs() {
  return {
      {"rahA", &Params::rahA, "Horizon", "strength A of the horizon-adjusting shift (0: off)",
       Acts::always,
       at_least(0.0, "beta_H = f A (h_AH - h) s^r with A < 0 drives the horizon away from --rah0, "
                     "not towards it"),
       &at<&EvolutionConfig::rhs, &RhsParams::horizon_shift, &HorizonShiftParams::A>},
      {"rah0", &Params::rah0, "Horizon", "desired coordinate radius h of the horizon",
       Acts::with_shift, above(0.0)},
      {"rah-width", &Params::rah_width, "Horizon",
       "width w of f(r), for every --rah-profile but auto", Acts::with_shift, above(0.0)},
      {"rah-rcut", &Params::rah_rcut, "Horizon",
       "beta_H vanishes smoothly by rcut (see --rah-taper), before the outer boundary; default "
       "rmax/2 when --rahA != 0",
       Acts::with_shift, above(0.0)},
      {"rah-taper", &Params::rah_taper, "Horizon",
       "how beta_H vanishes before the outer boundary: quartic (beta_H x exp(-(2r/rcut)^4): 0.94 "
       "at rcut/4, 0.37 at rcut/2, 1e-7 at rcut; its derivatives are small enough for coarse "
       "boxes) | step (C-infinity step from 1 at rcut/2 to 0 at rcut; large derivatives: "
       "convergence lost on boxes with rmax 128); default quartic when --rahA != 0",
       Acts::with_shift},
      {"rah-ramp", &Params::rah_ramp, "Horizon",
       "T: the strength grows as rahA (1 - exp(-(t/T)^2)); 0: full strength from t = 0",
       Acts::with_shift, at_least(0.0, "0: no ramp"),
       &at<&EvolutionConfig::rhs, &RhsParams::horizon_shift, &HorizonShiftParams::ramp>},
      {"rah-profile", &Params::rah_profile, "Horizon",
       "f(r), q = r/w: auto (rational with w = 3 max(rah0, M) to stretch, rah0 >= 0.8304 M; gauss "
       "with "
       "w = 1 M to shrink; "
       "--rah-width is then not used) | rational q/(1+q^2) (published) | rational3 "
       "q^3/(1+q^4) | gauss (q/2)exp((1-q^2)/2) | gauss3 (q^3/2)exp(3(1-q^2)/2)",
       Acts::with_shift},
      {"rah-normal", &Params::rah_normal, "Horizon",
       "s^r: conformal 1/sqrt(a) (smooth at the puncture) | unit sqrt(chi/a) (published; "
       "~|r| at a trumpet's puncture) | smooth sqrt((chi+chi_s)/a)",
       Acts::with_shift},
      {"rah-chi-smooth", &Params::rah_chi_smooth, "Horizon",
       "chi_s of --rah-normal smooth: the kink of sqrt(chi) at the puncture is rounded where "
       "chi ~ chi_s",
       Acts::with_smooth_normal, above(0.0),
       &at<&EvolutionConfig::rhs, &RhsParams::horizon_shift, &HorizonShiftParams::chi_smooth>},
      {"rah-hAH-file", &Params::rah_hAH_file, "Horizon",
       "open loop: h_AH(t) from the t and r_ah columns of a horizon.dat (no searches)",
       Acts::with_shift},
      {"driver-advection", &Params::driver_advection, "Numerics",
       "stencil of beta_GD d_r Delta^r in B's driver: matched (Delta^r's own term minus beta_H "
       "d_r Delta^r centred: stable at every spacing) | upwind-gd (published; with the horizon "
       "shift it grows at the grid scale at a rate ~ |beta_H|/dr: a blow-up whose onset time "
       "falls with the spacing) | upwind-full | centred",
       Acts::with_driver_stencil},
      {"delta-advection", &Params::delta_advection, "Numerics",
       "stencil of beta d_r Delta^r in d_t Delta^r: upwind-full | upwind-gd | centred",
       Acts::with_delta_stencil},
  };
}

/// The horizon searches that steer the shift, its study variants, and the output folder.
std::vector<ParamSpec> horizon_search_specs() {
  return {
      {"ah-every", &Params::ah_every, "Horizon",
       "horizon search: substage (every RK stage), extrapolated (after every step, h_AH at the "
       "RK stages from the last four radii; on two or more boxes the same as substage), step, "
       "or a number of steps (held in between); with --rahA != 0 and no --rah-hAH-file",
       Acts::with_searches},
      {"ah-interval", &Params::ah_interval, "Horizon",
       "T: a horizon search every T of evolution time (after the first step of the hierarchy at "
       "or past each multiple of T), h_AH held in between: the same hold at every resolution, as "
       "a 3D code calls its finder; refused with --ah-every other than substage",
       Acts::with_searches, above(0.0)},
      {"ah-tmin", &Params::ah_tmin, "Horizon", "no horizon searches for the shift before this time",
       Acts::with_searches, at_least(0.0),
       &at<&EvolutionConfig::horizon_search, &HorizonSearchSettings::t_min>},
      {"ah-tmax", &Params::ah_tmax, "Horizon", "no horizon searches for the shift after this time",
       Acts::with_searches, finite()},
      {"ah-tol", &Params::ah_tol, "Horizon",
       "root-finder tolerance of the horizon radius; at most 1e-3 x the smallest cell width",
       Acts::always, above(0.0),
       &at<&EvolutionConfig::horizon_search, &HorizonSearchSettings::finder,
           &HorizonFinderParams::tolerance>},
      {"rah-variant", &Params::rah_variant, "Horizon",
       "consistent (the method); for the study only: no-shift-derivatives, "
       "no-shift-second-derivatives, delta-rhs-from-gd, driver-full-shift, midstep-update, "
       "box-substage (boxes: each box its own latest h_AH)",
       Acts::with_shift},
      {"out", &Params::out, "Output", "output directory (refused if it exists and is not empty)"},
      {"force", &Params::force, "Output", "write into an existing non-empty --out"},
  };
}

} // namespace

/// Every evolve parameter, in the order of --help and config.toml.
const std::vector<ParamSpec>& param_specs() {
  static const std::vector<ParamSpec> specs = [] {
    std::vector<ParamSpec> all;
    for (auto group : {grid_and_data_specs, evolution_specs, diagnostics_specs, horizon_shift_specs,
                       horizon_search_specs}) {
      const std::vector<ParamSpec> specs = group();
      all.insert(all.end(), specs.begin(), specs.end());
    }
    return all;
  }();
  return specs;
}

/// The rule a flag's unset value stands for, shown by --help as its default.
const std::map<std::string, std::string>& default_rules() {
  static const std::map<std::string, std::string> rules{
      {"eta", "2/M (1/M: wormhole shrinks)"},
      {"kappa1", "0.02/M"},
      {"kappa1-hole", "1/M"},
      {"norm-rmax", "min(10 M, rmax/2)"},
      {"ah-tmax", "none"},
      {"ah-interval", "none (--ah-every)"},
      {"rah-taper", "quartic"},
      {"levels", "max(2, 1 + floor(log2(rmax/4M)))"},
      {"box-taper", "0.5 on two or more boxes"}};
  return rules;
}

} // namespace gbssn1d
