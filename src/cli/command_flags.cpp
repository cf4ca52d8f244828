// The subcommands' flags on the CLI11 app: each one's options, help page and footer, and what a
// parse leaves in its arguments (commands.hpp). With cli.cpp (the parse) and
// config/config_file.cpp (the evolve flags' table on an app), the one file that knows CLI11: the
// commands run from plain arguments (commands.hpp).
#include "cli/command_flags.hpp"

#include "config/config_file.hpp"
#include "core/registry.hpp"

#include <CLI/CLI.hpp>

#include <string>

namespace gbssn1d {

CommandFlags::CommandFlags(CLI::App& app, CommandArgs& args) : args_(&args) {
  add_evolve(app, args.evolve);
  add_converge(app, args.converge);
  add_sweep(app, args.sweep);
  add_resume(app, args.resume);
}

Subcommand CommandFlags::finish() {
  if (evolve_->parsed())
    return Subcommand::evolve;
  if (resume_->parsed()) {
    args_->resume.tmax_given = resume_tmax_->count() > 0;
    return Subcommand::resume;
  }
  if (converge_->parsed()) {
    args_->converge.expect_order_given = expect_order_->count() > 0;
    args_->converge.extras = converge_->remaining();
    return Subcommand::converge;
  }
  if (sweep_->parsed()) {
    SweepArgs& a = args_->sweep;
    a.jobs_given = jobs_->count() > 0;
    a.emit_given = emit_->count() > 0;
    a.member_given = member_->count() > 0;
    a.collect_given = collect_->count() > 0;
    a.extras = sweep_->remaining();
    return Subcommand::sweep;
  }
  return Subcommand::none;
}

/// `evolve`: the evolve flags (config/config_file.cpp), --config and --print-config.
void CommandFlags::add_evolve(CLI::App& app, EvolveArgs& a) {
  evolve_ = app.add_subcommand(
      "evolve",
      "evolve one black hole and write ASCII output.\nMost runs need only: --id (wormhole | "
      "1log-trumpet | maximal-trumpet), --tmax, --out, --rahA A --rah0 h (move the horizon to "
      "h), and for resolution --N (or --grid uniform|sinh|boxes with --N, --rmax). Example: "
      "gbssn1d evolve --id 1log-trumpet --rahA 0.5 --rah0 1.2 --tmax 100 --out out/stretch");
  add_options(*evolve_, a.params);
  evolve_->footer(
      "Lengths and times are in the units of --M (geometric units; with the default M = 1 "
      "they are multiples of M); the areal windows --norm-R* are multiples of M.\n"
      "Output in --out DIR: config.toml (repeats the run with --config), timeseries.dat (a row "
      "per --dt-series; its last line says how the run ended), profiles.dat (a block per "
      "--dt-profiles), horizon.dat, checkpoint.bin (with --checkpoint-every or after a "
      "signal; `gbssn1d resume DIR` continues), rah-hAH-file.dat (with --rah-hAH-file: the "
      "file as read at the start, which a resume uses).\nExit status: 0 completed; 1 a failed "
      "write; 2 "
      "invalid input (nothing written); 3 stopped (non-finite value, chi or alpha out of range, "
      "horizon finder failure); 128 + n interrupted by signal n: SIGTERM, SIGINT, SIGHUP, "
      "SIGUSR1 and SIGUSR2 (what batch schedulers send ahead of a time limit) finish the step, "
      "write a checkpoint and the end line; `gbssn1d resume DIR` continues.");
  evolve_
      ->add_option("--config", a.config_file,
                   "read parameters from a TOML/INI file of `key = value` lines (as "
                   "written to OUT/config.toml); flags given too override it")
      ->group("Configuration");
  evolve_
      ->add_flag("--print-config", a.print_config,
                 "print the effective configuration (a valid --config file) and exit")
      ->group("Configuration");
}

/// `resume`: the run's folder DIR and a new --tmax.
void CommandFlags::add_resume(CLI::App& app, ResumeArgs& a) {
  resume_ = app.add_subcommand(
      "resume", "continue a run in DIR from DIR/checkpoint.bin, bit for bit as if uninterrupted");
  resume_->add_option("DIR", a.dir, "output directory of the run")->required();
  resume_tmax_ =
      add_number_option(*resume_, "--tmax", a.tmax, "new final time (M); default: the run's own");
  resume_tmax_->default_str("the run's own");
  resume_->footer("The output files are cut back to the checkpoint and continued.");
}

/// `converge`: its own flags; the rest are passed to every member.
void CommandFlags::add_converge(CLI::App& app, ConvergeArgs& a) {
  converge_ = app.add_subcommand(
      "converge", "run one configuration (any evolve flags) at three or more resolutions");
  converge_->add_option("--N", a.N_list, "resolutions, e.g. 320,480,640, or a base N")->required();
  converge_->add_option("--factors", a.factors, "with a base N: N_k = N * factor, e.g. 1,1.5,2");
  add_number_option(*converge_, "-j,--jobs", a.options.jobs, "members run at once");
  converge_->add_option("--out", a.options.out, "output directory")->required();
  converge_->add_flag("--force", a.options.force, "write into a non-empty --out");
  std::string field_names;
  for (const auto& entry : registry)
    field_names += (field_names.empty() ? "" : ", ") + std::string(entry.name);
  converge_
      ->add_option("--fields", a.fields,
                   "fields whose differences give orders, comma separated, from: " + field_names)
      ->capture_default_str();
  converge_->add_option("--scaled-times", a.scaled_times,
                        "times of the Richardson-scaled H profiles (default: tmax)");
  add_number_option(*converge_, "--order", a.options.order, "order used to scale the profiles");
  expect_order_ = add_number_option(
      *converge_, "--expect-order", a.expect_order,
      "the order the verdict expects (a study converges when its orders reach this minus 1.5); "
      "recorded in convergence.dat");
  expect_order_->default_str("--fd-order");
  converge_->allow_extras();
  converge_->footer(
      "Every other flag is an evolve flag (see `gbssn1d evolve --help`). Every member lives on "
      "the same map (uniform, or sinh fixed by --dr-inner).\nVerdict: for each constraint norm "
      "(H, M_r, G^r on the coordinate window; H, M_r on the areal window; with --formulation "
      "z4c also G^r and Theta on the areal window) at each pair of "
      "neighbouring members and each --fields difference at each triple, the times where the "
      "finer value (the finer norm, or |f_b - f_c|) is above 10 times the round-off floor of "
      "the finest member involved are judged: the floor is eps_machine (M/dr)^2 of the "
      "quantity's scale (1/M^2 for H and M_r, 1/M for G^r, the field's RMS for a field), the "
      "round-off of a second difference at dr, the member's smallest cell whose round-off can "
      "have reached where the quantity is taken (its window's cells at t = 0, then every cell "
      "within 2 t of the window; after a few M the innermost cell, dr-min in its headers; "
      "measured on the stationary trumpet's H_L2_R, default sinh grid: 3-8e-11 at N = 3200, "
      "dr_min = M/400, and 1.2-2.4e-10 at N = 6400, M/800; the estimate gives 3.5e-11 and "
      "1.4e-10). Over the judged times, the order of each RMS over time, and for the norms "
      "of the RMS over each tenth of those times, decides (single times are reported, not "
      "judged; nor is H_L2_int; 10 or fewer judged times are too short to judge: not judged), in "
      "five classes, the verdict's first words (then H's class, then the worst quantity's): "
      "`converges` "
      "(every such order at least --expect-order - 1.5); `converges until the round-off floor` "
      "(so, and some pair's or triple's finer member lay at the floor at some times, not "
      "judged: the verdict names the members, quantities and floor estimates); `not judged` (a "
      "quantity without a value at any time, such as a norm whose window holds no point; or "
      "nothing judged at all, every value within its round-off floor estimate: no pass); "
      "`pre-asymptotic` (the errors fall with N: every order of an RMS over time at least 1 and "
      "no tenth of the run with an RMS order below 0, but some order is below --expect-order - "
      "1.5); `does not converge` (some order of an RMS over time below 1, or a tenth of the "
      "run where the finer member is worse). The verdict is written into convergence.dat's "
      "header (a `verdict:` line and an `order` line per quantity and resolutions) and onto "
      "stderr, naming the quantity, the resolutions, the first time below and the lowest "
      "order.\nExit status: 0 completed and converges (or converges until the round-off "
      "floor); 1 a failed write; 2 invalid input (nothing run); 3 a member stopped (non-finite "
      "value, chi or alpha out of range, horizon finder failure; the verdict says: does not "
      "converge: member N = ... failed); 4 completed, but does not converge (the verdict); 5 "
      "completed, pre-asymptotic (the verdict); 6 completed, but not judged (a judged quantity "
      "without a value at any time: a norm whose window held no point, NaN in timeseries.dat; "
      "10 or fewer judged times; or every value within its round-off floor estimate); "
      "128 + n interrupted by signal n (rerun "
      "the command to resume).\nOutput in --out: N<n>/ (each member's evolve output: "
      "config.toml, timeseries.dat, profiles.dat, horizon.dat); config.toml (the study); "
      "convergence.dat (columns: t, each norm per member as <norm>_N<n> for H_L2_ext, "
      "M_L2_ext, G_L2_ext, H_L2_R, M_L2_R, H_L2_int (z4c: also G_L2_R, Theta_L2_R), then the "
      "pairwise orders p_<H|M|G|H_R|M_R|H_int|G_R|Theta_R>_<n1>_<n2> and the --fields orders "
      "p3_<field>_<n1>_<n2>_<n3>; its header holds the "
      "verdict and an order line per "
      "quantity); scaled_H.dat (a block per --scaled-times, opened by '# t = <t>': columns r, "
      "H_N<coarsest>, H_N<n>_scaled = H scaled by (n/coarsest)^--order, on the coarsest "
      "member's r).");
}

/// `sweep`: its own flags; the rest are passed to every member.
void CommandFlags::add_sweep(CLI::App& app, SweepArgs& a) {
  sweep_ = app.add_subcommand("sweep", "run the product of value lists of any evolve flags");
  sweep_
      ->add_option("--sweep", a.options.sweeps,
                   "flag=value1,value2,... (repeat for more flags); flags that change together "
                   "share an axis: flag1,flag2=a1:b1,a2:b2")
      ->required();
  jobs_ = add_number_option(*sweep_, "-j,--jobs", a.options.jobs,
                            "members run at once (not with --emit-tasks: the scheduler runs them)");
  sweep_->add_option("--out", a.options.out, "output directory (a rerun resumes)")->required();
  add_number_option(*sweep_, "--progress-every", a.options.progress_every,
                    "seconds between progress lines (k of n done, running members) while "
                    "members run, at most 86400; 0: none");
  emit_ = sweep_->add_option(
      "--emit-tasks", a.options.emit_tasks,
      "write one command line per valid member (for GNU parallel or a Slurm array) and exit; "
      "each runs its member into --out from any folder and resumes it when requeued");
  member_ = sweep_->add_option(
      "--member", a.options.member,
      "run only the member of this name (what an emitted line does); exit 0 finished, 3 blew "
      "up or failed");
  collect_ = sweep_->add_flag(
      "--collect", a.options.collect,
      "build summary.dat from the members in --out without running any; exit 0 if all "
      "finished, 1 if some have not run yet, else 3 if any blew up, failed or was invalid");
  sweep_->allow_extras();
  sweep_->footer(
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

} // namespace gbssn1d
