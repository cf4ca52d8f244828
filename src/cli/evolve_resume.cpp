#include "cli/commands.hpp"

#include "config/config_file.hpp"
#include "config/folder_lock.hpp"
#include "config/input_files.hpp"
#include "config/param_rules.hpp"
#include "config/params.hpp"
#include "config/paths.hpp"
#include "config/same_run.hpp"
#include "core/console.hpp"
#include "core/registry.hpp"
#include "core/stop_signal.hpp"
#include "core/text.hpp"
#include "evolution/checkpoint.hpp"
#include "evolution/observe.hpp"
#include "evolution/simulation.hpp"
#include "io/output.hpp"

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
#include <string_view>
#include <unistd.h>
#include <variant>

namespace gbssn1d {

namespace {

/// With --force into a folder that is not empty: the entries an evolve run does not write (its
/// files, their temporary names, the lock), named for a warning; empty otherwise.
std::string leftovers_of_force(const Params& p) {
  namespace fs = std::filesystem;
  if (!p.force)
    return {};
  static const std::set<std::string> own = {"timeseries.dat", "profiles.dat",   "horizon.dat",
                                            "config.toml",    "checkpoint.bin", "rah-hAH-file.dat",
                                            folder_lock_name};
  std::vector<std::string> left;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(p.out, ec)) {
    const std::string name = entry.path().filename().string();
    if (!own.count(name) && !name.ends_with(".tmp") && !name.ends_with(".resume"))
      left.push_back(printable(name) + (entry.is_directory(ec) ? "/" : ""));
  }
  std::sort(left.begin(), left.end());
  if (left.size() > 6) {
    const std::size_t more = left.size() - 5;
    left.resize(5);
    left.push_back(fmt::format("and {} more", more));
  }
  return fmt::format("{}", fmt::join(left, ", "));
}

int run_and_report(Simulation& sim, Output& out, const Params& p);

/// The bytes of a file ("" if it cannot be read: the caller's checks refuse such a file).
std::string file_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Warns of a horizon-adjusting shift faster than the grid's Courant limit on the initial data
/// (|beta_H| dt / dr above 1). Not a refusal: the feedback shrinks beta_H as the horizon
/// moves, and such runs can go through (1+log trumpet, N = 200, rah0 1.2: --rahA 200, a
/// Courant number of 7.6 at t = 0, reaches 1000 M; --rahA 500 leaves the physical range at
/// t = 0.06); the warning names the flag for when the run stops.
void warn_shift_courant(const Simulation& sim, const Params& p) {
  const auto c = sim.horizon_shift_courant();
  if (c && !(c->number <= 1.0))
    say("gbssn1d: warning: --rahA {}: the horizon-adjusting shift starts at beta_H = {:.3g} at "
        "r = {:.4g} (h_AH = {:.4g}, --rah0 {}), a Courant number |beta_H| dt / dr of {:.3g} "
        "above 1; if the run stops early, lower --rahA\n",
        num(p.rahA), c->beta_H, c->r, c->h_AH, num(p.rah0), c->number);
}

} // namespace

int evolve(const Params& given, bool print_config) {
  const ResolvedParams p = resolve(given);
  validate(p);
  if (print_config) {
    const std::string text = config_text(p) + rule_values_line(p);
    if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0)
      throw OutputError(fmt::format("cannot write the configuration to standard output: {}",
                                    std::strerror(errno)));
    return 0;
  }
  validate_output_dir(p);
  for (const auto& w : warnings(p))
    say("gbssn1d: warning: {}\n", w);
  if (const std::string left = leftovers_of_force(p); !left.empty())
    say("gbssn1d: warning: --force: {} also holds {}, which this run does not write: left as "
        "they are, beside its own files (another command's output, e.g. a study's?)\n",
        printable(p.out), left);

  Simulation sim(evolution_config(p)); // initial data are computed before anything is written
  sim.show_progress = true;
  warn_shift_courant(sim, p);
  for (const auto& w : empty_norm_windows(sim.composite().grid(), sim.composite_profiles().R_areal,
                                          sim.config().norms))
    say("gbssn1d: warning: {}: {}\n", w.flags, w.what);
  const std::filesystem::path dir(p.out);
  // the content of --rah-hAH-file as it was read (before the folder is made)
  const std::optional<std::string> hAH_content = prescribed_horizon_content(p);
  if (const int signal = stop_signal(); signal != 0) {
    say("gbssn1d: interrupted by {} before the run started; nothing was written\n",
        signal_name(signal));
    return 128 + signal;
  }
  // one writer per folder, from here to the process's end; then the emptiness check again, under
  // the lock: another process may have written the folder since validate_output_dir
  const FolderLock lock("--out", dir);
  if (!p.force && !folder_is_empty(dir))
    throw ParamError("--out", p.out,
                     "exists and is not empty: another process wrote it meanwhile (use --force "
                     "to overwrite)");
  if (p.force) {
    // the earlier run's files this run may not write again go (unlinked: a hard-linked backup
    // keeps them): its checkpoint would otherwise offer `resume` a run this folder no longer
    // holds, its copy of --rah-hAH-file a curve this run does not follow
    std::error_code ignored;
    std::filesystem::remove(dir / "checkpoint.bin", ignored);
    if (!hAH_content)
      std::filesystem::remove(dir / std::string(prescribed_horizon_copy), ignored);
  }
  const std::string config = config_text(p);
  write_file_atomically(dir / "config.toml", header_text("") + config + rule_values_line(p));
  if (hAH_content)
    write_file_atomically(dir / std::string(prescribed_horizon_copy), *hAH_content);
  Output out(dir, config + sim.run_facts(), sim.config().rhs.formulation);
  sim.checkpoint_config = config + copy_hash_line(hAH_content);
  return run_and_report(sim, out, p);
}

