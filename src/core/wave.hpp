// The characteristic families of the outer boundary's outgoing waves: each registry row
// (core/registry.hpp) names its family, the gauge gives each family's speed (Gauge::speed,
// gbssn/rhs_params.hpp). Apart from the registry, so that parameters include it without the
// table of variables.
#pragma once

namespace gbssn1d {

/// The characteristic family whose outgoing mode a variable carries at the outer boundary.
enum class Wave {
  light,   ///< speed 1
  slicing, ///< the lapse's gauge mode: sqrt(mu_L), sqrt(2) for 1+log
  shift,   ///< the Gamma-driver's longitudinal mode: sqrt(4 xi / 3), 1 for xi = 3/4
};

} // namespace gbssn1d
