#include "study/sweep.hpp"

#include "config/config_file.hpp"
#include "config/numbers.hpp"
#include "config/params.hpp"
#include "core/console.hpp"
#include "core/stop_signal.hpp"
#include "io/output.hpp"
#include "io/table.hpp"
#include "study/orders.hpp"
#include "study/parallel.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <mutex>
#include <set>
#include <spawn.h>
#include <sstream>
#include <sys/file.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

extern char** environ;

namespace gbssn1d {

namespace fs = std::filesystem;

namespace {

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, sep);)
    out.push_back(item);
  return out;
}

/// Runs the executable with `args`, stdout and stderr into `log`; returns the exit status
/// (-1 if it could not start, 128 + n if signal n ended it). A SIGTERM/SIGINT sent to the
/// sweep is passed on to the member, which then stops like an interrupted evolve.
int spawn_and_wait(const std::string& exe, const std::vector<std::string>& args,
                   const fs::path& log) {
  std::vector<std::string> all{exe};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all)
    argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_APPEND, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  pid_t pid;
  const int rc = posix_spawn(&pid, exe.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0)
    return -1;
  int status = 0;
  bool forwarded = false;
  while (true) {
    const pid_t done = waitpid(pid, &status, WNOHANG);
    if (done == pid || (done < 0 && errno != EINTR))
      break;
    if (const int signal = stop_signal(); signal != 0 && !forwarded) {
      ::kill(pid, signal);
      forwarded = true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (WIFSIGNALED(status))
    return 128 + WTERMSIG(status);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// A member's status file, "status wall reason", as a rerun of the sweep reads it back.
struct RecordedStatus {
  std::string status, reason;
  double wall = 0.0;
};
std::optional<RecordedStatus> recorded_status(const fs::path& status_file) {
  std::ifstream in(status_file);
  RecordedStatus r;
  if (!(in >> r.status >> r.wall >> r.reason))
    return std::nullopt;
  return r;
}

/// Whether a member is done for good: finished (ok), or ended by its inputs (invalid, blew-up),
/// which a rerun would only repeat. A member that failed (a write error, killed by a signal of
/// its own such as the kernel's out-of-memory SIGKILL) or was interrupted is not: a rerun of
/// the sweep, or its requeued task line, runs it again, from its checkpoint where it has one.
/// A missing, empty or broken status file counts as not done.
bool member_done(const fs::path& status_file) {
  const auto r = recorded_status(status_file);
  return r && (r->status == "ok" || r->status == "invalid" || r->status == "blew-up");
}

std::string last_line(const fs::path& file) {
  std::ifstream in(file);
  std::string line, last;
  while (std::getline(in, line))
    if (line.find("error") != std::string::npos)
      last = line;
  return last;
}

/// Final r_ah, max |M_ah - M_ah(first)|, max |M_ah - M|, max H_L2_ext and H_L2_R, and the last
/// time of a member's timeseries.dat.
struct MemberResult {
  double r_ah = NAN, M_ah_drift = NAN, M_ah_err = NAN, H_max = NAN, H_final = NAN, H_R_max = NAN,
         t_end = NAN;
};

MemberResult read_result(const fs::path& series) {
  MemberResult res;
  Table table;
  try {
    table = read_table(series);
  } catch (const std::runtime_error&) {
    return res; // no output: every figure stays NaN
  }
  double M0 = NAN;
  for (const auto& values : table.rows) {
    auto row = [&](const char* name) {
      const auto c = table.column(name);
      return c && *c < values.size() ? values[*c] : NAN;
    };
    res.r_ah = row("r_ah");
    if (std::isnan(M0) && std::isfinite(row("M_ah")))
      M0 = row("M_ah");
    const double drift = std::abs(row("M_ah") - M0);
    if (std::isfinite(drift))
      res.M_ah_drift = std::isnan(res.M_ah_drift) ? drift : std::max(res.M_ah_drift, drift);
    const double err = std::abs(row("M_ah_err"));
    if (std::isfinite(err))
      res.M_ah_err = std::isnan(res.M_ah_err) ? err : std::max(res.M_ah_err, err);
    res.H_max = std::isnan(res.H_max) ? row("H_L2_ext") : std::max(res.H_max, row("H_L2_ext"));
    res.H_R_max = std::isnan(res.H_R_max) ? row("H_L2_R") : std::max(res.H_R_max, row("H_L2_R"));
    res.H_final = row("H_L2_ext");
    res.t_end = row("t");
  }
  return res;
}

/// A member's inputs: its effective configuration (defaults resolved), as its config.toml would
/// hold it; for a member that does not parse, its arguments.
std::string member_inputs(const SweepMember& m) {
  try {
    Params p = parse_evolve_args({m.args.begin() + 1, m.args.end() - 2}); // without --out, --force
    p.out.clear();
    resolve_defaults(p);
    return config_text(p);
  } catch (const std::exception&) {
    return fmt::format("args = \"{}\"\n", fmt::join(m.args, " "));
  }
}

/// What an earlier run of the sweep in `dir` ran member `m` with: the inputs file written when
/// it started, or (for a member folder without one) the member's config.toml; empty if nothing
/// of it is there.
std::string earlier_inputs(const fs::path& dir, const SweepMember& m) {
  std::error_code ec; // a path that cannot be examined holds nothing (its creation is refused)
  for (const fs::path& file : {dir / "logs" / (m.name + ".inputs"), dir / m.name / "config.toml"})
    if (fs::is_regular_file(file, ec)) {
      std::ifstream in(file);
      std::stringstream s;
      s << in.rdbuf();
      return s.str();
    }
  return {};
}

std::string token(std::string s) {
  for (char& c : s)
    if (c == ' ' || c == '\t')
      c = '_';
  return s.empty() ? "-" : s;
}

} // namespace

SweepAxis parse_sweep_axis(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
    throw ParamError("--sweep", text, "must look like flag=value1,value2,...");
  SweepAxis axis;
  axis.flags = split(text.substr(0, eq), ',');
  for (const auto& flag : axis.flags) {
    if (!is_parameter_name(flag))
      throw ParamError("--sweep", text, fmt::format("'{}' is not an evolve flag", flag));
    if (flag == "out" || flag == "force")
      throw ParamError("--sweep", text, "the sweep chooses each member's --out itself");
  }
  if (std::any_of(text.begin(), text.end(), [](unsigned char c) { return c < 0x20 || c == 0x7f; }))
    throw ParamError("--sweep", printable(text),
                     "holds a control character (a value must be one line of text)");
  for (const auto& point : split(text.substr(eq + 1), ',')) {
    std::vector<std::string> values = split(point, ':');
    if (values.size() != axis.flags.size()
        || std::any_of(values.begin(), values.end(), [](const auto& v) { return v.empty(); }))
      throw ParamError(
          "--sweep", text,
          fmt::format("'{}' must give {} value(s) joined by ':'", point, axis.flags.size()));
    for (const auto& v : values)
      if (v.find_first_of(" \t") != std::string::npos)
        throw ParamError("--sweep", printable(text),
                         fmt::format("the value '{}' holds white space (a value is one word: "
                                     "summary.dat's columns are separated by spaces)",
                                     printable(v)));
    axis.values.push_back(values);
  }
  return axis;
}

std::vector<SweepMember> sweep_members(const std::vector<SweepAxis>& axes,
                                       const std::vector<std::string>& evolve_args,
                                       const std::string& out) {
  std::vector<SweepMember> members{SweepMember{}};
  for (const auto& axis : axes) {
    std::vector<SweepMember> next;
    for (const auto& m : members)
      for (const auto& point : axis.values) {
        SweepMember n = m;
        for (std::size_t f = 0; f < axis.flags.size(); ++f)
          n.values.emplace_back(axis.flags[f], point[f]);
        next.push_back(n);
      }
    members = next;
  }
  for (auto& m : members) {
    for (const auto& [flag, value] : m.values) {
      std::string part = flag + "=" + value;
      for (char& c : part)
        if (c == '/' || c == ' ')
          c = '_';
      m.name += (m.name.empty() ? "" : "_") + part;
    }
    m.args = {"evolve"};
    m.args.insert(m.args.end(), evolve_args.begin(), evolve_args.end());
    for (const auto& [flag, value] : m.values)
      m.args.push_back("--" + flag + "=" + value);
    m.args.push_back("--out=" + (fs::path(out) / m.name).string());
    m.args.push_back("--force");
    m.inputs = member_inputs(m);
  }
  // Two members in one folder would share (and overwrite) their results, and two members of
  // one configuration would run the same thing twice and repeat it in the summary.
  std::map<std::string, const SweepMember*> by_name, by_config;
  auto values_text = [](const SweepMember& m) {
    std::string s;
    for (const auto& [flag, value] : m.values)
      s += (s.empty() ? "" : " ") + flag + "=" + value;
    return printable(s);
  };
  for (const auto& m : members) {
    // the folder, and logs/NAME.inputs, .status, .lock, .log: each a name of at most 255 bytes
    if (m.name.size() + std::string(".inputs").size() > 255)
      throw ParamError("--sweep", values_text(m),
                       fmt::format("gives a member folder name of {} bytes; with its log files' "
                                   "suffixes the system's limit of 255 is passed (shorter values)",
                                   m.name.size()));
    if (const auto [it, fresh] = by_name.emplace(m.name, &m); !fresh)
      throw ParamError("--sweep", values_text(m),
                       fmt::format("gives the member folder '{}' of '{}' again", printable(m.name),
                                   values_text(*it->second)));
    if (const auto [it, fresh] = by_config.emplace(m.inputs, &m); !fresh)
      throw ParamError(
          "--sweep", values_text(m),
          fmt::format("runs the same configuration as '{}'", values_text(*it->second)));
  }
  return members;
}

namespace {

/// A member's inputs without the horizon-shift flags if its strength is 0 (where they do
/// nothing): members with equal keys are the same run.
std::string same_run_key(const std::string& inputs) {
  if (inputs.find("\nrahA = 0\n") == std::string::npos && inputs.rfind("rahA = 0\n", 0) != 0)
    return inputs;
  std::istringstream lines(inputs);
  std::string key;
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("rah", 0) != 0 || line.rfind("rahA ", 0) == 0)
      key += line + "\n";
  return key;
}

/// Groups of members that are the same run (the horizon-shift flags of a member with rahA = 0
/// do nothing), each as "a = b = c"; said on stderr and in summary.dat, so that nobody reads
/// them as different results.
std::vector<std::string> same_runs(const std::vector<SweepMember>& members) {
  std::map<std::string, std::vector<std::string>> groups;
  std::vector<std::string> order;
  for (const auto& m : members) {
    const std::string key = same_run_key(m.inputs);
    auto& g = groups[key];
    if (g.empty())
      order.push_back(key);
    g.push_back(m.name);
  }
  std::vector<std::string> out;
  for (const auto& key : order)
    if (groups[key].size() > 1)
      out.push_back(fmt::format("{}", fmt::join(groups[key], " = ")));
  return out;
}

/// Why `m` cannot run (its flags do not validate), or nullopt.
std::optional<std::string> invalid_reason(const SweepMember& m) {
  try {
    std::vector<std::string> args(m.args.begin() + 1, m.args.end());
    Params p = parse_evolve_args(args);
    resolve_defaults(p);
    validate(p);
    return std::nullopt;
  } catch (const std::exception& e) {
    return std::string(e.what());
  }
}

/// A folder that holds members run with other inputs is refused (naming them) before anything
/// is written or launched: results of other inputs are never reused or mixed in.
void check_earlier_inputs(const fs::path& dir, const std::vector<const SweepMember*>& members,
                          const std::string& out) {
  std::vector<std::string> changed;
  for (const SweepMember* m : members) {
    const std::string before = earlier_inputs(dir, *m);
    if (before.empty())
      continue;
    const auto diff = config_differences(before, m->inputs);
    if (!diff.empty())
      changed.push_back(fmt::format("{} ({})", m->name, fmt::join(diff, ", ")));
  }
  if (!changed.empty())
    throw ParamError(
        "--out", out,
        fmt::format("holds members run with other inputs: {}; nothing was run or changed. "
                    "Use another --out, or remove those members' folders and logs/ files to "
                    "rerun them",
                    fmt::join(changed.begin(),
                              changed.begin() + std::min<std::ptrdiff_t>(changed.size(), 3), "; "))
            + (changed.size() > 3 ? fmt::format(" (and {} more)", changed.size() - 3) : ""));
}

std::vector<const SweepMember*> all_of(const std::vector<SweepMember>& members) {
  std::vector<const SweepMember*> all;
  for (const auto& m : members)
    all.push_back(&m);
  return all;
}

/// What one member's run ended with.
struct MemberOutcome {
  std::string status = "ok", reason = "-";
  double wall = 0.0;
};

/// Runs member `m` to completion (from its checkpoint if it has one) as a subprocess, with its
/// inputs, log and status in DIR/logs/: the one place a member is run, by a sweep and by an
/// emitted task line alike. `on_start` is called when the subprocess starts.
MemberOutcome run_member(const fs::path& dir, const SweepMember& m, const std::string& exe,
                         const std::function<void()>& on_start = {}) {
  MemberOutcome o;
  // one process at a time runs a member (a task line started twice, or two sweeps of one
  // folder): the lock is released when this process ends, however it ends
  const fs::path lock_file = dir / "logs" / (m.name + ".lock");
  const int lock = ::open(lock_file.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
  if (lock < 0)
    throw OutputError(
        fmt::format("cannot create {}: {}", lock_file.string(), std::strerror(errno)));
  if (::flock(lock, LOCK_EX | LOCK_NB) != 0) {
    ::close(lock);
    o.status = "busy";
    o.reason = fmt::format("another process runs this member (it holds {})", lock_file.string());
    return o; // its status file is the other process's
  }
  struct Unlock {
    int fd;
    ~Unlock() { ::close(fd); }
  } unlock{lock};
  // the time an earlier, unfinished attempt took counts: wall_s is the member's total
  const double earlier_wall = [&] {
    const auto r = recorded_status(dir / "logs" / (m.name + ".status"));
    return r && std::isfinite(r->wall) && r->wall > 0.0 ? r->wall : 0.0;
  }();
  write_file_atomically(dir / "logs" / (m.name + ".inputs"), m.inputs);
  // Invalid values are caught here, before a subprocess is started.
  if (const auto why = invalid_reason(m)) {
    o.status = "invalid";
    o.reason = *why;
  } else {
    if (on_start)
      on_start();
    const auto start = std::chrono::steady_clock::now();
    const fs::path log = dir / "logs" / (m.name + ".log");
    // a member stopped with a checkpoint (interrupted, killed, or requeued) continues from it
    const fs::path member_dir = dir / m.name;
    const bool resumable = fs::is_regular_file(member_dir / "checkpoint.bin")
                           && fs::is_regular_file(member_dir / "config.toml");
    const std::vector<std::string> args =
        resumable ? std::vector<std::string>{"resume", member_dir.string()} : m.args;
    const int rc = spawn_and_wait(exe, args, log);
    o.wall = earlier_wall
             + std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (rc > 128 && stop_signal() != 0) {
      o.status = "interrupted";
      o.reason = "interrupted by " + signal_name(rc - 128);
    } else if (rc != 0) {
      o.status = rc == 3 ? "blew-up" : "failed";
      o.reason = last_line(log);
      if (o.reason.empty())
        o.reason =
            rc > 128 ? "killed by " + signal_name(rc - 128) : fmt::format("exit status {}", rc);
    }
  }
  write_file_atomically(dir / "logs" / (m.name + ".status"),
                        fmt::format("{} {} {}\n", o.status, o.wall, token(o.reason)));
  return o;
}

/// A member's H_L2_R_max far above its neighbours'.
struct Spike {
  std::size_t member = 0;
  std::string axis; ///< the axis' flags, e.g. "rahA" or "rahA,rah0"
  double median = 0.0, factor = 0.0;
  std::size_t neighbours = 0;
};

/// The finished members whose H_L2_R_max exceeds kSpikeFactor times the median of their
/// neighbours along some axis: the other finished members that differ from them in that
/// axis' values only. Axes that vary N are skipped (there H falls with N by design). A member
/// is reported once, along the axis with the largest factor.
std::vector<Spike> find_spikes(const std::vector<SweepAxis>& axes,
                               const std::vector<std::string>& resolution_axis,
                               const std::vector<SweepMember>& members,
                               const std::vector<std::string>& statuses,
                               const std::vector<MemberResult>& results) {
  auto usable = [&](std::size_t k) {
    return statuses[k] == "ok" && std::isfinite(results[k].H_R_max) && results[k].H_R_max > 0.0;
  };
  std::map<std::size_t, Spike> found;
  for (const auto& axis : axes) {
    if (axis.flags == resolution_axis)
      continue;
    // the line of each member along this axis: the members with its values on every other axis
    std::map<std::string, std::vector<std::size_t>> lines;
    for (std::size_t k = 0; k < members.size(); ++k) {
      std::string key;
      for (const auto& [flag, value] : members[k].values)
        if (std::find(axis.flags.begin(), axis.flags.end(), flag) == axis.flags.end())
          key += flag + "=" + value + ";";
      if (usable(k))
        lines[key].push_back(k);
    }
    for (const auto& [key, ks] : lines)
      for (std::size_t k : ks) {
        std::vector<double> others;
        for (std::size_t j : ks)
          if (j != k)
            others.push_back(results[j].H_R_max);
        if (others.empty())
          continue;
        std::sort(others.begin(), others.end());
        const std::size_t n = others.size();
        const double median =
            n % 2 == 1 ? others[n / 2] : std::sqrt(others[n / 2 - 1] * others[n / 2]);
        const double factor = results[k].H_R_max / median;
        if (factor > kSpikeFactor && (!found.count(k) || factor > found[k].factor))
          found[k] = Spike{k, fmt::format("{}", fmt::join(axis.flags, ",")), median, factor, n};
      }
  }
  std::vector<Spike> out;
  for (const auto& [k, sp] : found)
    out.push_back(sp);
  return out;
}

/// Each distinct `gbssn1d: warning:` line of the members' logs, once, with the members that
/// gave it.
void report_warnings(const fs::path& dir, const std::vector<SweepMember>& members) {
  const std::string prefix = "gbssn1d: warning: ";
  std::vector<std::string> order;
  std::map<std::string, std::vector<std::string>> who;
  for (const auto& m : members) {
    std::ifstream log(dir / "logs" / (m.name + ".log"));
    std::set<std::string> seen; // a member counts once per warning
    for (std::string line; std::getline(log, line);) {
      if (line.rfind(prefix, 0) != 0)
        continue;
      const std::string text = line.substr(prefix.size());
      if (!seen.insert(text).second)
        continue;
      auto& list = who[text];
      if (list.empty())
        order.push_back(text);
      list.push_back(m.name);
    }
  }
  for (const auto& text : order) {
    const auto& list = who[text];
    const std::size_t shown = std::min<std::size_t>(list.size(), 6);
    say("gbssn1d sweep: warning from {} member(s) ({}{}): {}\n", list.size(),
        fmt::join(list.begin(), list.begin() + static_cast<std::ptrdiff_t>(shown), ", "),
        list.size() > shown ? fmt::format(" and {} more", list.size() - shown) : "", text);
  }
}

/// DIR/summary.dat from the members' status files and outputs (nothing is run); members
/// without a status are `invalid` if their flags do not validate, `missing` otherwise. Returns
/// each member's status.
std::vector<std::string> write_summary(const fs::path& dir, const SweepOptions& options,
                                       const std::vector<SweepAxis>& axes,
                                       const std::vector<SweepMember>& members) {
  std::vector<std::string> cols;
  std::vector<std::string> resolution_axis; // the flags that vary together with N
  for (const auto& axis : axes) {
    cols.insert(cols.end(), axis.flags.begin(), axis.flags.end());
    if (std::find(axis.flags.begin(), axis.flags.end(), "N") != axis.flags.end())
      resolution_axis = axis.flags;
  }
  const bool with_resolutions = !resolution_axis.empty();
  for (const char* c : {"status", "flag", "t_end", "r_ah_final", "M_ah_drift", "M_ah_err_max",
                        "H_L2_ext_max", "H_L2_R_max", "wall_s"})
    cols.emplace_back(c);
  if (with_resolutions)
    cols.emplace_back("order_H_final");
  cols.emplace_back("reason");

  std::vector<MemberResult> results(members.size());
  std::vector<std::string> statuses(members.size()), reasons(members.size());
  std::vector<double> walls(members.size(), 0.0);
  for (std::size_t k = 0; k < members.size(); ++k) {
    std::ifstream in(dir / "logs" / (members[k].name + ".status"));
    in >> statuses[k] >> walls[k] >> reasons[k];
    if (statuses[k].empty()) {
      const auto why = invalid_reason(members[k]);
      statuses[k] = why ? "invalid" : "missing";
      reasons[k] = why ? token(*why) : "-";
    }
    results[k] = read_result(dir / members[k].name / "timeseries.dat");
  }
  // order of the final H_L2_ext over each group of members that differ only in N
  std::vector<double> orders(members.size(), NAN);
  if (with_resolutions) {
    std::map<std::string, std::vector<std::size_t>> groups;
    for (std::size_t k = 0; k < members.size(); ++k) {
      std::string key;
      for (const auto& [flag, value] : members[k].values)
        if (std::find(resolution_axis.begin(), resolution_axis.end(), flag)
            == resolution_axis.end())
          key += flag + "=" + value + ";";
      groups[key].push_back(k);
    }
    for (const auto& [key, ks] : groups) {
      std::vector<double> N, E;
      for (std::size_t k : ks)
        if (statuses[k] == "ok") {
          for (const auto& [flag, value] : members[k].values)
            if (flag == "N")
              N.push_back(parse_number<int>("--sweep", value)); // as the member read it
          E.push_back(results[k].H_final);
        }
      if (N.size() >= 2)
        for (std::size_t k : ks)
          orders[k] = order_fitted(N, E);
    }
  }
  const std::vector<Spike> spikes = find_spikes(axes, resolution_axis, members, statuses, results);
  for (const auto& sp : spikes)
    reasons[sp.member] =
        token(fmt::format("spike: H_L2_R_max {:.2e} is {:.0f} times the median "
                          "{:.2e} of its neighbours along {}",
                          results[sp.member].H_R_max, sp.factor, sp.median, sp.axis));
  std::string same;
  for (const auto& g : same_runs(members))
    same += "same run (rahA = 0: the horizon-shift flags do nothing): " + g + "\n";
  DataFile summary(
      dir / "summary.dat",
      same
          + fmt::format("sweep over {} members: {}\nr_ah_final is the last r_ah; "
                        "M_ah_drift = max |M_ah - M_ah(first)|; M_ah_err_max = max |M_ah - M|; "
                        "H_L2_ext_max, H_L2_R_max over the run; t_end the last time; "
                        "order_H_final fitted over N for members that differ only in N\n"
                        "flag: spike for a finished member whose H_L2_R_max is more than {:g} "
                        "times the median of its neighbours along an axis (the finished "
                        "members that differ from it in that axis' values only; not along an "
                        "axis of N), '-' otherwise; the reason says along which axis\n",
                        members.size(), fmt::join(options.sweeps, " "), kSpikeFactor),
      cols);
  for (std::size_t k = 0; k < members.size(); ++k) {
    std::string line;
    for (const auto& [flag, value] : members[k].values)
      line += value + " ";
    const MemberResult& res = results[k];
    const bool spiked =
        std::any_of(spikes.begin(), spikes.end(), [&](const Spike& sp) { return sp.member == k; });
    line += fmt::format("{} {} {:.6g} {:.10e} {:.6e} {:.6e} {:.6e} {:.6e} {:.3f}", statuses[k],
                        spiked ? "spike" : "-", res.t_end, res.r_ah, res.M_ah_drift, res.M_ah_err,
                        res.H_max, res.H_R_max, walls[k]);
    if (with_resolutions)
      line += fmt::format(" {:.4f}", orders[k]);
    line += " " + reasons[k] + "\n";
    summary.write(line.data(), line.size());
  }
  summary.flush(); // checked: a failed write throws OutputError
  for (const auto& sp : spikes)
    say("gbssn1d sweep: spike: {} has max H_L2_R = {:.2e}, {:.0f} times the median {:.2e} of its "
        "{} neighbour(s) along {}; flagged in summary.dat\n",
        members[sp.member].name, results[sp.member].H_R_max, sp.factor, sp.median, sp.neighbours,
        sp.axis);
  report_warnings(dir, members);
  return statuses;
}

/// The sweep's axes in their order (OUT/logs/axes): member folders are named in that order,
/// so a rerun, --member or --collect with the axes in another order would find none of them.
std::string axis_order_text(const std::vector<SweepAxis>& axes) {
  std::string text;
  for (const auto& axis : axes)
    text += fmt::format("{}\n", fmt::join(axis.flags, ","));
  return text;
}

void record_axis_order(const std::string& out, const std::vector<SweepAxis>& axes) {
  const fs::path file = fs::path(out) / "logs" / "axes";
  create_output_dir("--out", file.parent_path());
  if (!fs::exists(file))
    write_file_atomically(file, axis_order_text(axes));
}

/// Refuses axes in another order than the folder's sweep (or other axes), naming its order.
void check_axis_order(const std::string& out, const std::vector<SweepAxis>& axes) {
  std::ifstream in(fs::path(out) / "logs" / "axes");
  if (!in)
    return; // a new sweep, or one from before the axes were recorded
  std::ostringstream text;
  text << in.rdbuf();
  const std::string now = axis_order_text(axes);
  if (text.str() == now)
    return;
  std::vector<std::string> before, given;
  std::istringstream a(text.str()), b(now);
  for (std::string line; std::getline(a, line);)
    before.push_back(line);
  for (std::string line; std::getline(b, line);)
    given.push_back(line);
  auto sorted = [](std::vector<std::string> v) {
    std::sort(v.begin(), v.end());
    return v;
  };
  throw ParamError(
      "--sweep", fmt::format("{}", fmt::join(given, " ")),
      sorted(before) == sorted(given)
          ? fmt::format("gives the axes of the sweep in {} in another order: give them as it "
                        "did, {} (member folders are named in that order)",
                        printable(out), fmt::join(before, " then "))
          : fmt::format("{} holds a sweep over other flags ({}): use another --out", printable(out),
                        fmt::join(before, " then ")));
}

/// `sweep ... --member NAME`: that member alone, as an emitted task line runs it (checked
/// against the inputs of what its folder holds, resumed from its checkpoint, its log and status
/// in DIR/logs/). Exit status: 0 finished, 3 blew up or failed, 2 invalid, 128 + signal when
/// interrupted; a member finished earlier is not rerun and gives its recorded status.
int run_one_member(const SweepOptions& options, const std::vector<SweepAxis>& axes,
                   const std::vector<SweepMember>& members, const std::string& exe) {
  const auto it = std::find_if(members.begin(), members.end(),
                               [&](const SweepMember& m) { return m.name == options.member; });
  if (it == members.end())
    throw ParamError("--member", options.member,
                     fmt::format("is not a member of this sweep (its {} members: {}{})",
                                 members.size(), members.front().name,
                                 members.size() > 1 ? " ... " + members.back().name : ""));
  const SweepMember& m = *it;
  const fs::path dir(options.out);
  check_earlier_inputs(dir, {&m}, options.out);
  const fs::path status_file = dir / "logs" / (m.name + ".status");
  MemberOutcome o;
  if (member_done(status_file)) {
    std::ifstream in(status_file);
    in >> o.status >> o.wall >> o.reason;
    say("gbssn1d sweep: {} finished earlier: {}\n", m.name, o.status);
  } else {
    create_output_dir("--out", dir / "logs");
    record_axis_order(options.out, axes);
    install_stop_handlers();
    o = run_member(dir, m, exe);
    if (o.status == "busy")
      throw ParamError("--member", printable(m.name), o.reason + "; nothing was run");
    say("gbssn1d sweep: {} {} ({:.1f} s){}\n", m.name, o.status, o.wall,
        o.status == "ok" ? "" : ": " + o.reason);
  }
  if (o.status == "ok")
    return 0;
  if (o.status == "invalid")
    return 2;
  if (o.status == "interrupted")
    return stop_signal() != 0 ? 128 + stop_signal() : 3;
  return 3;
}

/// The exit status for a set of member statuses: 0 if all finished, 1 if some have not run yet
/// (--collect before every line ran), else 3 if any blew up, failed or was invalid.
int exit_status(const std::vector<std::string>& statuses, std::size_t n) {
  std::map<std::string, std::size_t> count;
  for (const auto& s : statuses)
    ++count[s];
  if (count["ok"] == n)
    return 0;
  std::vector<std::string> parts;
  for (const auto& [status, k] : count)
    if (status != "ok" && k > 0)
      parts.push_back(fmt::format("{} {}", k, status));
  say("gbssn1d sweep: {} of {} members did not complete ({}; see summary.dat)\n", n - count["ok"],
      n, fmt::join(parts, ", "));
  // members not run yet: the study is not complete, whatever the others did (collect again)
  return count["missing"] > 0 ? 1 : 3;
}

} // namespace

int run_sweep(const SweepOptions& options, const std::vector<std::string>& evolve_args) {
  std::vector<SweepAxis> axes;
  for (const auto& s : options.sweeps)
    axes.push_back(parse_sweep_axis(s));
  if (axes.empty())
    throw ParamError("--sweep", "''", "give at least one flag=values list");
  {
    std::set<std::string> flags; // a flag on two axes would mislabel the members
    for (const auto& axis : axes)
      for (const auto& flag : axis.flags)
        if (!flags.insert(flag).second)
          throw ParamError("--sweep", flag, "is swept more than once (one axis per flag)");
  }
  if (options.out.empty())
    throw ParamError("--out", "''", "an output directory is required");
  check_path("--out", options.out);
  {
    double count = 1.0;
    std::vector<std::string> sizes;
    for (const auto& axis : axes) {
      count *= static_cast<double>(axis.values.size());
      sizes.push_back(
          fmt::format("{} ({} values)", fmt::join(axis.flags, ","), axis.values.size()));
    }
    if (count > static_cast<double>(kMembersMax))
      throw ParamError("--sweep", fmt::format("{}", fmt::join(sizes, " x ")),
                       fmt::format("gives {:.0f} members, more than {}: split it into sweeps "
                                   "of fewer values (each into its own --out)",
                                   count, kMembersMax));
  }
  check_axis_order(options.out, axes);
  const std::vector<SweepMember> members = sweep_members(axes, evolve_args, options.out);
  if (options.member.empty() && !options.collect)
    for (const auto& g : same_runs(members))
      say("gbssn1d sweep: note: {} are the same run (the horizon-shift flags do nothing with "
          "rahA = 0); each is run and listed, with the same results\n",
          g);
  // A value common to all members that no member can run with is a usage error: refused
  // before anything is launched or written.
  {
    std::string first_error;
    bool any_valid = false;
    for (const auto& m : members) {
      try {
        std::vector<std::string> args(m.args.begin() + 1, m.args.end());
        Params p = parse_evolve_args(args);
        resolve_defaults(p);
        validate(p);
        any_valid = true;
        break;
      } catch (const ParamError& e) {
        if (first_error.empty())
          first_error = e.what();
      }
    }
    if (!any_valid && !first_error.empty())
      throw ParamError("--sweep", fmt::format("{}", fmt::join(options.sweeps, " ")),
                       "no member is valid: " + first_error);
  }
  const std::string exe = fs::canonical("/proc/self/exe").string();

  const fs::path dir(options.out);
  if (!options.member.empty() && !options.collect && options.emit_tasks.empty())
    return run_one_member(options, axes, members, exe);
  if (options.collect) {
    check_earlier_inputs(dir, all_of(members), options.out);
    const auto statuses = write_summary(dir, options, axes, members);
    say("gbssn1d sweep: summary.dat collected from {} members (nothing was run)\n", members.size());
    return exit_status(statuses, members.size());
  }
  if (!options.emit_tasks.empty()) {
    // One line per valid member, each the one-member form of this very sweep: it runs that
    // member (resuming its checkpoint when requeued) and writes its results, log and status
    // into the sweep's folder, from whatever folder the scheduler starts it in. Invalid
    // members are not emitted; --collect marks them.
    check_earlier_inputs(dir, all_of(members), options.out);
    {
      // the folder every line runs its member into must be able to be one: refused here, not
      // by each task on the cluster (a sweep's folder may hold members already: a rerun)
      Params o;
      o.out = options.out;
      o.force = true;
      validate_output_dir(o);
    }
    const std::string cwd = fs::current_path().string();
    const std::string abs_out = fs::absolute(options.out).lexically_normal().string();
    std::string lines;
    std::size_t emitted = 0;
    for (const auto& m : members) {
      if (const auto why = invalid_reason(m)) {
        say("gbssn1d sweep: {} not emitted: {}\n", m.name, *why);
        continue;
      }
      lines += "cd " + shell_quote(cwd) + " && " + shell_quote(exe) + " sweep --out "
               + shell_quote(abs_out) + " --member " + shell_quote(m.name) + " --progress-every 0";
      for (const auto& sw : options.sweeps)
        lines += " --sweep " + shell_quote(sw);
      for (const auto& a : evolve_args)
        lines += ' ' + shell_quote(a);
      lines += '\n';
      ++emitted;
    }
    check_path("--emit-tasks", options.emit_tasks);
    // the task file must not take the place of the folder its lines run members into
    {
      const fs::path tasks_path = fs::absolute(options.emit_tasks).lexically_normal();
      for (fs::path p = fs::absolute(options.out).lexically_normal(); p.has_relative_path();
           p = p.parent_path())
        if (p == tasks_path || p.string() + "/" == tasks_path.string())
          throw ParamError("--emit-tasks", printable(options.emit_tasks),
                           "names --out's folder (or one it lies in): the task lines would take "
                           "its place");
    }
    if (abs_out.find_first_of("\n\r") != std::string::npos)
      throw ParamError("--out", printable(options.out),
                       "holds a line break, which would split its task lines");
    // an existing file is not overwritten unless it holds these very lines (a rerun of the
    // same emit); a device or FIFO (/dev/stdout into a pipe) is written to as it is
    if (fs::is_regular_file(options.emit_tasks)) {
      std::ifstream old(options.emit_tasks, std::ios::binary);
      std::ostringstream text;
      text << old.rdbuf();
      if (text.str() != lines)
        throw ParamError("--emit-tasks", printable(options.emit_tasks),
                         "exists and holds something else: nothing was written (name a new "
                         "file, or remove this one)");
    }
    std::ofstream tasks(options.emit_tasks);
    if (!tasks)
      throw ParamError("--emit-tasks", options.emit_tasks, "cannot be written");
    tasks << lines;
    tasks.close(); // flushes: a full disk shows here
    if (!tasks)
      throw OutputError(fmt::format("--emit-tasks {}: the command lines could not be written",
                                    options.emit_tasks));
    record_axis_order(options.out, axes); // (the folder is made once the lines are written)
    say("gbssn1d sweep: {} member command lines written to {} (of {} members); then "
        "`gbssn1d sweep ... --collect` with the same flags builds summary.dat\n",
        emitted, options.emit_tasks, members.size());
    return 0;
  }

  // A rerun into the same folder continues the sweep only if every member that has left
  // anything there was run with the inputs it would run with now.
  check_earlier_inputs(dir, all_of(members), options.out);
  create_output_dir("--out", dir / "logs");
  record_axis_order(options.out, axes);
  install_stop_handlers();
  std::mutex mutex;
  std::size_t finished = 0; // members done in this run (under `mutex`)
  using Clock = std::chrono::steady_clock;
  std::map<std::string, Clock::time_point> running; // member -> start (under `mutex`)
  std::size_t done_before = 0; // members finished by an earlier run of the same sweep
  for (const auto& m : members)
    done_before += member_done(dir / "logs" / (m.name + ".status")) ? 1 : 0;
  // A progress line every progress_every seconds while members run: on long runs the [k/n]
  // lines can be hours apart.
  std::condition_variable all_done;
  bool stop_progress = false;
  std::thread progress;
  if (options.progress_every > 0.0)
    progress = std::thread([&] {
      std::unique_lock lock(mutex);
      const auto every = std::chrono::duration<double>(options.progress_every);
      while (!all_done.wait_for(lock, every, [&] { return stop_progress; })) {
        if (running.empty())
          continue;
        const auto longest =
            std::min_element(running.begin(), running.end(),
                             [](const auto& a, const auto& b) { return a.second < b.second; });
        say("gbssn1d sweep: {} of {} members done, {} running (longest: {}, {:.0f} s)\n",
            done_before + finished, members.size(), running.size(), longest->first,
            std::chrono::duration<double>(Clock::now() - longest->second).count());
      }
    });
  auto member_task = [&](std::size_t k) {
    {
      const SweepMember& m = members[k];
      const fs::path status_file = dir / "logs" / (m.name + ".status");
      if (member_done(status_file))
        return; // finished in an earlier run of the same sweep
      if (stop_signal() != 0)
        return; // interrupted: start nothing new (a rerun resumes)
      const MemberOutcome o = run_member(dir, m, exe, [&] {
        const std::lock_guard lock(mutex);
        running[m.name] = Clock::now();
      });
      const std::string& status = o.status;
      const std::string& reason = o.reason;
      const double wall = o.wall;
      const std::lock_guard lock(mutex);
      running.erase(m.name);
      ++finished;
      say("gbssn1d sweep: [{}/{}] {} {} ({:.1f} s){}\n", done_before + finished, members.size(),
          m.name, status, wall, status == "ok" ? "" : ": " + reason);
    }
  };
  {
    struct JoinOnExit { // the reporter stops however run_tasks ends (an exception included)
      std::function<void()> stop;
      ~JoinOnExit() { stop(); }
    } join_progress{[&] {
      if (!progress.joinable())
        return;
      {
        const std::lock_guard lock(mutex);
        stop_progress = true;
      }
      all_done.notify_all();
      progress.join();
    }};
    run_tasks(members.size(), options.jobs, member_task);
  }

  const auto statuses = write_summary(dir, options, axes, members);
  if (const int signal = stop_signal(); signal != 0) {
    say("gbssn1d sweep: interrupted by {}; rerun the same command to finish\n",
        signal_name(signal));
    return 128 + signal;
  }
  return exit_status(statuses, members.size());
}

} // namespace gbssn1d
