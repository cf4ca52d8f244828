#include "cli/cli.hpp"

#include "config/config_file.hpp"
#include "config/numbers.hpp"
#include "config/params.hpp"
#include "core/console.hpp"
#include "core/registry.hpp"
#include "core/stop_signal.hpp"
#include "evolution/simulation.hpp"
#include "study/converge.hpp"
#include "study/sweep.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

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

int run_and_report(Simulation& sim, Output& out, const Params& p);

/// A run with --rah-hAH-file keeps a copy of the file as read at its start in its folder, and a
/// resume continues with that copy: the file named by the flag may have been edited since, or a
/// relative path may name another file from another folder.
const char* const prescribed_horizon_copy = "rah-hAH-file.dat";

/// The bytes of --rah-hAH-file when it is in use (rahA != 0), nothing otherwise.
std::optional<std::string> prescribed_horizon_content(const Params& p) {
  if (p.rah_hAH_file.empty() || p.rahA == 0.0)
    return std::nullopt;
  std::ifstream in(p.rah_hAH_file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in && !in.eof())
    throw ParamError("--rah-hAH-file", printable(p.rah_hAH_file), "cannot be read");
  return text.str();
}

int evolve(Params p, bool print_config) {
  resolve_defaults(p);
  validate(p);
  if (print_config) {
    const std::string text = config_text(p);
    if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0)
      throw OutputError(fmt::format("cannot write the configuration to standard output: {}",
                                    std::strerror(errno)));
    return 0;
  }
  validate_output_dir(p);
  for (const auto& w : warnings(p))
    say("gbssn1d: warning: {}\n", w);

  Simulation sim(evolution_config(p)); // initial data are computed before anything is written
  sim.show_progress = true;
  const std::filesystem::path dir(p.out);
  // the content of --rah-hAH-file as it was read (before the folder is made)
  const std::optional<std::string> hAH_content = prescribed_horizon_content(p);
  if (const int signal = stop_signal(); signal != 0) {
    say("gbssn1d: interrupted by {} before the run started; nothing was written\n",
        signal_name(signal));
    return 128 + signal;
  }
  create_output_dir("--out", dir);
  const std::string config = config_text(p);
  write_file_atomically(dir / "config.toml", header_text("") + config);
  if (hAH_content)
    write_file_atomically(dir / prescribed_horizon_copy, *hAH_content);
  Output out(dir, config + sim.run_facts());
  sim.checkpoint_config = config;
  return run_and_report(sim, out, p);
}

/// Runs `sim` into `out`; says how it ended on stderr and in timeseries.dat; returns the exit
/// status (0, 3 stopped, 128 + n interrupted by signal n, 1 a failed write).
int run_and_report(Simulation& sim, Output& out, const Params& p) {
  install_stop_handlers();
  const auto start = std::chrono::steady_clock::now();
  // How the run ended goes to stderr and, as the last line, into timeseries.dat.
  auto stopped = [&](const std::string& prefix, const std::string& what, const std::string& kept,
                     int status) {
    say("gbssn1d: {}{}; {}\n", prefix, what, kept);
    out.write_end(fmt::format("stopped: {}", what));
    return status;
  };
  try {
    sim.run(&out);
  } catch (const NonFiniteError& e) {
    return stopped("error: ", e.what(), "output up to the last finite state kept in " + p.out, 3);
  } catch (const HorizonFinderError& e) {
    return stopped("error: ", e.what(), "output up to then kept in " + p.out, 3);
  } catch (const Interrupted& e) {
    return stopped("", e.what(),
                   fmt::format("output up to then and a checkpoint kept in {}; resume with: {}",
                               p.out, resume_command(p.out)),
                   128 + e.signal);
  } catch (const OutputError& e) {
    say("gbssn1d: error: {}; the output in {} is incomplete\n", e.what(), p.out);
    try {
      out.write_end(fmt::format("stopped: {}", e.what())); // other files may still take it
    } catch (const OutputError&) {
    }
    return 1;
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out.write_end(fmt::format("completed at t = {}", sim.time()));
  say("gbssn1d: reached t = {} in {:.2f} s ({} steps, {} RHS evaluations)\n", sim.time(), wall,
      sim.schedule().n_steps, sim.evaluations());
  return 0;
}

/// How far timeseries.dat goes: the time of its last data row, and whether its last line says
/// the run completed.
struct SeriesEnd {
  double t_last = 0.0;
  bool completed = false;
};

SeriesEnd series_end(const std::filesystem::path& file) {
  SeriesEnd end;
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("# end: completed", 0) == 0)
      end.completed = true;
    else if (!line.empty() && line[0] != '#') {
      end.completed = false; // rows after an end line: a later resume wrote them
      end.t_last = std::strtod(line.c_str(), nullptr);
    }
  }
  return end;
}

