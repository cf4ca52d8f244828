// `gbssn1d sweep`: its own flags (the axes, -j, the scheduler's steps), the rest passed to
// every member (study/sweep.hpp).
#include "cli/command_rules.hpp"
#include "cli/commands.hpp"

#include "config/config_file.hpp"
#include "config/params.hpp"
#include "study/sweep.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>

namespace gbssn1d {

int run_sweep_command(SweepArgs& a) {
  if (!a.options.emit_tasks.empty() && a.jobs_given)
    throw ParamError("-j", std::to_string(a.options.jobs),
                     "has no effect with --emit-tasks: the lines run as the scheduler runs "
                     "them (e.g. `parallel -j N < TASKS`, or an array job)");
  if ((a.member_given || a.collect_given) && a.jobs_given)
    throw ParamError("-j", std::to_string(a.options.jobs),
                     "has no effect with --member or --collect (one member, or none, runs)");
  if (a.collect_given && (a.member_given || a.emit_given))
    throw ParamError("--collect", "is its own step: not with --member or --emit-tasks");
  if (a.member_given && a.options.member.empty())
    throw ParamError("--member", "''",
                     "names no member (a member folder's name, as in the "
                     "emitted lines)");
  if (a.member_given && a.emit_given)
    throw ParamError("--member", a.options.member, "not with --emit-tasks");
  check_jobs(a.options.jobs);
  if (!std::isfinite(a.options.progress_every) || a.options.progress_every < 0.0
      || a.options.progress_every > 86400.0)
    throw ParamError("--progress-every", fmt::format("{}", a.options.progress_every),
                     "must be a number of seconds in [0, 86400] (0: no progress lines)");
  const auto evolve_args = pass_through(a.extras, {"out", "force"});
  parse_evolve_args(evolve_args); // common flags must parse before anything runs
  return run_sweep(a.options, evolve_args);
}

} // namespace gbssn1d