namespace {

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

} // namespace

namespace {

/// DIR must hold a run's config.toml and (`with_checkpoint`) checkpoint.bin; a file of the run
/// that cannot even be examined (a loop of symbolic links) is refused.
void check_resume_dir(const std::string& dir_name, bool with_checkpoint) {
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
  {
    std::error_code ec;
    if (!fs::exists(dir, ec) && !ec)
      throw ParamError("DIR", printable(dir_name), "does not exist");
    if (!fs::is_directory(dir, ec))
      throw ParamError("DIR", printable(dir_name), "is not a folder (give a run's output folder)");
  }
  if (!has_file("config.toml"))
    throw ParamError("DIR", dir_name, "has no config.toml (not a gbssn1d output directory)");
  if (with_checkpoint && !has_file("checkpoint.bin"))
    throw ParamError("DIR", dir_name,
                     "has no checkpoint.bin (run with --checkpoint-every T, or stop a run with "
                     "a stop signal: SIGTERM, SIGINT, SIGHUP, SIGUSR1 or SIGUSR2)");
  // resume replaces its config.toml and checkpoint.bin and rewrites its output files (each
  // through a new file renamed into place): refused up front, as evolve refuses an --out it
  // cannot write, not after the checks as a failed write
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    throw ParamError("DIR", printable(dir_name),
                     fmt::format("is not writable ({}): resume writes its config.toml, "
                                 "checkpoint.bin and output files into it",
                                 std::strerror(errno)));
}

/// The run's copy of --rah-hAH-file as its checkpoints record it, and the parameters that
/// continue with it.
struct KeptHorizonFile {
  Params params;
  std::string hash_line; ///< for the checkpoints the resumed run writes ("" without a copy)
};

/// The run's parameters with --rah-hAH-file naming the copy the run took at its start, whatever
/// the flag's path names now (said if that differs). Every run that used the file kept a copy:
/// without it (deleted, a symbolic link, not a regular file, unreadable) or with a copy that is
/// not the one the run read (its hash is not the one `checkpoint_config` records) the folder is
/// refused, naming the copy, rather than continued with other data. A checkpoint of an earlier
/// version records no hash: its copy is taken as it is, with a warning.
KeptHorizonFile with_kept_horizon_file(const Params& p, const std::string& dir_name,
                                       const std::string& checkpoint_config) {
  namespace fs = std::filesystem;
  KeptHorizonFile run{p, ""};
  Params& run_params = run.params;
  if (!uses_hAH_file(p))
    return run;
  const fs::path copy = fs::path(dir_name) / std::string(prescribed_horizon_copy);
  const auto refuse = [&](const std::string& why) {
    return ParamError(
        "DIR", printable(dir_name),
        fmt::format("its copy of --rah-hAH-file, {}, {}: a run continues only with the copy it "
                    "took at its start, not with what {} holds now (put the file the run started "
                    "with there to resume)",
                    printable(copy.string()), why, printable(p.rah_hAH_file)));
  };
  std::error_code ec;
  // the copy itself, not what a link there points to: the run wrote a file, never a link
  const fs::file_status st = fs::symlink_status(copy, ec);
  if (ec && ec != std::errc::no_such_file_or_directory)
    throw refuse("cannot be examined: " + ec.message());
  if (!fs::exists(st))
    throw refuse("is missing");
  if (fs::is_symlink(st))
    throw refuse("is a symbolic link, not the file the run wrote");
  if (!fs::is_regular_file(st))
    throw refuse("is not a regular file");
  std::ifstream in(copy, std::ios::binary);
  std::ostringstream kept;
  kept << in.rdbuf();
  if (!in || in.bad())
    throw refuse("cannot be read");
  const std::string hash = copy_hash(kept.str());
  run.hash_line = copy_hash_line(kept.str());
  if (const auto recorded = recorded_copy_hash(checkpoint_config)) {
    if (*recorded != hash)
      throw refuse("has changed since the run read it (its FNV-1a hash is not the one the "
                   "checkpoint recorded)");
  } else {
    say("gbssn1d: warning: the checkpoint in {} records no hash of {} (an earlier version wrote "
        "it): the copy cannot be checked against the file the run read; it is taken as it is\n",
        printable(dir_name), printable(copy.string()));
  }
  std::optional<std::string> now;
  try {
    now = prescribed_horizon_content(p);
  } catch (const ParamError&) {
  }
  if (!now || *now != kept.str())
    say("gbssn1d: note: --rah-hAH-file {} is not what the run read at its start (edited, "
        "missing, or another file from this folder); it continues with the copy it took then, "
        "{}\n",
        printable(p.rah_hAH_file), copy.string());
  run_params.rah_hAH_file = copy.string();
  return run;
}

} // namespace

