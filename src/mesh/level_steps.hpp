// The levels' time steps: how many steps each box takes per step of the hierarchy (Berger-Oliger
// subcycling, a factor 1 or 2 between parent and child), and the hierarchy's step itself.
#pragma once

#include "mesh/layout.hpp"
#include "mesh/stepper_options.hpp"

#include <vector>

namespace gbssn1d::mesh {

/// Steps level l takes per step of the hierarchy (level 0's step) under `options`: 1 on level
/// 0, then the same or twice its parent's (see StepperOptions::dt_max).
std::vector<long> level_steps(const MeshLayout& layout, const StepperOptions& options);
/// The hierarchy's step (level 0's) under `options`.
double hierarchy_dt(const MeshLayout& layout, const StepperOptions& options);

} // namespace gbssn1d::mesh
