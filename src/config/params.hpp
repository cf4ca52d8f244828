// All run parameters in one struct, with defaults, and their validation.
#pragma once

#include "config/choices.hpp"
#include "evolution/evolution_config.hpp"

#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace gbssn1d {

/// The typed configuration's defaults, which the parameters below take as theirs (one source).
inline const EvolutionConfig& evolution_defaults() {
  static const EvolutionConfig config;
  return config;
}

/// Flags as the user gives them; numbers default to the typed configuration's values, except
/// where a flag's own convention differs (an unset eta or norm-rmax stands for a rule resolved
/// against M and rmax, an unset ah-tmax for no limit; the areal norm windows are in units of
/// M; a choice is its enum: config/choices.hpp). A flag whose default is a rule is an optional,
/// never a sentinel value: any number the user gives is validated as that number.
struct Params {
  // grid
  int N = static_cast<int>(evolution_defaults().grid.N);
  double rmax = evolution_defaults().grid.rmax;
  GridChoice grid = RadialGrid::sinh; ///< uniform | sinh | boxes
  /// --grid boxes: refinement levels; unset: levels_rule (resolve())
  std::optional<int> levels;
  /// boxes: rk-stages | dense | quadratic
  TimeInterpChoice time_interp = mesh::TimeInterpolation::rk_stages;
  bool no_subcycling = false; ///< boxes: every level steps with the finest dt
  /// boxes: the fraction of a box's cells (outermost) blended towards its parent at every
  /// synchronisation, 0 ... 0.5 (mesh::StepperOptions::taper_cells = round(box_taper N));
  /// unset: 0.5 on two or more boxes, 0 on a single grid or one box (resolve();
  /// docs/horizon-shift-study.md Sec. 6.6)
  std::optional<double> box_taper;
  /// boxes: only boxes reaching beyond this radius / M are tapered
  double box_taper_from =
      evolution_defaults().stepping.taper_min_extent / evolution_defaults().initial_data.M;
  /// innermost cell width of the sinh grid at N = sinh_reference_N (M)
  double dr_inner = evolution_defaults().grid.dr_inner;
  // initial data
  /// wormhole | maximal-trumpet | 1log-trumpet | flat
  InitialDataChoice id = InitialDataKind::wormhole;
  double M = evolution_defaults().initial_data.M;
  LapseChoice lapse0 = InitialLapse::precollapsed; ///< one | precollapsed (wormhole)
  // formulation (Sec. 17): Z4c's constraint damping kappa1 (1/length) and kappa2
  FormulationChoice formulation = Formulation::bssn; ///< bssn | z4c
  VolumeChoice gbssn_volume = Volume::lagrangian;    ///< BSSN's: lagrangian | eulerian
  /// unset: 0.02/M with Z4c (resolve(), kappa1_rule); left unset with BSSN
  std::optional<double> kappa1;
  double kappa2 = evolution_defaults().rhs.z4c.kappa2;
  /// Z4c: kappa1 near the hole (areal radius below ~6 M, where the cell resolves it); unset:
  /// 1/M with Z4c (kappa1_hole_rule), left unset with BSSN; 0: kappa1 everywhere
  std::optional<double> kappa1_hole;
  bool z4c_lapse_adm = false; ///< Z4c: the lapse driven by the ADM K instead of K-hat (study)
  // matter (Sec. 19): a massless scalar field, its time-symmetric Gaussian pulse
  MatterChoice matter = Matter::none; ///< none | scalar
  double scalar_amp = evolution_defaults().initial_data.scalar.amplitude;
  double scalar_r0 = evolution_defaults().initial_data.scalar.r0;
  double scalar_width = evolution_defaults().initial_data.scalar.width;
  /// the areal radii (in M), comma-separated, of the spheres whose Misner-Sharp mass and energy
  /// flux the series records (flux_radii()); empty: none
  std::string flux_R;
  // gauge
  /// Gamma-driver damping; unset: 2/M, or 1/M for a shrink of wormhole data (resolve())
  std::optional<double> eta;
  bool advective_shift = false;
  bool non_advective_lapse = false;
  /// gamma-driver | zero (beta = 0 for all time: (G2) with xi = 0)
  ShiftChoice shift = ShiftCondition::gamma_driver;
  // numerics
  /// dt = cfl x smallest spacing, on every grid (docs/horizon-shift-study.md Sec. 11; boxes
  /// stepped at 0.25 until their errors were measured the same at 0.5)
  double cfl = evolution_defaults().stepping.cfl;
  double ko_sigma = evolution_defaults().rhs.ko_sigma;
  int fd_order = evolution_defaults().grid.fd_order; ///< 2 | 4 | 6 | 8
  UpwindChoice upwind = fd::Upwind::lopsided;        ///< lopsided | biased (fd::Upwind)
  /// chi is raised to at least this after every RK4 step (0: off)
  double chi_floor = evolution_defaults().chi_floor;
  // time
  double tmax = evolution_defaults().tmax;
  double dt_series = evolution_defaults().dt_series;
  double dt_profiles = evolution_defaults().dt_profiles;
  /// simulated time between checkpoints (0: only on a signal)
  double checkpoint_every = evolution_defaults().checkpoint_every;
  // diagnostics
  double norm_rmin = evolution_defaults().norms.rmin;
  std::optional<double> norm_rmax; ///< unset: min(10 M, rmax / 2) (resolve())
  double norm_Rmin = 2.5;  ///< areal-radius window of the *_R norms, in M (the same place in
  double norm_Rmax = 12.0; ///< every gauge): norm-Rmin M <= R <= norm-Rmax M
  double norm_Rint = 1.8;  ///< interior window: R <= norm-Rint M inside the horizon
  // apparent horizon and the horizon-adjusting shift (Sec. 6, Sec. 14)
  double rahA =
      evolution_defaults().rhs.horizon_shift.A; ///< strength A of beta_H (0: no horizon shift)
  double rah0 =
      evolution_defaults().rhs.horizon_shift.h; ///< desired coordinate radius h of the horizon (M)
  double rah_width =
      evolution_defaults().rhs.horizon_shift.width; ///< w in f(r) = (r/w) / (1 + (r/w)^2) (M)
  /// T of the strength ramp A (1 - exp(-(t/T)^2)) (M)
  double rah_ramp = evolution_defaults().rhs.horizon_shift.ramp;
  /// beta_H vanishes by rah_rcut (see rah_taper); unset: rmax/2 (resolve(), with the
  /// horizon shift on)
  std::optional<double> rah_rcut;
  /// quartic | step (HorizonShiftParams::Taper); unset: quartic when rahA != 0 (resolve()),
  /// so that config.toml records it and a run made with another taper is told apart
  std::optional<TaperChoice> rah_taper;
  /// auto | rational | rational3 | gauss | gauss3
  ProfileChoice rah_profile = ShiftProfile::automatic;
  NormalChoice rah_normal = ShiftNormal::conformal; ///< conformal | unit | smooth
  /// chi_s of the smooth normal sqrt((chi + chi_s)/a)
  double rah_chi_smooth = evolution_defaults().rhs.horizon_shift.chi_smooth;
  std::string rah_hAH_file; ///< open loop: h_AH(t) from columns t, r_ah of a file
  /// beta_GD d_r Delta^r in B's driver
  DriverStencilChoice driver_advection = AdvectionStencil::matched;
  StencilChoice delta_advection = AdvectionStencil::upwind_full; ///< beta d_r Delta^r in (E6)
  AhEvery ah_every = SearchEvery::substage; ///< substage | extrapolated | step | n (every n steps)
  /// T: a search after the first step of the hierarchy at or past each multiple of T of
  /// evolution time, h_AH held in between (the same hold for every resolution); unset: --ah-every
  std::optional<double> ah_interval;
  double ah_tmin =
      evolution_defaults().horizon_search.t_min; ///< searches are made for ah-tmin <= t ...
  std::optional<double> ah_tmax;                 ///< ... <= ah-tmax; unset: until the end
  double ah_tol =
      evolution_defaults().horizon_search.finder.tolerance; ///< root-finder tolerance in r (M)
  /// consistent | no-shift-derivatives | driver-full-shift | midstep-update (study only)
  VariantChoice rah_variant = ShiftVariant::consistent;
  // output
  std::string out;
  bool force = false;
};

