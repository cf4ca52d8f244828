// `gbssn1d resume DIR [--tmax T]`: a run continued from its checkpoint, bit for bit.
#include "cli/commands.hpp"
#include "cli/run_report.hpp"

#include "config/config_file.hpp"
#include "config/folder_lock.hpp"
#include "config/input_files.hpp"
#include "config/params.hpp"
#include "config/paths.hpp"
#include "config/same_run.hpp"
#include "core/console.hpp"
#include "core/stop_signal.hpp"
#include "core/text.hpp"
#include "evolution/checkpoint.hpp"
#include "evolution/simulation.hpp"
#include "io/output.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace gbssn1d {

namespace {

/// The bytes of a file ("" if it cannot be read: the caller's checks refuse such a file).
std::string file_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
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

/// The run in DIR continued from its checkpoint to the run's own or a new tmax.
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
  Output out(dir, config + sim.run_facts(), sim.state().fields(), sim.config().spheres, c.marks);
  return run_and_report(sim, out, p);
}

} // namespace

int run_resume_command(const ResumeArgs& a) {
  return resume(a.dir, a.tmax_given ? std::optional(a.tmax) : std::nullopt);
}

} // namespace gbssn1d
