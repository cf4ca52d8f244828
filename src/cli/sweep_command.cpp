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

/// `sweep`: its own flags; the rest are passed to every member.
void add_sweep(CLI::App& app, SweepArgs& a) {
  a.cmd = app.add_subcommand("sweep", "run the product of value lists of any evolve flags");
  a.cmd
      ->add_option("--sweep", a.options.sweeps,
                   "flag=value1,value2,... (repeat for more flags); flags that change together "
                   "share an axis: flag1,flag2=a1:b1,a2:b2")
      ->required();
  a.jobs =
      add_number_option(*a.cmd, "-j,--jobs", a.options.jobs,
                        "members run at once (not with --emit-tasks: the scheduler runs them)");
  a.cmd->add_option("--out", a.options.out, "output directory (a rerun resumes)")->required();
  add_number_option(*a.cmd, "--progress-every", a.options.progress_every,
                    "seconds between progress lines (k of n done, running members) while "
                    "members run, at most 86400; 0: none");
  a.emit = a.cmd->add_option(
      "--emit-tasks", a.options.emit_tasks,
      "write one command line per valid member (for GNU parallel or a Slurm array) and exit; "
      "each runs its member into --out from any folder and resumes it when requeued");
  a.member = a.cmd->add_option(
      "--member", a.options.member,
      "run only the member of this name (what an emitted line does); exit 0 finished, 3 blew "
      "up or failed");
  a.collect = a.cmd->add_flag(
      "--collect", a.options.collect,
      "build summary.dat from the members in --out without running any; exit 0 if all "
      "finished, 1 if some have not run yet, else 3 if any blew up, failed or was invalid");
  a.cmd->allow_extras();
  a.cmd->footer(
      "Every other flag is an evolve flag, common to all members.\nOutput in --out: NAME/ "
      "(each member's evolve output with its own config.toml, NAME = its values, e.g. "
      "rahA=0.5_rah0=1.2), logs/ (NAME.log, NAME.status, NAME.inputs), summary.dat (its path is "
      "printed at the end).\nOUT/summary.dat: a row per member, columns: the swept flags, status, "
      "flag, "
      "t_end, r_ah_final, M_ah_drift, M_ah_err_max, H_L2_ext_max, H_L2_R_max, wall_s, reason; "
      "its values, status (ok, invalid, blew-up, failed, interrupted, missing; a rerun "
      "of the sweep, or a requeued task line, runs the failed, interrupted and missing members "
      "again, from their checkpoints where they have one, and wall_s is a member's total), flag "
      "(spike: a finished member whose H_L2_R_max is more than 100 times the median of its "
      "neighbours' along an axis, the axes of N excepted; named on stderr too), figures and a "
      "reason. Each distinct `gbssn1d: warning:` of the members' logs is repeated on stderr "
      "once, with the members that gave it.\nExit status: 0 every member finished (spikes "
      "included); 1 a failed write, or with --collect members not run yet; 2 invalid input; 3 a "
      "member blew up, failed or was invalid; 128 + n interrupted by signal n.\nA member runs "
      "in one process at a time (OUT/logs/NAME.lock): a line started while it runs is refused. "
      "At most 10000 members.");
}

int run_sweep_command(SweepArgs& a) {
  if (!a.options.emit_tasks.empty() && a.jobs->count() > 0)
    throw ParamError("-j", std::to_string(a.options.jobs),
                     "has no effect with --emit-tasks: the lines run as the scheduler runs "
                     "them (e.g. `parallel -j N < TASKS`, or an array job)");
  if ((a.member->count() > 0 || a.collect->count() > 0) && a.jobs->count() > 0)
    throw ParamError("-j", std::to_string(a.options.jobs),
                     "has no effect with --member or --collect (one member, or none, runs)");
  if (a.collect->count() > 0 && (a.member->count() > 0 || a.emit->count() > 0))
    throw ParamError("--collect", "is its own step: not with --member or --emit-tasks");
  if (a.member->count() > 0 && a.options.member.empty())
    throw ParamError("--member", "''",
                     "names no member (a member folder's name, as in the "
                     "emitted lines)");
  if (a.member->count() > 0 && a.emit->count() > 0)
    throw ParamError("--member", a.options.member, "not with --emit-tasks");
  check_jobs(a.options.jobs);
  if (!std::isfinite(a.options.progress_every) || a.options.progress_every < 0.0
      || a.options.progress_every > 86400.0)
    throw ParamError("--progress-every", fmt::format("{}", a.options.progress_every),
                     "must be a number of seconds in [0, 86400] (0: no progress lines)");
  const auto evolve_args = pass_through(*a.cmd, {"out", "force"});
  parse_evolve_args(evolve_args); // common flags must parse before anything runs
  return run_sweep(a.options, evolve_args);
}

} // namespace gbssn1d