/// A parameter refused, with the flag it came from: "--rmax = -3 is invalid: must be > 0".
/// A value as an error message shows it: whole up to 200 bytes, else its first 100 bytes and
/// its length (a value of a million digits is not echoed whole).
inline std::string shown_value(const std::string& value) {
  if (value.size() <= 200)
    return value;
  return value.substr(0, 100) + "... (" + std::to_string(value.size()) + " bytes)";
}

/// A message on one line: its control characters (a newline or tab in a value from a config
/// file or a quoted argument) as \xNN, as printable() writes them; other bytes as they are.
inline std::string one_line(const std::string& text) {
  static constexpr char hex[] = "0123456789abcdef";
  std::string out;
  for (const char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if (c < 0x20 || c == 0x7f)
      out += std::string("\\x") + hex[c >> 4] + hex[c & 0xf];
    else
      out += ch;
  }
  return out;
}

class ParamError : public std::runtime_error {
public:
  ParamError(const std::string& flag, const std::string& value, const std::string& why)
      : std::runtime_error(one_line(flag + " = " + shown_value(value) + " is invalid: " + why)),
        flag_(flag) {}
  /// "flag: message", for errors that are not about one value.
  ParamError(const std::string& flag, const std::string& message)
      : std::runtime_error(one_line(flag + ": " + message)), flag_(flag) {}
  const std::string& flag() const { return flag_; }

private:
  std::string flag_;
};

