// A sweep as task lines for a scheduler (`sweep ... --emit-tasks FILE`): each line the
// one-member form of the sweep, runnable from any folder.
#pragma once

#include "study/sweep.hpp"

#include <string>
#include <vector>

namespace gbssn1d {

/// `sweep ... --emit-tasks FILE`: the task lines written to FILE (nothing is run).
int emit_tasks(const SweepOptions& options, const std::vector<SweepAxis>& axes,
               const std::vector<SweepMember>& members, const std::vector<std::string>& evolve_args,
               const std::string& exe);

} // namespace gbssn1d
