// The typed configuration of one evolution: what to evolve (grid, initial data, equations with
// their gauge and horizon shift) and how (time step, output cadence, diagnostics windows,
// horizon searches). The command line fills it from its parameters (config/params.hpp,
// evolution_config()); the evolution knows nothing of flags or their spellings.
#pragma once

#include "gbssn/rhs_params.hpp"
#include "grid/grid.hpp"
#include "horizon/horizon_finder_params.hpp"
#include "initial_data/initial_data_params.hpp"
#include "mesh/stepper_options.hpp"

#include <functional>
#include <limits>

namespace gbssn1d {

/// Windows of the constraint norms of timeseries.dat (diagnostics/constraints.hpp).
struct NormWindows {
  double rmin = 1.0, rmax = 10.0; ///< coordinate window of the *_ext norms
  double Rmin = 2.5, Rmax = 12.0; ///< areal-radius window of the *_R norms (length, not / M)
  double Rint = 1.8;              ///< areal radius bounding the interior norm H_L2_int
};

/// When the apparent horizon is searched for, for the horizon shift's h_AH (the schedule that
/// evolution/horizon_tracker.hpp runs).
struct HorizonSearchSettings {
  /// Where the searches happen, beyond their cadence. The two study schedules are deliberately
  /// inconsistent ways of feeding h_AH to the equations (docs/horizon-shift-study.md).
  enum class Schedule {
    standard,       ///< as every_steps says
    midstep_update, ///< every_steps >= 1: inside the RHS, at the 2nd RK substage of every n-th step
    /// boxes, every_steps = 0: the box holding the horizon searches at its own substages, every
    /// other box uses its latest value (an h_AH that jumps across refinement boundaries and lags)
    box_substage,
  };
  /// 0: at every RK substage (inside the RHS); n >= 1: every n steps
  long every_steps = 0;
  /// T > 0: a search after the first step at or past each multiple of T of evolution time,
  /// h_AH held in between (`--ah-interval`; every_steps is then 0); 0: as every_steps says
  double interval = 0.0;
  /// every_steps = 0 on a single grid: a search after every step instead, h_AH at each RK
  /// stage's time extrapolated from the last four radii, as boxes always do
  /// (`--ah-every extrapolated`; HorizonTracker::Mode::extrapolated)
  bool extrapolate = false;
  Schedule schedule = Schedule::standard;
  double t_min = 0.0;                                     ///< no searches before t_min ...
  double t_max = std::numeric_limits<double>::infinity(); ///< ... or after t_max
  HorizonFinderParams finder{.tolerance = 1e-12};         ///< the root-finder's settings
  /// Open loop: h_AH(t) prescribed as a function of time (no searches); empty: closed loop.
  std::function<double(double)> prescribed;
  bool in_window(double t) const { return t >= t_min && t <= t_max; }
};

/// Box-in-box refinement (mesh/hierarchy.hpp); with one level the grid is a single grid.
struct RefinementSettings {
  /// The horizon is searched for on the finest level on which it lies at least this many
  /// cells inside the outer edge: the finder's window of 8 cells around its seed, the 6-point
  /// interpolation's reach and one cell to spare.
  static constexpr double horizon_margin_cells = 12.0;
  std::size_t levels = 1; ///< level l covers r <= rmax / 2^l with N cells (uniform)
};

struct EvolutionConfig {
  GridSpec grid;
  RefinementSettings refinement;
  /// How the levels step (RK4 at dt = cfl x their spacing; on boxes also the time interpolation
  /// at fine boundaries, subcycling and the largest step); cfl 0.5 (docs/horizon-shift-study.md
  /// Sec. 11); a tapered buffer (where one is asked for) only on boxes reaching beyond 16 M
  /// (Sec. 6.6).
  mesh::StepperOptions stepping{.cfl = 0.5, .taper_min_extent = 16.0};
  InitialDataParams initial_data;
  RhsParams rhs;           ///< equations, gauge, dissipation, horizon shift
  double chi_floor = 1e-5; ///< chi is raised to at least this after every RK4 step (0: off)
  double tmax = 10.0;
  double dt_series = 0.25;       ///< time between rows of timeseries.dat
  double dt_profiles = 5.0;      ///< time between blocks of profiles.dat
  double checkpoint_every = 0.0; ///< simulated time between checkpoints (0: only on a signal)
  NormWindows norms;
  /// The areal radii, in units of M, of the spheres whose Misner-Sharp mass and energy flux the
  /// scalar field's series records (columns m_R<X>, flux_R<X>; --flux-R)
  std::vector<double> spheres;
  HorizonSearchSettings horizon_search;
};

/// The RK4 time step on a single `grid`: cfl x the smallest spacing.
inline double time_step(double cfl, const Grid& grid) {
  return cfl * grid.min_spacing();
}

} // namespace gbssn1d