/// The Z4c equations: --kappa1 and --kappa2 act only then.
inline bool z4c_on(const Params& p) {
  return p.formulation == Formulation::z4c;
}

/// The scalar field is evolved: the --scalar-* flags act only then.
inline bool scalar_on(const Params& p) {
  return p.matter == Matter::scalar;
}

/// The horizon-adjusting shift is on: a strength A != 0. The --rah-* flags act only then.
inline bool shift_on(const Params& p) {
  return p.rahA != 0.0;
}

/// h_AH(t) comes from --rah-hAH-file (open loop, no searches steer beta_H): the shift is on and
/// a file is named.
inline bool uses_hAH_file(const Params& p) {
  return shift_on(p) && !p.rah_hAH_file.empty();
}

/// The most spheres --flux-R takes (two columns each in timeseries.dat).
inline constexpr std::size_t max_flux_spheres = 16;
/// --flux-R's areal radii, in its order: each a finite number > 0 (in M), none twice, at most
/// max_flux_spheres; ParamError (--flux-R) otherwise. Empty text: none.
std::vector<double> flux_radii(const Params& p);

/// A horizon shift that shrinks the horizon of wormhole data (rahA != 0, rah0 below the
/// standard 0.8304 M): with eta = 2/M the Gamma-driver does not settle on wormhole data and such
/// runs go non-finite after 100-200 M; eta = 1/M holds them (docs/horizon-shift-study.md,
/// Sec. 4.2 and Sec. 9), so it is their default.
bool shrinks_wormhole(const Params& p);

/// The default number of boxes: the most levels whose finest box still reaches r = 4 M,
/// 1 + floor(log2(rmax / 4M)), at least 2 (rmax 128: 6 levels; rmax 1024: 9).
int levels_rule(double rmax, double M);