int resume(const std::string& dir_name, std::optional<double> tmax) {
  namespace fs = std::filesystem;
  const fs::path dir(dir_name);
  check_path("DIR", dir);
  // a file of the run that cannot even be examined (a loop of symbolic links) is refused
  auto has_file = [&](const char* name) {
    std::error_code ec;
    const fs::file_status st = fs::status(dir / name, ec);
    if (ec && ec != std::errc::no_such_file_or_directory)
      throw ParamError("DIR", printable(dir_name),
                       fmt::format("its {} cannot be read: {}", name, ec.message()));
    return fs::is_regular_file(st);
  };
  if (!has_file("config.toml"))
    throw ParamError("DIR", dir_name, "has no config.toml (not a gbssn1d output directory)");
  if (!has_file("checkpoint.bin"))
    throw ParamError("DIR", dir_name,
                     "has no checkpoint.bin (run with --checkpoint-every T, or stop a run with "
                     "a stop signal: SIGTERM, SIGINT, SIGHUP, SIGUSR1 or SIGUSR2)");
  Params p = parse_evolve_args({"--config", (dir / "config.toml").string()});
  if (tmax)
    p.tmax = *tmax;
  p.out = dir_name;
  resolve_defaults(p);
  validate(p);
  Checkpoint c;
  try {
    c = read_checkpoint(dir / "checkpoint.bin");
  } catch (const CheckpointError& e) {
    throw ParamError("DIR", dir_name, e.what());
  }
  const std::string config = config_text(p);
  if (!config_differences(c.config, config, {"tmax", "out", "force"}).empty())
    throw ParamError("DIR", dir_name, "its checkpoint belongs to another configuration");
  if (p.tmax < c.t)
    throw ParamError("--tmax", fmt::format("{}", p.tmax),
                     fmt::format("is before the checkpoint at t = {}", c.t));
  // What the files hold already: a completed run is left alone, and no resume may cut away
  // output beyond the new end.
  const SeriesEnd written = series_end(dir / "timeseries.dat");
  if (written.completed && (!tmax || p.tmax <= written.t_last)) {
    say("gbssn1d: {} is complete at t = {}; nothing to do (`{} --tmax T` continues it to a "
        "later T)\n",
        dir_name, written.t_last, resume_command(dir_name));
    return 0;
  }
  if (p.tmax < written.t_last)
    throw ParamError("--tmax", fmt::format("{}", p.tmax),
                     fmt::format("is before the last output at t = {}: resuming would cut "
                                 "the output written after it",
                                 written.t_last));
  // the h_AH file as the run read it at its start (its copy), whatever the flag's path names now
  Params run_params = p;
  if (const std::filesystem::path copy = dir / prescribed_horizon_copy;
      !p.rah_hAH_file.empty() && p.rahA != 0.0 && fs::is_regular_file(copy)) {
    std::optional<std::string> now;
    try {
      now = prescribed_horizon_content(p);
    } catch (const ParamError&) {
    }
    std::ifstream in(copy, std::ios::binary);
    std::ostringstream kept;
    kept << in.rdbuf();
    if (!now || *now != kept.str())
      say("gbssn1d: note: --rah-hAH-file {} is not what the run read at its start (edited, "
          "missing, or another file from this folder); it continues with the copy it took then, "
          "{}\n",
          printable(p.rah_hAH_file), copy.string());
    run_params.rah_hAH_file = copy.string();
  }
  Simulation sim(evolution_config(run_params));
  try {
    sim.restore(c);
    Output::check_resumable(dir, c.marks);
  } catch (const CheckpointError& e) {
    throw ParamError("DIR", dir_name, e.what());
  } catch (const OutputError& e) {
    throw ParamError("DIR", dir_name, e.what());
  }
  // every check is done: only now is any file changed (unless a stop signal came meanwhile)
  if (const int signal = stop_signal(); signal != 0) {
    say("gbssn1d: interrupted by {} before resuming; nothing was changed\n", signal_name(signal));
    return 128 + signal;
  }
  sim.show_progress = true;
  sim.checkpoint_config = config;
  write_file_atomically(dir / "config.toml", header_text("") + config);
  say("gbssn1d: resuming {} at t = {} (step {}) to t = {}\n", dir_name, c.t, c.step, p.tmax);
  Output out(dir, config + sim.run_facts(), c.marks);
  return run_and_report(sim, out, p);
}

} // namespace

