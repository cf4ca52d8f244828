// What configures the equations: the gauge (1+log slicing and Gamma-driver, Sec. 4) with its
// characteristic speeds, the differencing of the advection terms, dissipation and the
// horizon-adjusting shift. Parameters only, so that configurations include them without the
// point-wise equations (gbssn/equations.hpp, gbssn/gauge.hpp, gbssn/horizon_shift.hpp).
#pragma once

#include "core/formulation.hpp"
#include "core/wave.hpp"
#include "fd/stencils.hpp"
#include "gbssn/horizon_shift_params.hpp"

#include <cmath>

namespace gbssn1d {

/// The gauge: 1+log slicing (G1) and the Gamma-driver shift (G2)-(G3), one type with
/// defaulted parameters (its equations: gbssn/gauge.hpp). Its characteristic speeds at infinity
/// set the Sommerfeld speeds of the outer boundary (Sec. 8) through each variable's Wave in the
/// registry.
struct Gauge {
  /// (G1) d_t alpha = [beta d_r alpha] - mu_L alpha K; 1+log slicing is mu_L = 2
  /// (f(alpha) = mu_L / alpha in d_t alpha = -alpha^2 f(alpha) K).
  struct Slicing {
    double mu_L = 2.0;
    bool advective = true; ///< with the bracket beta d_r alpha
  };
  /// (G2) d_t beta = xi B [+ beta d_r beta],
  /// (G3) d_t B = d_t Delta^r - eta B [+ beta d_r B - beta d_r Delta^r].
  struct GammaDriver {
    double xi = 0.75;
    double eta = 2.0;       ///< damping (1/length); 2/M by default (config)
    bool advective = false; ///< with the brackets (moving-puncture shift)
  };
  Slicing slicing;
  GammaDriver shift;

  /// Speed at infinity (alpha, chi, a, b -> 1) of each characteristic family: the slicing mode
  /// sqrt(f(alpha) alpha^2 gamma^rr) = sqrt(mu_L) (Sec. 8), the Gamma-driver's longitudinal
  /// mode sqrt(4 xi / 3) (Alcubierre, Introduction to 3+1 Numerical Relativity, ch. 4), light 1.
  double speed(Wave wave) const {
    switch (wave) {
    case Wave::slicing:
      return std::sqrt(slicing.mu_L);
    case Wave::shift:
      return std::sqrt(4.0 * shift.xi / 3.0);
    case Wave::light:
    default:
      return 1.0;
    }
  }
};

/// How a term beta d_r Delta^r is differenced.
enum class AdvectionStencil {
  upwind_gd,   ///< lopsided towards where beta_GD comes from
  upwind_full, ///< lopsided towards where the full shift beta_GD + beta_H comes from
  centred,     ///< centred, of the grid's order
  /// B's driver only: Delta^r's own advection term of (E6) (its stencil, with the full shift)
  /// minus beta_H d_r Delta^r centred. Then B - Delta^r carries no lopsided stencil, as with the
  /// plain Gamma-driver, where the two terms are the same; a lopsided stencil of beta_GD in B's
  /// driver alone grows at the grid scale at a rate ~ |beta_H| / dr (docs/hyperbolicity.py;
  /// docs/horizon-shift-study.md, Sec. 12). Without the horizon shift it is upwind_full.
  matched,
};

/// The differencing of the two beta d_r Delta^r terms: the one inside d_t Delta^r|beta_GD that
/// drives B (G3)/(H2), and Delta^r's own advection in (E6).
struct AdvectionParams {
  AdvectionStencil driver = AdvectionStencil::matched;
  AdvectionStencil delta = AdvectionStencil::upwind_full;
};

/// Z4c's constraint damping (Sec. 17, (Z2)-(Z4)): kappa1 (1/length) damps Theta and
/// G^r = Delta^r - Delta_gamma^r at the rate ~ alpha kappa1; kappa2 weights the damping of
/// Theta's part in K-hat (kappa2 = 0: the standard choice, Bernuzzi & Hilditch 2010). And what
/// drives the 1+log lapse: K-hat (Z4c's standard, (G1)), or for the study the ADM trace
/// K = K-hat + 2 Theta, BSSN's slicing.
///
/// kappa1 may rise near the hole (docs/z4c-study.md, Sec. 9): kappa1(R) = kappa1 + (kappa1_near -
/// kappa1) / (1 + (R/hole_radius)^4) in the areal radius R (the same place in every gauge), with
/// kappa1_near = max(kappa1, min(kappa1_hole, kappa1_dr_max / dr)) at a point of cell width dr:
/// never above what the cell resolves (grid-scale noise grows where kappa1 dr > 0.3, Sec. 4), so
/// that the local damping rate alpha kappa1 (2 + kappa2) times an RK4 step stays below
/// (2 + kappa2) kappa1_dr_max cfl. kappa1_hole = 0 (or <= kappa1): kappa1 everywhere.
struct Z4cParams {
  double kappa1 = 0.02; ///< 0.02/M at M = 1 (config: kappa1_rule)
  double kappa2 = 0.0;
  bool lapse_adm_K = false;
  double kappa1_hole = 1.0; ///< 1/M at M = 1 (config: kappa1_hole_rule)
  double hole_radius = 6.0; ///< 6 M at M = 1: the areal radius where kappa1 is half-way up
  static constexpr double kappa1_dr_max = 0.2;
};

struct RhsParams {
  Formulation formulation = Formulation::bssn;
  Matter matter = Matter::none; ///< the matter evolved besides (Sec. 19)
  Z4cParams z4c;                ///< Z4c only
  Gauge gauge;
  double ko_sigma = 0.1; ///< Kreiss-Oliger strength (0 switches dissipation off)
  AdvectionParams advection;
  fd::Upwind upwind = fd::Upwind::lopsided; ///< the upwind pair of every advection term
  HorizonShiftParams horizon_shift;
};

} // namespace gbssn1d
