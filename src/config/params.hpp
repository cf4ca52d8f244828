// All run parameters in one struct, with defaults, and their validation.
#pragma once

#include "evolution/evolution_config.hpp"

#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace gbssn1d {

/// The value of Params::eta that stands for its default, 2/M (resolve_defaults).
inline constexpr double eta_default = -1.0;

struct Params {
  // grid
  int N = 400;
  double rmax = 100.0;
  std::string grid = "sinh"; ///< uniform | sinh
  double dr_inner = 0.02;    ///< innermost cell width of the sinh grid at N = sinh_reference_N (M)
  // initial data
  std::string id = "wormhole"; ///< wormhole | maximal-trumpet | 1log-trumpet
  double M = 1.0;
  std::string lapse0 = "precollapsed"; ///< one | precollapsed (wormhole)
  // gauge
  double eta = eta_default; ///< Gamma-driver damping; eta_default stands for 2/M
  bool advective_shift = false;
  bool non_advective_lapse = false;
  // numerics
  double cfl = 0.25;
  double ko_sigma = 0.1;
  double chi_floor = 1e-5; ///< chi is raised to at least this after every RK4 step (0: off)
  // time
  double tmax = 10.0;
  double dt_series = 0.25;
  double dt_profiles = 5.0;
  double checkpoint_every = 0.0; ///< simulated time between checkpoints (0: only on a signal)
  // diagnostics
  double norm_rmin = 1.0;
  double norm_rmax = -1.0; ///< < 0 means min(10 M, rmax / 2)
  double norm_Rmin = 2.5;  ///< areal-radius window of the *_R norms, in M (the same place in
  double norm_Rmax = 12.0; ///< every gauge): norm-Rmin M <= R <= norm-Rmax M
  double norm_Rint = 1.8;  ///< interior window: R <= norm-Rint M inside the horizon
  // apparent horizon and the horizon-adjusting shift (Sec. 6, Sec. 14)
  double rahA = 0.0;                          ///< strength A of beta_H (0: no horizon shift)
  double rah0 = 0.89;                         ///< desired coordinate radius h of the horizon (M)
  double rah_width = 1.0;                     ///< w in f(r) = (r/w) / (1 + (r/w)^2) (M)
  double rah_ramp = 0.0;                      ///< T of the strength ramp A (1 - exp(-(t/T)^2)) (M)
  std::string rah_profile = "auto";           ///< auto | rational | rational3 | gauss | gauss3
  std::string rah_normal = "conformal";       ///< conformal | unit | smooth
  double rah_chi_smooth = 0.05;               ///< chi_s of the smooth normal sqrt((chi + chi_s)/a)
  std::string rah_hAH_file;                   ///< open loop: h_AH(t) from columns t, r_ah of a file
  std::string driver_advection = "upwind-gd"; ///< beta_GD d_r Delta^r in B's driver
  std::string delta_advection = "upwind-full"; ///< beta d_r Delta^r in (E6)
  std::string ah_every = "substage";           ///< substage | step | n (every n steps)
  double ah_tmin = 0.0;                        ///< searches are made for ah-tmin <= t ...
  double ah_tmax = -1.0;                       ///< ... <= ah-tmax; < 0: until the end
  double ah_tol = 1e-12;                       ///< root-finder tolerance in r (M)
  /// consistent | no-shift-derivatives | driver-full-shift | midstep-update (study only)
  std::string rah_variant = "consistent";
  // output
  std::string out;
  bool force = false;
};

/// A parameter refused, with the flag it came from: "--rmax = -3 is invalid: must be > 0".
class ParamError : public std::runtime_error {
public:
  ParamError(const std::string& flag, const std::string& value, const std::string& why)
      : std::runtime_error(flag + " = " + value + " is invalid: " + why), flag_(flag) {}
  /// "flag: message", for errors that are not about one value.
  ParamError(const std::string& flag, const std::string& message)
      : std::runtime_error(flag + ": " + message), flag_(flag) {}
  const std::string& flag() const { return flag_; }

private:
  std::string flag_;
};

/// Fill the defaults that depend on other parameters (eta = 2/M, norm-rmax).
void resolve_defaults(Params& p);

/// Throws ParamError naming the first bad parameter. Reads nothing from disk, writes nothing.
void validate(const Params& p);

/// Valid but known-bad combinations, each a sentence for stderr (the run goes ahead).
std::vector<std::string> warnings(const Params& p);

/// Throws ParamError if --out cannot be used (exists and is not an empty directory, unless
/// --force; not writable). Creates nothing.
void validate_output_dir(const Params& p);

/// create_directories(dir), or ParamError naming `flag` and the reason (no filesystem_error
/// text leaks out).
void create_output_dir(const std::string& flag, const std::filesystem::path& dir);

// Conversions of the validated (and resolved) parameters into the typed pieces the code uses.
/// The evolution's configuration; may read --rah-hAH-file (ParamError if it cannot).
EvolutionConfig evolution_config(const Params& p);
GridSpec grid_spec(const Params& p);
InitialDataParams initial_data_params(const Params& p);
RhsParams rhs_params(const Params& p);

/// h_AH(t) read from the columns `t` and `r_ah` of a gbssn1d output file (horizon.dat or
/// timeseries.dat), as a cubic B-spline in t (C2, so that RK4 sees a smooth function). Throws
/// ParamError (--rah-hAH-file) if the file cannot be read, its times are not equally spaced,
/// it has no horizon at some time, or it ends before `t_end`.
std::function<double(double)> load_prescribed_horizon(const std::string& path, double t_end);

/// How often h_AH is searched for: at every RK substage (0), or every n >= 1 full steps.
long ah_every_steps(const Params& p);

} // namespace gbssn1d
