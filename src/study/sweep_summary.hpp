// A sweep's results: OUT/summary.dat from the members' status files and outputs (final r_ah,
// M_AH drift and error, H norms; members that spike far above their neighbours flagged), the
// members' warnings said once, and the sweep's exit status.
#pragma once

#include "study/sweep.hpp"

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace gbssn1d {

/// DIR/summary.dat from the members' status files and outputs (nothing is run); members
/// without a status are `invalid` if their flags do not validate, `missing` otherwise. Returns
/// each member's status.
std::vector<std::string> write_summary(const std::filesystem::path& dir,
                                       const SweepOptions& options,
                                       const std::vector<SweepAxis>& axes,
                                       const std::vector<SweepMember>& members);

/// The exit status for a set of member statuses: 0 if all finished, 1 if some have not run yet
/// (--collect before every line ran), else 3 if any blew up, failed or was invalid.
int exit_status(const std::vector<std::string>& statuses, std::size_t n);

} // namespace gbssn1d