int resume(const std::string& dir_name, std::optional<double> tmax) {
  namespace fs = std::filesystem;
  const fs::path dir(dir_name);
  check_resume_dir(dir_name, false);
  // one writer per folder, from before anything is read: a run still writing DIR (which writes
  // no checkpoint until its first) is named as the holder, not reported as a missing checkpoint
  const FolderLock lock("DIR", dir);
  check_resume_dir(dir_name, true);
  // a key added since the run was recorded means what the run did without it
  std::vector<std::string> args{"--config", (dir / "config.toml").string()};
  for (const auto& a : absent_key_args(file_text(dir / "config.toml")))
    args.push_back(a);
  Params given = parse_evolve_args(args);
  if (tmax)
    given.tmax = *tmax;
  given.out = dir_name;
  const ResolvedParams p = resolve(given);
  validate(p);
  Checkpoint c;
  try {
    c = read_checkpoint(dir / "checkpoint.bin");
  } catch (const CheckpointError& e) {
    throw ParamError("DIR", dir_name, e.what());
  }
  const std::string config = config_text(p);
  if (const auto differ = config_differences(c.config, config, {"tmax", "out", "force"});
      !differ.empty())
    throw ParamError("DIR", dir_name,
                     fmt::format("its checkpoint belongs to another configuration ({})",
                                 fmt::join(differ, "; ")));
  if (p.tmax < c.t)
    throw ParamError("--tmax", fmt::format("{}", p.tmax),
                     fmt::format("is before the checkpoint at t = {}", time_text(c.t)));
  // What the files hold already: a completed run is left alone, and no resume may cut away
  // output beyond the new end.
  const SeriesEnd written = series_end(dir / "timeseries.dat");
  if (written.completed && (!tmax || p.tmax <= written.t_last)) {
    say("gbssn1d: {} is complete at t = {}; nothing to do (`{} --tmax T` continues it to a "
        "later T)\n",
        dir_name, time_text(written.t_last), resume_command(dir_name));
    return 0;
  }
  if (p.tmax < written.t_last)
    throw ParamError("--tmax", fmt::format("{}", p.tmax),
                     fmt::format("is before the last output at t = {}: resuming would cut "
                                 "the output written after it",
                                 time_text(written.t_last)));
  const KeptHorizonFile kept = with_kept_horizon_file(p, dir_name, c.config);
  Simulation sim(evolution_config(resolve(kept.params)));
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
  sim.checkpoint_config = config + kept.hash_line;
  write_file_atomically(dir / "config.toml", header_text("") + config + rule_values_line(p));
  say("gbssn1d: resuming {} at t = {} (step {}) to t = {}\n", dir_name, time_text(c.t), c.step,
      time_text(p.tmax));
  Output out(dir, config + sim.run_facts(), sim.config().rhs.formulation, c.marks);
  return run_and_report(sim, out, p);
}

} // namespace gbssn1d
