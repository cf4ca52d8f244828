// The horizon finder's settings (horizon/apparent_horizon.hpp), apart from it, so that
// configurations include them without the state and its registry.
#pragma once

namespace gbssn1d {

/// The root-finder of the expansion Theta_+(r) = 0.
struct HorizonFinderParams {
  double tolerance = 1e-13; ///< absolute tolerance of the root in r (M)
  double r_min = 0.0;       ///< scan only r >= r_min (keeps clear of the puncture)
};

} // namespace gbssn1d
