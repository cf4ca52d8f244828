// The part of validate() (config/params.hpp) that builds the grid: its cells finite, increasing
// and resolvable, the horizon finder's tolerance against them, and the step's limits
// (checkpoints, step and row counts, the Gamma-driver damping, Z4c's damping).
#pragma once

#include "config/params.hpp"

namespace gbssn1d {

/// Throws ParamError naming the flag whose value gives no usable grid or step.
void validate_grid_and_steps(const ResolvedParams& p);

} // namespace gbssn1d