namespace {

/// An item of a comma-separated list as a number (the one reader, config/numbers.hpp), or
/// ParamError naming `flag` and the list.
template <class T>
T list_number(const std::string& flag, const std::string& list, const std::string& item) {
  if (const auto value = parse_decimal<T>(item))
    return *value;
  throw ParamError(flag, printable(list),
                   fmt::format("'{}' is not {}", printable(item), number_kind<T>()));
}

/// The items of "a,b,c"; ParamError naming `flag` for an empty list or an empty item.
std::vector<std::string> split_list(const std::string& flag, const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');)
    out.push_back(item);
  if (out.empty() || (!s.empty() && s.back() == ',')
      || std::any_of(out.begin(), out.end(), [](const auto& item) { return item.empty(); }))
    throw ParamError(flag, s.empty() ? "''" : printable(s),
                     "must be a comma-separated list without empty items");
  return out;
}

/// -j: at least 1, at most jobs_max (threads and processes beyond that only thrash).
void check_jobs(int jobs) {
  constexpr int jobs_max = 1024;
  if (jobs < 1 || jobs > jobs_max)
    throw ParamError("-j", std::to_string(jobs), fmt::format("must lie in [1, {}]", jobs_max));
}

/// A flag given twice on the command line is refused (a --config file's values may be
/// overridden once by the command line; --sweep is meant to repeat). The short -j is the same
/// flag as --jobs ("-j 2", "-j2").
void refuse_repeated_flags(const std::vector<std::string>& args) {
  std::set<std::string> seen;
  for (const auto& a : args) {
    const bool short_jobs = a.rfind("-j", 0) == 0;
    if ((a.rfind("--", 0) != 0 || a == "--") && !short_jobs)
      continue;
    std::string name = a.substr(0, a.find('='));
    if (short_jobs || name == "--jobs")
      name = "-j/--jobs";
    if (name == "--sweep")
      continue;
    if (!seen.insert(name).second)
      throw ParamError(name, "is given more than once (a flag may be given once; flags given "
                             "with --config may be overridden once)");
  }
}

/// Refuses empty values: `--flag=` (which a parser would complete with the next argument, so
/// that the next flag became the value and was lost) and an empty argument (`--flag ''`).
void refuse_empty_values(const std::vector<std::string>& args) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.size() > 2 && a.rfind("--", 0) == 0 && a.back() == '=')
      throw ParamError(a.substr(0, a.size() - 1),
                       "is given an empty value: put the value after '=', or leave the flag out");
    if (a.empty()) {
      const bool after_flag = i > 0 && args[i - 1].rfind("-", 0) == 0;
      throw ParamError(after_flag ? args[i - 1] : std::string("argument"),
                       after_flag ? "is given an empty value: give a value, or leave the flag out"
                                  : "an empty argument is not a value of any flag");
    }
  }
}

/// The evolve flags given to converge/sweep; refuses those the study sets itself.
std::vector<std::string> pass_through(const CLI::App& cmd, const std::vector<std::string>& own) {
  std::vector<std::string> extras = cmd.remaining();
  for (const auto& a : extras)
    for (const auto& flag : own)
      if (a == "--" + flag || a.rfind("--" + flag + "=", 0) == 0)
        throw ParamError("--" + flag, a, "is set by the study itself for each member");
  return extras;
}

