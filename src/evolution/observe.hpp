// What a run measures of its levels' state, apart from evolving it: the derived profiles (H,
// M_r, G_r, R, Theta_+) per level and composite, values at a radius, every marginal surface,
// the physical-range check, and the time-series row with its own diagnostic right-hand side
// (engrenage's diagnostics module, GRChombo's post-timestep hooks). Nothing here changes the
// evolved state or the evolution's RHS counts.
#pragma once

#include "diagnostics/constraints.hpp"
#include "evolution/evolution_config.hpp"
#include "gbssn/rhs.hpp"
#include "horizon/apparent_horizon.hpp"
#include "io/output.hpp"
#include "mesh/composite.hpp"

#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace gbssn1d {

/// Thrown when the state stops being finite, or chi or alpha leaves its physical range
/// (check_physical_range); says what, where and when.
class NonFiniteError : public std::runtime_error {
public:
  NonFiniteError(double t, double r, const std::string& var);
  /// A finite value outside its range: "`var` = value at r, t: `why`".
  NonFiniteError(double t, double r, const std::string& var, double value, const std::string& why);
  double t, r;
  std::string var;
};

/// Throws NonFiniteError at the first non-finite value of any level's state at time t, or a
/// chi <= 0, or an alpha outside [alpha_min, alpha_max] (on the interior).
void check_physical_range(const mesh::MeshLayout& layout, const std::vector<State>& levels,
                          double t, double alpha_min, double alpha_max);

/// A norm window (NormWindows) that holds no point, so that its norms are NaN: the flags that
/// set it, and what is empty (with the columns it leaves without a value).
struct EmptyNormWindow {
  std::string flags, what;
};
/// The windows of `w` empty on the composite grid `g` (the coordinate window) and on the outer
/// sheet of its areal radius R_areal (the areal window; as l2_norm_areal's rule), for the run's
/// start: a window empty there is empty for good (coordinate), or until the gauge moves the
/// grid's R across it (areal). The interior window is not checked: it is empty on a wormhole's
/// other sheet until the puncture forms.
std::vector<EmptyNormWindow> empty_norm_windows(const Grid& g, std::span<const double> R_areal,
                                                const NormWindows& w);

/// The spheres of --flux-R (areal radii X M, `spheres` in units of M) that do not lie on the
/// outer sheet of the areal radius R_areal (sphere_at_areal_radius's rule), so that their
/// columns are NaN, for the run's start (as empty_norm_windows).
std::vector<EmptyNormWindow> absent_spheres(std::span<const double> R_areal,
                                            std::span<const double> spheres, double M);

/// H, M_r, G_r, R, Theta_+ on every level's interior.
std::vector<DerivedProfiles> level_profiles(const mesh::MeshLayout& layout,
                                            const std::vector<State>& levels);
/// Their composite over [0, rmax] (each r from the finest level covering it).
DerivedProfiles composite_profiles(const mesh::MeshLayout& layout, const mesh::Composite& composite,
                                   const std::vector<DerivedProfiles>& levels);
/// A variable at radius r (6-point Lagrange on the finest level that covers r).
double value_at_radius(const mesh::MeshLayout& layout, const std::vector<State>& levels, Var v,
                       double r);
/// H at radius r from level profiles.
double H_at_radius(const mesh::MeshLayout& layout, const std::vector<DerivedProfiles>& levels,
                   double r);
/// A sphere of fixed areal radius in the time series (the scalar field's columns m_R<X> and
/// flux_R<X>): its coordinate radius, the Misner-Sharp mass inside it (T4) and the energy that
/// leaves through it per unit coordinate time (S7).
struct SphereSample {
  double r, m, flux;
};
/// The outermost sphere of areal radius R on the outer sheet of the composite profiles `d` (of a
/// state with matter): bracketed there, then found as the root of R's 6-point interpolant on the
/// finest level that covers it, where m and the flux are interpolated too. NaN, all three, where
/// no such sphere lies on the grid: R beyond the outermost point's areal radius, or below the
/// throat's (wormhole, trumpet) or the innermost point's (a regular centre). `computed` holds the
/// levels' profiles computed so far (one entry per level, filled as needed, so that the spheres
/// of one row compute each level's once); on a single grid `d` is the level's.
SphereSample sphere_at_areal_radius(const mesh::MeshLayout& layout,
                                    const std::vector<State>& levels, const DerivedProfiles& d,
                                    const Grid& composite, double R,
                                    std::vector<std::optional<DerivedProfiles>>& computed);
/// Every marginal surface at time t, each from the finest level covering it; a
/// HorizonFinderError gets t added.
HorizonSearch find_all_horizons(const mesh::MeshLayout& layout, const std::vector<State>& levels,
                                const HorizonFinderParams& finder, double t);

/// The time-series row of a state: norms of the constraints, the horizon, and d_t alpha from a
/// right-hand side of its own per level (never searching; its h_AH is the evolution's), so
/// that the evolution's RHS evaluations stay countable.
class SeriesDiagnostics {
public:
  SeriesDiagnostics(const EvolutionConfig& config, const mesh::MeshLayout& layout);
  SeriesRow row(const std::vector<State>& levels, double t, const DerivedProfiles& d,
                const HorizonSearch& found, const std::optional<double>& h_AH,
                const mesh::Composite& composite);

private:
  const EvolutionConfig& config_;
  const mesh::MeshLayout& layout_;
  std::vector<GbssnRhs> rhs_;
  std::vector<State> dudt_; ///< per level: scratch
};

} // namespace gbssn1d