/// A run's parameters with every rule default resolved, once (resolve()): the type that
/// validate(), warnings(), the same-run key and the conversions into the evolution's
/// configuration take. Its Params are the flags as config.toml records them (a rule's value
/// filled in where the rule applies, e.g. eta always, kappa1 with Z4c only); the values the
/// rules give are read through the accessors below, numbers on every grid and formulation.
/// They hide the optional flags of the same names, so that a resolved parameter is never read
/// as unset nor its rule applied a second time. Change a flag on a Params and resolve again.
class ResolvedParams : public Params {
public:
  /// The flags as config.toml records them.
  const Params& flags() const { return *this; }
  int levels() const { return levels_; }          ///< 1 on a single grid
  double box_taper() const { return box_taper_; } ///< 0 on a single grid and one box
  double eta() const { return eta_; }
  double kappa1() const { return kappa1_; }           ///< with BSSN too, where nothing reads it
  double kappa1_hole() const { return kappa1_hole_; } ///< likewise
  double norm_rmax() const { return norm_rmax_; }
  /// beta_H vanishes by this radius: rmax/2 with the shift on, infinity without (unless given)
  double rah_rcut() const { return rah_rcut_; }
  TaperChoice rah_taper() const { return rah_taper_; }

private:
  friend ResolvedParams resolve(Params p);
  explicit ResolvedParams(const Params& flags) : Params(flags) {}
  int levels_ = 1;
  double box_taper_ = 0.0;
  double eta_ = 0.0;
  double kappa1_ = 0.0;
  double kappa1_hole_ = 0.0;
  double norm_rmax_ = 0.0;
  double rah_rcut_ = 0.0;
  TaperChoice rah_taper_ = Taper::quartic;
};

/// The parameters with the defaults that depend on other parameters resolved (eta = 2/M,
/// Z4c's kappa1 and kappa1-hole, norm-rmax, the boxes' levels and taper, the shift's cut-off,
/// taper and auto profile): the rules' values, each computed here only. Throws ParamError for
/// a value the rule it resolves would drop (--rah-width with --rah-profile auto and the shift
/// on). Validates nothing else (validate()).
ResolvedParams resolve(Params p);

/// Z4c with its constraint damping on somewhere (kappa1 > 0, or kappa1 raised near the hole).
inline bool damped_z4c(const ResolvedParams& p) {
  return z4c_on(p) && (p.kappa1() > 0.0 || p.kappa1_hole() > 0.0);
}

/// Throws ParamError naming the first bad parameter. Reads nothing from disk, writes nothing.
void validate(const ResolvedParams& p);

/// Valid but known-bad combinations, each a sentence for stderr (the run goes ahead).
std::vector<std::string> warnings(const ResolvedParams& p);

// Conversions of the validated parameters into the typed pieces the code uses.
/// The evolution's configuration; may read --rah-hAH-file (ParamError if it cannot).
EvolutionConfig evolution_config(const ResolvedParams& p);
GridSpec grid_spec(const Params& p);
InitialDataParams initial_data_params(const Params& p);

/// h_AH(t) read from the columns `t` and `r_ah` of a gbssn1d output file (horizon.dat or
/// timeseries.dat), as a cubic B-spline in t (C2, so that RK4 sees a smooth function). Throws
/// ParamError (--rah-hAH-file) if the file cannot be read, its times are not equally spaced,
/// it has no horizon at some time, or it ends before `t_end`.
std::function<double(double)> load_prescribed_horizon(const std::string& path, double t_end);

/// The largest step a level takes: the stability limit of the damping terms, rate dt <= 1
/// (RK4's limit for d_t u = -rate u is 2.78; Schnetter 2010, CQG 27:167001), which coarse
/// boxes would otherwise exceed (their CFL step grows with their spacing, a damping's limit does
/// not). `rate` is damping_rate().
double dt_max_of_damping(double rate);

/// The fastest damping of the run's equations, 1/length: the Gamma-driver's eta, and with Z4c
/// the constraint damping's alpha kappa1 (2 + kappa2) of Theta and 2 alpha kappa1 of Delta^r
/// (alpha <= 1; equations document Sec. 17).
double damping_rate(const ResolvedParams& p);

/// How often h_AH is searched for: at every RK substage (0), or every n >= 1 full steps.
long ah_every_steps(const Params& p);

} // namespace gbssn1d