int converge(const ConvergeOptions& options_in, const std::string& N_list,
             const std::string& factors, const std::string& fields, const std::string& times,
             const std::vector<std::string>& evolve_args) {
  ConvergeOptions options = options_in;
  options.N.clear();
  for (const auto& n : split_list("--N", N_list))
    options.N.push_back(list_number<int>("--N", N_list, n));
  if (!factors.empty()) { // a base N and factors: N_k = round(N * f_k)
    if (options.N.size() != 1)
      throw ParamError("--factors", factors, "needs a single base --N");
    const int base_N = options.N.front();
    options.N.clear();
    for (const auto& f : split_list("--factors", factors)) {
      const double factor = list_number<double>("--factors", factors, f);
      if (!(factor > 0))
        throw ParamError("--factors", factors, "factors must be > 0");
      const double n = base_N * factor;
      if (std::abs(n - std::round(n)) > 1e-9 * n || n > 1e7)
        throw ParamError(
            "--factors", factors,
            fmt::format("--N {} x {} = {} is not a whole number of cells", base_N, f, n));
      options.N.push_back(static_cast<int>(std::lround(n)));
    }
  }
  options.fields = split_list("--fields", fields);
  options.scaled_times.clear();
  if (!times.empty())
    for (const auto& t : split_list("--scaled-times", times))
      options.scaled_times.push_back(list_number<double>("--scaled-times", times, t));
  if (!std::isfinite(options.order) || options.order <= 0.0 || options.order > 30.0)
    throw ParamError("--order", fmt::format("{}", options.order),
                     "must be a number in (0, 30] (H is scaled by (N/N_0)^order)");
  check_jobs(options.jobs);
  Params base = parse_evolve_args(evolve_args);
  base.N = options.N.front(); // the first member; each member sets its own
  base.out = options.out;
  resolve_defaults(base);
  for (const double t : options.scaled_times)
    if (t < 0.0 || t > base.tmax)
      throw ParamError("--scaled-times", printable(times),
                       fmt::format("{} is outside the run's [0, tmax = {}]", t, base.tmax));
  check_path("--out", options.out);
  bool continuing = false;
  // A converge folder of other inputs: say which, so that nobody takes --force lightly (with
  // --force the members rerun; a member resumes only from a checkpoint of its own inputs).
  std::error_code ec; // a path that cannot be examined is refused by validate_output_dir
  if (const auto old = std::filesystem::path(options.out) / "config.toml";
      !options.force && std::filesystem::is_regular_file(old, ec)) {
    std::ifstream in(old);
    std::stringstream text;
    text << in.rdbuf();
    const auto diff = config_differences(text.str(), config_text(base), {"out", "force", "N"});
    if (!diff.empty())
      throw ParamError("--out", options.out,
                       fmt::format("holds a converge study of other inputs ({}); use another "
                                   "--out, or --force to rerun into it",
                                   fmt::join(diff, ", ")));
    // the same study (an interrupted one, as its message says): its members continue from
    // their checkpoints, each checked against its own inputs
    continuing = true;
    say("gbssn1d converge: {} holds this study (same inputs): members continue from their "
        "checkpoints\n",
        options.out);
  }
  validate_output_dir([&] {
    Params o = base;
    o.force = options.force || continuing;
    return o;
  }());
  converge_members(base, options); // validates every member before anything is written
  return run_converge(base, options, config_text(base));
}

} // namespace

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

} // namespace

namespace {

int run_command_line(int argc, char** argv) {
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
  CLI::App app{"gbssn1d: spherically symmetric generalized BSSN evolutions of a Schwarzschild "
               "black hole",
               "gbssn1d"};
  app.set_version_flag("--version", std::string("gbssn1d ") + GBSSN1D_VERSION);
  app.require_subcommand(1);
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);

