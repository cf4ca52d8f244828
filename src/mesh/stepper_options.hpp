// How the levels of a box hierarchy step (mesh/hierarchy.hpp: MeshStepper), apart from the
// stepper, so that configurations include them without the state and its registry.
#pragma once

#include "mesh/time_interpolation_kind.hpp"

#include <cstddef>
#include <limits>

namespace gbssn1d::mesh {

struct StepperOptions {
  TimeInterpolation time = TimeInterpolation::rk_stages;
  bool subcycling = true; ///< false: every level steps with the finest dt
  double cfl = 0.25;      ///< dt_l = cfl dr_l (at most dt_max)
  /// Largest step any level takes (e.g. the stability limit of a stiff damping term, which
  /// does not shrink with the spacing): a level whose CFL step would exceed it steps with the
  /// largest dt_finest x 2^k below it, as often as its child (time refinement factor 1, as
  /// Carpet's time_refinement_factors do for the outer levels).
  double dt_max = std::numeric_limits<double>::infinity();
  /// A fine box's outermost `taper_cells` interior cells are blended towards the prolongation
  /// of their parent at every synchronisation (after restriction), with weights rising
  /// smoothly from 0 inside to 1 at the outermost cell: a tapered buffer (Lehner, Liebling &
  /// Reula 2006; the 3 outermost cells that OllinSphere-BiB overwrites). Between
  /// synchronisations the stages are untouched, so each RK4 step stays consistent. 0: off.
  std::size_t taper_cells = 0;
  /// Only boxes that reach beyond this radius are tapered (0: every box but level 0).
  double taper_min_extent = 0.0;
};

} // namespace gbssn1d::mesh
