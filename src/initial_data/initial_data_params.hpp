// Which initial data, for which mass: the parameters of initial_data() (initial_data.hpp),
// apart from it, so that configurations include them without the state and its registry.
#pragma once

namespace gbssn1d {

enum class InitialDataKind { wormhole, maximal_trumpet, onelog_trumpet, flat };
enum class InitialLapse { one, precollapsed };

/// A time-symmetric Gaussian pulse of the scalar field, Phi = amplitude exp(-((r - r0)/width)^2),
/// Pi = 0 (equations document, Sec. 19; --matter scalar).
struct ScalarPulse {
  double amplitude = 0.01;
  double r0 = 10.0;
  double width = 2.0;
};

struct InitialDataParams {
  InitialDataKind kind = InitialDataKind::wormhole;
  double M = 1.0;
  InitialLapse lapse0 = InitialLapse::precollapsed; ///< wormhole only
  ScalarPulse scalar; ///< with the scalar field only (the state's Fields)
};

} // namespace gbssn1d