  Params params;
  bool print_config = false;
  std::string config_file; // expanded before parsing; listed here for --help
  CLI::App* evolve_cmd =
      app.add_subcommand("evolve", "evolve one black hole and write ASCII output");
  add_options(*evolve_cmd, params);
  evolve_cmd->footer(
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
  evolve_cmd
      ->add_option("--config", config_file,
                   "read parameters from a TOML/INI file of `key = value` lines (as "
                   "written to OUT/config.toml); flags given too override it")
      ->group("Configuration");
  evolve_cmd
      ->add_flag("--print-config", print_config,
                 "print the effective configuration (a valid --config file) and exit")
      ->group("Configuration");

  // converge: one configuration at several resolutions
  ConvergeOptions converge_options;
  std::string N_list, factors, fields = "alpha,chi,K", scaled_times;
  CLI::App* converge_cmd = app.add_subcommand(
      "converge", "run one configuration (any evolve flags) at three or more resolutions");
  converge_cmd->add_option("--N", N_list, "resolutions, e.g. 320,480,640, or a base N")->required();
  converge_cmd->add_option("--factors", factors, "with a base N: N_k = N * factor, e.g. 1,1.5,2");
  add_number_option(*converge_cmd, "-j,--jobs", converge_options.jobs, "members run at once");
  converge_cmd->add_option("--out", converge_options.out, "output directory")->required();
  converge_cmd->add_flag("--force", converge_options.force, "write into a non-empty --out");
  std::string field_names;
  for (const auto& entry : registry)
    field_names += (field_names.empty() ? "" : ", ") + std::string(entry.name);
  converge_cmd
      ->add_option("--fields", fields,
                   "fields whose differences give orders, comma separated, from: " + field_names)
      ->capture_default_str();
  converge_cmd->add_option("--scaled-times", scaled_times,
                           "times of the Richardson-scaled H profiles (default: tmax)");
  add_number_option(*converge_cmd, "--order", converge_options.order,
                    "order used to scale the profiles");
  double expect_order = 0.0;
  CLI::Option* expect_order_opt = add_number_option(
      *converge_cmd, "--expect-order", expect_order,
      "the order the verdict expects (a study converges when its orders reach this minus 1.5); "
      "recorded in convergence.dat");
  expect_order_opt->default_str("--fd-order");
  converge_cmd->allow_extras();
  converge_cmd->footer(
      "Every other flag is an evolve flag (see `gbssn1d evolve --help`). Every member lives on "
      "the same map (uniform, or sinh fixed by --dr-inner).\nVerdict: for each constraint norm "
      "(H, M_r, G^r on the coordinate window; H, M_r on the areal window) at each pair of "
      "neighbouring members and each --fields difference at each triple, at the times where "
      "the coarse value is above round-off (1e-10 of its scale), the order of its RMS over "
      "time must be at least --expect-order - 1.5, and for the norms so must the order of the "
      "RMS over each tenth of those times (single times are reported, not judged; nor is "
      "H_L2_int). The verdict is written into convergence.dat's header (a `verdict:` line "
      "and an `order` line per quantity and resolutions) and onto stderr, naming the "
      "quantity, the resolutions, the first time below and the lowest order.\nExit status: 0 "
      "completed and converges; 1 a failed write; 2 invalid input (nothing run); 3 a member "
      "stopped (non-finite value, chi or alpha out of range, horizon finder failure); 4 "
      "completed, but does not converge (the verdict); 128 + n interrupted by signal n (rerun "
      "the command to resume).");

  // sweep: the Cartesian product of flag values
  SweepOptions sweep_options;
  CLI::App* sweep_cmd =
      app.add_subcommand("sweep", "run the product of value lists of any evolve flags");
  sweep_cmd
      ->add_option("--sweep", sweep_options.sweeps,
                   "flag=value1,value2,... (repeat for more flags); flags that change together "
                   "share an axis: flag1,flag2=a1:b1,a2:b2")
      ->required();
  CLI::Option* sweep_jobs =
      add_number_option(*sweep_cmd, "-j,--jobs", sweep_options.jobs,
                        "members run at once (not with --emit-tasks: the scheduler runs them)");
  sweep_cmd->add_option("--out", sweep_options.out, "output directory (a rerun resumes)")
      ->required();
  add_number_option(*sweep_cmd, "--progress-every", sweep_options.progress_every,
                    "seconds between progress lines (k of n done, running members) while "
                    "members run, at most 86400; 0: none");
  CLI::Option* sweep_emit = sweep_cmd->add_option(
      "--emit-tasks", sweep_options.emit_tasks,
      "write one command line per valid member (for GNU parallel or a Slurm array) and exit; "
      "each runs its member into --out from any folder and resumes it when requeued");
  CLI::Option* sweep_member = sweep_cmd->add_option(
      "--member", sweep_options.member,
      "run only the member of this name (what an emitted line does); exit 0 finished, 3 blew "
      "up or failed");
  CLI::Option* sweep_collect = sweep_cmd->add_flag(
      "--collect", sweep_options.collect,
      "build summary.dat from the members in --out without running any; exit 0 if all "
      "finished, 1 if some have not run yet, else 3 if any blew up, failed or was invalid");
  sweep_cmd->allow_extras();
  sweep_cmd->footer(
      "Every other flag is an evolve flag, common to all members.\nOUT/summary.dat: a row per "
      "member: its values, status (ok, invalid, blew-up, failed, interrupted, missing; a rerun "
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

  // resume: continue a run from its checkpoint
  std::string resume_dir;
  double resume_tmax = 0.0;
  CLI::App* resume_cmd = app.add_subcommand(
      "resume", "continue a run in DIR from DIR/checkpoint.bin, bit for bit as if uninterrupted");
  resume_cmd->add_option("DIR", resume_dir, "output directory of the run")->required();
  CLI::Option* resume_tmax_opt = add_number_option(*resume_cmd, "--tmax", resume_tmax,
                                                   "new final time (M); default: the run's own");
  resume_tmax_opt->default_str("the run's own");
  resume_cmd->footer("The output files are cut back to the checkpoint and continued.");

  // the flags whose values came from an evolve --config file, and that file: a refused value
  // then says where it was given, since the user typed no such flag
  std::map<std::string, std::string> config_origins;
  auto origin = [&](const std::string& flag) {
    const auto it = config_origins.find(flag);
    return it == config_origins.end() ? std::string()
                                      : fmt::format(" (given as '{}' in --config {})",
                                                    flag.substr(2), printable(it->second));
  };
  auto parse_error_origin = [&](const std::string& what) { // CLI11 names the flag in its text
    for (const auto& [flag, file] : config_origins) {
      const auto at = what.find(flag);
      const auto after = at == std::string::npos ? 0 : at + flag.size();
      if (at != std::string::npos
          && (after == what.size()
              || !(std::isalnum(static_cast<unsigned char>(what[after])) || what[after] == '-')))
        return origin(flag);
    }
    return std::string();
  };

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
      args = expand_config(args, &config_origins);
    std::reverse(args.begin(), args.end()); // CLI11 takes a reversed vector of arguments
    app.parse(args);
  } catch (const CLI::CallForHelp& e) {
    return help_or_version(app, e);
  } catch (const CLI::CallForAllHelp& e) {
    return help_or_version(app, e);
  } catch (const CLI::CallForVersion& e) {
    return help_or_version(app, e);
  } catch (const CLI::ParseError& e) {
    std::string what = e.what();
    std::replace(what.begin(), what.end(), '\n', ' ');
    say("gbssn1d: error: {}{}\n", what, parse_error_origin(what));
    return 2;
  } catch (const ParamError& e) {
    say("gbssn1d: error: {}{}\n", e.what(), origin(e.flag()));
    return 2;
  }

  try {
    if (evolve_cmd->parsed())
      return evolve(params, print_config);
    if (resume_cmd->parsed())
      return resume(resume_dir,
                    resume_tmax_opt->count() > 0 ? std::optional(resume_tmax) : std::nullopt);
    if (converge_cmd->parsed()) {
      if (expect_order_opt->count() > 0) {
        if (!std::isfinite(expect_order) || expect_order <= 0.0 || expect_order > 30.0)
          throw ParamError("--expect-order", fmt::format("{}", expect_order),
                           "must be a number in (0, 30]");
        converge_options.expect_order = expect_order;
      }
      return converge(converge_options, N_list, factors, fields, scaled_times,
                      pass_through(*converge_cmd, {"N", "out", "force"}));
    }
    if (sweep_cmd->parsed()) {
      if (!sweep_options.emit_tasks.empty() && sweep_jobs->count() > 0)
        throw ParamError("-j", std::to_string(sweep_options.jobs),
                         "has no effect with --emit-tasks: the lines run as the scheduler runs "
                         "them (e.g. `parallel -j N < TASKS`, or an array job)");
      if ((sweep_member->count() > 0 || sweep_collect->count() > 0) && sweep_jobs->count() > 0)
        throw ParamError("-j", std::to_string(sweep_options.jobs),
                         "has no effect with --member or --collect (one member, or none, runs)");
      if (sweep_collect->count() > 0 && (sweep_member->count() > 0 || sweep_emit->count() > 0))
        throw ParamError("--collect", "is its own step: not with --member or --emit-tasks");
      if (sweep_member->count() > 0 && sweep_options.member.empty())
        throw ParamError("--member", "''",
                         "names no member (a member folder's name, as in the "
                         "emitted lines)");
      if (sweep_member->count() > 0 && sweep_emit->count() > 0)
        throw ParamError("--member", sweep_options.member, "not with --emit-tasks");
      check_jobs(sweep_options.jobs);
      if (!std::isfinite(sweep_options.progress_every) || sweep_options.progress_every < 0.0
          || sweep_options.progress_every > 86400.0)
        throw ParamError("--progress-every", fmt::format("{}", sweep_options.progress_every),
                         "must be a number of seconds in [0, 86400] (0: no progress lines)");
      const auto evolve_args = pass_through(*sweep_cmd, {"out", "force"});
      parse_evolve_args(evolve_args); // common flags must parse before anything runs
      return run_sweep(sweep_options, evolve_args);
    }
  } catch (const ParamError& e) {
    say("gbssn1d: error: {}{}\n", e.what(), origin(e.flag()));
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
