// Apparent horizons: zeros of the outgoing expansion Theta_+(r) of the spheres r = const
// (equations document, Sec. 6, (T1)-(T3)).
//
// Theta_+ and the areal radius are computed at the grid points (4th-order derivatives) and
// interpolated between them by 6-point Lagrange interpolation in the uniform coordinate x
// (6th order, so the finder adds nothing to the 4th-order truncation error). Sign changes are
// bracketed by a scan over the grid and refined by Boost.Math's TOMS 748.
#pragma once

#include "gbssn/state.hpp"
#include "grid/grid.hpp"
#include "horizon/horizon_finder_params.hpp"

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace gbssn1d {

struct MarginalSurface {
  double r;              ///< coordinate radius
  double R_areal;        ///< areal radius
  double mass;           ///< R_areal / 2
  bool outer;            ///< Theta_+ < 0 inside, > 0 outside (an outer trapping boundary)
  std::size_t level = 0; ///< the refinement level (box) it was found on; 0 on a single grid
};

struct HorizonSearch {
  /// Every zero of Theta_+, outermost first.
  std::vector<MarginalSurface> surfaces;
  /// The apparent horizon: the outermost zero with Theta_+ < 0 just inside, if any.
  std::optional<MarginalSurface> horizon() const;
};

/// The finder met values it cannot work with (a non-finite Theta_+ or root, a bracket the
/// root-finder rejects). The message says what and where; a run stops on it, with its output
/// up to then intact.
class HorizonFinderError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// Finds every marginally trapped sphere on the grid, between the first and the last interior
/// cell. Theta_+ at the first cells is differenced as the evolution differences them, through
/// the origin ghosts: `u` must have them filled by parity (fill_origin_ghosts), as every state
/// of a run has.
HorizonSearch find_horizons(const State& u, const Grid& grid, const HorizonFinderParams& params);

/// The apparent horizon only, searched first within `window` cells of `r_seed` (the previous
/// location), then, if none is found there, over the whole grid. Without `areal_radius` the
/// surface's R_areal and mass are NaN, not computed (what the RK substages' searches, which
/// read r alone, ask for).
std::optional<MarginalSurface> find_horizon_near(const State& u, const Grid& grid,
                                                 const HorizonFinderParams& params, double r_seed,
                                                 std::size_t window = 8, bool areal_radius = true);

} // namespace gbssn1d
