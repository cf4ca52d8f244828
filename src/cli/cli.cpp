#include "cli/cli.hpp"

#include "core/text.hpp"
#include "study/verdict.hpp"

#include "cli/commands.hpp"

#include "config/config_file.hpp"
#include "config/params.hpp"
#include "core/console.hpp"
#include "core/registry.hpp"
#include "core/stop_signal.hpp"
#include "study/converge.hpp"
#include "study/sweep.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <variant>

namespace gbssn1d {

namespace {

/// --help or --version printed by CLI11 to standard output, whose failure (a full disk, a closed
/// pipe) is an error, not a success.
int help_or_version(CLI::App& app, const CLI::Error& e) {
  const int status = app.exit(e);
  std::cout.flush();
  if (!std::cout) {
    say("gbssn1d: error: cannot write to standard output\n");
    return 1;
  }
  return status;
}

/// Each subcommand's options as CLI11 fills them.
struct EvolveArgs {
  Params params;
  bool print_config = false;
  std::string config_file; // expanded before parsing (expand_config); listed here for --help
  CLI::App* cmd = nullptr;
};
struct ConvergeArgs {
  ConvergeOptions options;
  std::string N_list, factors, fields = "alpha,chi,K", scaled_times;
  double expect_order = 0.0;
  CLI::Option* expect_order_opt = nullptr;
  CLI::App* cmd = nullptr;
};
struct SweepArgs {
  SweepOptions options;
  CLI::Option *jobs = nullptr, *emit = nullptr, *member = nullptr, *collect = nullptr;
  CLI::App* cmd = nullptr;
};
struct ResumeArgs {
  std::string dir;
  double tmax = 0.0;
  CLI::Option* tmax_opt = nullptr;
  CLI::App* cmd = nullptr;
};

/// The process made safe before anything is opened or parsed.
void prepare_process(int argc, char** argv) {
  // Standard streams closed by the caller (`2>&-`) are reopened on /dev/null before anything
  // is opened: otherwise the first file opened takes descriptor 0, 1 or 2, and console
  // messages would land inside it (timeseries.dat).
  for (int fd = 0; fd <= 2; ++fd)
    if (::fcntl(fd, F_GETFD) == -1 && errno == EBADF)
      (void)::open("/dev/null", fd == 0 ? O_RDONLY : O_WRONLY); // takes the lowest free: fd
  // A file-size limit then fails the write (EFBIG, reported by the checked flush) instead of
  // killing the process.
  std::signal(SIGXFSZ, SIG_IGN);
  // A closed pipe or terminal gives EPIPE on a write instead of killing the process: console
  // messages are best effort (core/console.hpp), files report their write errors.
  std::signal(SIGPIPE, SIG_IGN);
  // A stop signal is a request from the first instant: before any file is created (a run
  // killed in its first milliseconds left a folder holding only config.toml.tmp).
  install_stop_handlers();
  if (argc > 0 && argv[0] != nullptr && std::string(argv[0]).find('/') != std::string::npos)
    invoked_as() = argv[0];
}

/// `evolve`: the evolve flags (config/config_file.cpp), --config and --print-config.
void add_evolve(CLI::App& app, EvolveArgs& a) {
  a.cmd = app.add_subcommand(
      "evolve",
      "evolve one black hole and write ASCII output.\nMost runs need only: --id (wormhole | "
      "1log-trumpet | maximal-trumpet), --tmax, --out, --rahA A --rah0 h (move the horizon to "
      "h), and for resolution --N (or --grid uniform|sinh|boxes with --N, --rmax). Example: "
      "gbssn1d evolve --id 1log-trumpet --rahA 0.5 --rah0 1.2 --tmax 100 --out out/stretch");
  add_options(*a.cmd, a.params);
  a.cmd->footer(
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
  a.cmd
      ->add_option("--config", a.config_file,
                   "read parameters from a TOML/INI file of `key = value` lines (as "
                   "written to OUT/config.toml); flags given too override it")
      ->group("Configuration");
  a.cmd
      ->add_flag("--print-config", a.print_config,
                 "print the effective configuration (a valid --config file) and exit")
      ->group("Configuration");
}

/// `converge`: its own flags; the rest are passed to every member.
void add_converge(CLI::App& app, ConvergeArgs& a) {
  a.cmd = app.add_subcommand(
      "converge", "run one configuration (any evolve flags) at three or more resolutions");
  a.cmd->add_option("--N", a.N_list, "resolutions, e.g. 320,480,640, or a base N")->required();
  a.cmd->add_option("--factors", a.factors, "with a base N: N_k = N * factor, e.g. 1,1.5,2");
  add_number_option(*a.cmd, "-j,--jobs", a.options.jobs, "members run at once");
  a.cmd->add_option("--out", a.options.out, "output directory")->required();
  a.cmd->add_flag("--force", a.options.force, "write into a non-empty --out");
  std::string field_names;
  for (const auto& entry : registry)
    field_names += (field_names.empty() ? "" : ", ") + std::string(entry.name);
  a.cmd
      ->add_option("--fields", a.fields,
                   "fields whose differences give orders, comma separated, from: " + field_names)
      ->capture_default_str();
  a.cmd->add_option("--scaled-times", a.scaled_times,
                    "times of the Richardson-scaled H profiles (default: tmax)");
  add_number_option(*a.cmd, "--order", a.options.order, "order used to scale the profiles");
  a.expect_order_opt = add_number_option(
      *a.cmd, "--expect-order", a.expect_order,
      "the order the verdict expects (a study converges when its orders reach this minus 1.5); "
      "recorded in convergence.dat");
  a.expect_order_opt->default_str("--fd-order");
  a.cmd->allow_extras();
  a.cmd->footer(
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

/// `resume DIR [--tmax T]`.
void add_resume(CLI::App& app, ResumeArgs& a) {
  a.cmd = app.add_subcommand(
      "resume", "continue a run in DIR from DIR/checkpoint.bin, bit for bit as if uninterrupted");
  a.cmd->add_option("DIR", a.dir, "output directory of the run")->required();
  a.tmax_opt =
      add_number_option(*a.cmd, "--tmax", a.tmax, "new final time (M); default: the run's own");
  a.tmax_opt->default_str("the run's own");
  a.cmd->footer("The output files are cut back to the checkpoint and continued.");
}

int run_converge_command(ConvergeArgs& a) {
  if (a.expect_order_opt->count() > 0) {
    // the threshold, --expect-order - kOrderTolerance, must stay positive: at or below 0 a
    // study whose errors do not fall would meet it
    if (!std::isfinite(a.expect_order) || a.expect_order <= kOrderTolerance
        || a.expect_order > 30.0)
      throw ParamError("--expect-order", fmt::format("{}", a.expect_order),
                       fmt::format("must be a number in ({}, 30]: the verdict's threshold, "
                                   "--expect-order - {}, must stay positive",
                                   kOrderTolerance, kOrderTolerance));
    a.options.expect_order = a.expect_order;
  }
  return converge(a.options, a.N_list, a.factors, a.fields, a.scaled_times,
                  pass_through(*a.cmd, {"N", "out", "force"}));
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

/// The flags whose values came from an evolve --config file, and that file: a refused value
/// then says where it was given, since the user typed no such flag.
struct ConfigOrigins {
  std::map<std::string, std::string> file_of;
  std::string note(const std::string& flag) const {
    const auto it = file_of.find(flag);
    return it == file_of.end() ? std::string()
                               : fmt::format(" (given as '{}' in --config {})", flag.substr(2),
                                             printable(it->second));
  }
  /// The note for the flag CLI11 names in its message `what`.
  std::string note_in(const std::string& what) const {
    for (const auto& [flag, file] : file_of) {
      const auto at = what.find(flag);
      const auto after = at == std::string::npos ? 0 : at + flag.size();
      if (at != std::string::npos
          && (after == what.size()
              || !(std::isalnum(static_cast<unsigned char>(what[after])) || what[after] == '-')))
        return note(flag);
    }
    return std::string();
  }
};

/// Edit distance (Levenshtein) of two flag names.
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j)
    row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

/// What CLI11 could not place, in the order typed (its own message lists them reversed): the
/// first unknown flag, with the command's flags closest to it, or a stray word; a flag before
/// the subcommand is told to come after it.
std::string unexpected_arguments(const CLI::App& app) {
  std::vector<std::string> rest = app.remaining(true);
  std::reverse(rest.begin(), rest.end()); // (CLI11 parsed the reversed vector)
  const auto subcommands = app.get_subcommands();
  const CLI::App* command = subcommands.empty() ? nullptr : subcommands.front();
  const std::string where =
      command ? fmt::format("gbssn1d {}", command->get_name()) : std::string("gbssn1d");
  const auto flag = std::find_if(rest.begin(), rest.end(),
                                 [](const std::string& w) { return w.rfind("--", 0) == 0; });
  if (flag == rest.end())
    return fmt::format("{} does not take '{}' (an argument without a flag; see {} --help)", where,
                       printable(rest.empty() ? std::string() : rest.front()), where);
  const std::vector<std::string> before = app.remaining(false); // not the subcommand's
  if (!command || std::find(before.begin(), before.end(), *flag) != before.end())
    return fmt::format("{} before the subcommand: flags follow it (gbssn1d {} {} ...)",
                       printable(*flag), command ? command->get_name() : "evolve",
                       printable(*flag));
  const std::string name = flag->substr(0, flag->find('='));
  // the command's flags within two edits, closest first, at most three
  std::vector<std::pair<std::size_t, std::string>> near;
  for (const CLI::Option* o : command->get_options())
    for (const std::string& known : o->get_lnames())
      if (const std::size_t d = edit_distance(name.substr(2), known); d <= 2)
        near.emplace_back(d, "--" + known);
  std::stable_sort(near.begin(), near.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> close;
  for (std::size_t k = 0; k < near.size() && k < 3; ++k)
    close.push_back(near[k].second);
  return fmt::format("{} is not a flag of {}{} (see {} --help)", printable(name), where,
                     close.empty() ? std::string()
                                   : fmt::format("; did you mean {}?", fmt::join(close, " or ")),
                     where);
}

int run_command_line(int argc, char** argv) {
  prepare_process(argc, argv);
  CLI::App app{"gbssn1d: spherically symmetric generalized BSSN evolutions of a Schwarzschild "
               "black hole",
               "gbssn1d"};
  app.set_version_flag("--version", std::string("gbssn1d ") + GBSSN1D_VERSION);
  app.footer("Each subcommand's own page lists its flags: gbssn1d evolve --help (grouped, with "
             "its output files and exit statuses), gbssn1d resume --help, gbssn1d converge "
             "--help, gbssn1d sweep --help.");
  app.require_subcommand(1);
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);

  EvolveArgs evolve_args;
  ConvergeArgs converge_args;
  SweepArgs sweep_args;
  ResumeArgs resume_args;
  add_evolve(app, evolve_args);
  add_converge(app, converge_args);
  add_sweep(app, sweep_args);
  add_resume(app, resume_args);
  ConfigOrigins origins;
  try {
    std::vector<std::string> args(argv + 1, argv + argc);
    const std::set<std::string> subcommands{"evolve", "resume", "converge", "sweep"};
    if (!args.empty() && args.front().rfind("-", 0) != 0 && !subcommands.count(args.front()))
      throw ParamError("subcommand", fmt::format("'{}' is not a subcommand: use evolve, resume, "
                                                 "converge or sweep (gbssn1d --help)",
                                                 printable(args.front())));
    refuse_empty_values(args);
    refuse_repeated_flags(args);
    // evolve reads --config here; converge and sweep pass it on to their members, whose own
    // flags may then override the file's values once
    if (!args.empty() && args.front() == "evolve")
      args = expand_config(args, &origins.file_of);
    std::reverse(args.begin(), args.end()); // CLI11 takes a reversed vector of arguments
    app.parse(args);
  } catch (const CLI::CallForHelp& e) {
    return help_or_version(app, e);
  } catch (const CLI::CallForAllHelp& e) {
    return help_or_version(app, e);
  } catch (const CLI::CallForVersion& e) {
    return help_or_version(app, e);
  } catch (const CLI::ExtrasError&) {
    say("gbssn1d: error: {}\n", unexpected_arguments(app));
    return 2;
  } catch (const CLI::ParseError& e) {
    // CLI11's message quotes the value: its control characters escaped, on one line
    const std::string what = one_line(e.what());
    say("gbssn1d: error: {}{}\n", what, origins.note_in(what));
    return 2;
  } catch (const ParamError& e) {
    say("gbssn1d: error: {}{}\n", e.what(), origins.note(e.flag()));
    return 2;
  }

  try {
    if (evolve_args.cmd->parsed())
      return evolve(evolve_args.params, evolve_args.print_config);
    if (resume_args.cmd->parsed())
      return resume(resume_args.dir, resume_args.tmax_opt->count() > 0
                                         ? std::optional(resume_args.tmax)
                                         : std::nullopt);
    if (converge_args.cmd->parsed())
      return run_converge_command(converge_args);
    if (sweep_args.cmd->parsed())
      return run_sweep_command(sweep_args);
  } catch (const ParamError& e) {
    say("gbssn1d: error: {}{}\n", e.what(), origins.note(e.flag()));
    return 2;
  }
  return 0;
}

} // namespace

int run_cli(int argc, char** argv) {
  // The one place where every failure becomes a message and an exit status: nothing
  // escapes as an abort, and no library's text ("filesystem error: ...") reaches the user.
  try {
    return run_command_line(argc, argv);
  } catch (const ParamError& e) {
    say("gbssn1d: error: {}\n", e.what());
    return 2;
  } catch (const std::filesystem::filesystem_error& e) {
    say("gbssn1d: error: {}{}\n",
        e.path1().empty() ? std::string() : printable(e.path1().string()) + ": ",
        e.code().message());
    return 1;
  } catch (const std::bad_alloc&) {
    say("gbssn1d: error: out of memory (a smaller --N, fewer members at once with -j, or "
        "fewer members)\n");
    return 1;
  } catch (const std::exception& e) {
    say("gbssn1d: error: {}\n", e.what());
    return 1;
  } catch (...) {
    say("gbssn1d: error: an unknown failure\n");
    return 1;
  }
}

} // namespace gbssn1d
