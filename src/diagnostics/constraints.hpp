// Constraint monitors and norms on the grid (equations document, Sec. 5, Sec. 6).
#pragma once

#include "gbssn/state.hpp"
#include "grid/grid.hpp"

#include <span>
#include <vector>

namespace gbssn1d {

/// Derived profiles on the interior points (index 0 ... N-1 = grid point first_interior()...).
struct DerivedProfiles {
  std::vector<double> H, M_r, G_r, R_areal, Theta_plus;
  std::vector<double> m_ms;  ///< (T4) the Misner-Sharp mass
  std::vector<double> Theta; ///< Z4c's Theta (Sec. 17); empty for a BSSN state
  /// (S7) the energy flux through the sphere of fixed areal radius through each point; empty
  /// without matter
  std::vector<double> flux;
};

DerivedProfiles derived_profiles(const State& u, const Grid& grid);

/// Discrete L2 norm over the interior points with rmin <= r <= rmax, weighted by the cell
/// widths: sqrt( sum f_i^2 dr_i / sum dr_i ). `values` holds one value per interior point.
/// NaN when no point lies in the range (no value, not a vanishing one).
double l2_norm(std::span<const double> values, const Grid& grid, double rmin, double rmax);

/// L2 norm over the interior points of the outer sheet (outside the outermost minimum of the
/// areal radius: a wormhole's throat) whose areal radius lies in [Rmin, Rmax], weighted by the
/// areal width |dR| of each cell: sqrt( sum f_i^2 |dR_i| / sum |dR_i| ). A window in R is the same
/// place in every gauge, so norms of runs with different shifts compare. NaN when no point lies
/// in the window.
double l2_norm_areal(std::span<const double> values, std::span<const double> R_areal, double Rmin,
                     double Rmax);

/// The first interior point of the outer sheet (l2_norm_areal): outside the outermost minimum of
/// the areal radius, found walking in from the outer boundary.
std::size_t outer_sheet_begin(std::span<const double> R_areal);

/// L2 norm near the puncture: over the points from the innermost one outwards while the areal
/// radius stays <= Rmax (inside the horizon when Rmax < 2M), weighted by the cell widths dr
/// (near a trumpet's puncture R hardly changes, so |dR| would hide those cells). NaN when the
/// innermost point already has R > Rmax (a wormhole's other sheet).
double l2_norm_interior(std::span<const double> values, std::span<const double> R_areal,
                        const Grid& grid, double Rmax);

/// The lapse at r = 0 from the two innermost cells, using that alpha is even:
/// alpha(r) = c0 + c2 r^2  =>  alpha(0) = (r2^2 alpha1 - r1^2 alpha2) / (r2^2 - r1^2).
double central_value(std::span<const double> f, const Grid& grid);

} // namespace gbssn1d
