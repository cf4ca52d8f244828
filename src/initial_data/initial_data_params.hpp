// Which initial data, for which mass: the parameters of initial_data() (initial_data.hpp),
// apart from it, so that configurations include them without the state and its registry.
#pragma once

namespace gbssn1d {

enum class InitialDataKind { wormhole, maximal_trumpet, onelog_trumpet };
enum class InitialLapse { one, precollapsed };

struct InitialDataParams {
  InitialDataKind kind = InitialDataKind::wormhole;
  double M = 1.0;
  InitialLapse lapse0 = InitialLapse::precollapsed; ///< wormhole only
};

} // namespace gbssn1d
