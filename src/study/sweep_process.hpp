// Running one sweep member as a subprocess of this executable (posix_spawn), with its inputs,
// log, lock and status in OUT/logs/: the one place a member is run, by a sweep and by an
// emitted task line alike.
#pragma once

#include "study/sweep.hpp"

#include <filesystem>
#include <functional>
#include <string>

namespace gbssn1d {

/// What one member's run ended with.
struct MemberOutcome {
  std::string status = "ok", reason = "-";
  double wall = 0.0;
};

/// Runs member `m` to completion (from its checkpoint if it has one) as a subprocess of `exe`.
/// `on_start` is called when the subprocess starts. A SIGTERM/SIGINT sent to the sweep is
/// passed on to the member, which then stops like an interrupted evolve.
MemberOutcome run_member(const std::filesystem::path& dir, const SweepMember& m,
                         const std::string& exe, const std::function<void()>& on_start = {});

} // namespace gbssn1d
