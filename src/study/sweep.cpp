#include "study/sweep.hpp"

#include "config/folder_lock.hpp"

#include "config/paths.hpp"
#include "core/text.hpp"
#include "study/sweep_process.hpp"
#include "study/sweep_store.hpp"
#include "study/sweep_summary.hpp"
#include "study/sweep_tasks.hpp"

#include "config/config_file.hpp"
#include "config/params.hpp"
#include "core/console.hpp"
#include "core/stop_signal.hpp"
#include "study/parallel.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

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
  refuse_links(dir, {&m}, options.out);
  check_earlier_inputs(dir, {&m}, options.out);
  // member tasks of one sweep run side by side; a whole sweep of the folder excludes them
  const FolderLock lock("--out", dir, LockMode::shared);
  refuse_links(dir, {&m}, options.out); // again, under the lock
  check_earlier_inputs(dir, {&m}, options.out);
  const fs::path status_file = dir / "logs" / (m.name + ".status");
  MemberOutcome o;
  if (member_done(dir, m)) {
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

/// The sweep's axes from its --sweep arguments: each flag on one axis, --out given, at most
/// kMembersMax members.
std::vector<SweepAxis> checked_axes(const SweepOptions& options) {
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
  return axes;
}

/// A value common to all members that no member can run with is a usage error: refused
/// before anything is launched or written.
void check_some_member_valid(const SweepOptions& options, const std::vector<SweepMember>& members) {
  std::string first_error;
  bool any_valid = false;
  for (const auto& m : members) {
    try {
      std::vector<std::string> args(m.args.begin() + 1, m.args.end());
      validate(resolve(parse_evolve_args(args)));
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

/// The members of a sweep run here: the [k/n] line as each finishes, and a line every
/// `every` seconds while members run (on long runs the [k/n] lines can be hours apart).
class SweepProgress {
public:
  using Clock = std::chrono::steady_clock;
  SweepProgress(std::size_t n, std::size_t done_before, double every)
      : n_(n), done_before_(done_before) {
    if (every > 0.0)
      thread_ = std::thread([this, every] { report_every(every); });
  }
  ~SweepProgress() { // the reporter stops however the members end (an exception included)
    if (!thread_.joinable())
      return;
    {
      const std::lock_guard lock(mutex_);
      stop_ = true;
    }
    all_done_.notify_all();
    thread_.join();
  }
  void started(const std::string& name) {
    const std::lock_guard lock(mutex_);
    running_[name] = Clock::now();
  }
  void finished(const std::string& name, const MemberOutcome& o) {
    const std::lock_guard lock(mutex_);
    running_.erase(name);
    ++finished_;
    say("gbssn1d sweep: [{}/{}] {} {} ({:.1f} s){}\n", done_before_ + finished_, n_, name, o.status,
        o.wall, o.status == "ok" ? "" : ": " + o.reason);
  }

private:
  void report_every(double seconds) {
    std::unique_lock lock(mutex_);
    const auto every = std::chrono::duration<double>(seconds);
    while (!all_done_.wait_for(lock, every, [&] { return stop_; })) {
      if (running_.empty())
        continue;
      const auto longest =
          std::min_element(running_.begin(), running_.end(),
                           [](const auto& a, const auto& b) { return a.second < b.second; });
      say("gbssn1d sweep: {} of {} members done, {} running (longest: {}, {:.0f} s)\n",
          done_before_ + finished_, n_, running_.size(), longest->first,
          std::chrono::duration<double>(Clock::now() - longest->second).count());
    }
  }

  std::size_t n_, done_before_, finished_ = 0; ///< finished_: in this run
  std::mutex mutex_;
  std::map<std::string, Clock::time_point> running_; ///< member -> start
  std::condition_variable all_done_;
  bool stop_ = false;
  std::thread thread_;
};

/// Member folders of an earlier sweep into the same folder that this sweep does not list (other
/// values): said, since summary.dat will not hold them; they are left as they are.
void warn_of_unlisted_members(const fs::path& dir, const std::vector<SweepMember>& members) {
  std::set<std::string> listed;
  for (const auto& m : members)
    listed.insert(m.name);
  std::vector<std::string> unlisted;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_directory(ec) && name != "logs" && !listed.count(name)
        && fs::exists(dir / "logs" / (name + ".status"), ec))
      unlisted.push_back(name);
  }
  if (unlisted.empty())
    return;
  std::sort(unlisted.begin(), unlisted.end());
  say("gbssn1d sweep: warning: {} holds {} member folder{} of an earlier sweep that this one "
      "does not list ({}): left as they are, and not in summary.dat\n",
      dir.string(), unlisted.size(), unlisted.size() == 1 ? "" : "s", fmt::join(unlisted, ", "));
}

/// The members run here, -j at a time, then summary.dat. A rerun into the same folder
/// continues the sweep only if every member that has left anything there was run with the
/// inputs it would run with now.
int run_members_here(const SweepOptions& options, const std::vector<SweepAxis>& axes,
                     const std::vector<SweepMember>& members, const std::string& exe) {
  const fs::path dir(options.out);
  refuse_links(dir, all_of(members), options.out);
  check_earlier_inputs(dir, all_of(members), options.out);
  // one sweep of a folder at a time (and no member tasks beside it); then the links and the
  // earlier inputs again, under the lock: a sweep of other inputs may have finished meanwhile
  const FolderLock lock("--out", dir);
  refuse_links(dir, all_of(members), options.out);
  check_earlier_inputs(dir, all_of(members), options.out);
  create_output_dir("--out", dir / "logs");
  record_axis_order(options.out, axes);
  warn_of_unlisted_members(dir, members);
  install_stop_handlers();
  std::size_t done_before = 0; // members finished by an earlier run of the same sweep
  for (const auto& m : members) {
    done_before += member_done(dir, m) ? 1 : 0;
    if (const auto r = recorded_status(dir / "logs" / (m.name + ".status")))
      if (const auto why = member_output_problem(dir, m, r->status))
        say("gbssn1d sweep: {} was recorded {}, but {}: it runs again\n", m.name, r->status, *why);
  }
  {
    SweepProgress progress(members.size(), done_before, options.progress_every);
    run_tasks(members.size(), options.jobs, [&](std::size_t k) {
      const SweepMember& m = members[k];
      if (member_done(dir, m))
        return; // finished in an earlier run of the same sweep
      if (stop_signal() != 0)
        return; // interrupted: start nothing new (a rerun resumes)
      const MemberOutcome o = run_member(dir, m, exe, [&] { progress.started(m.name); });
      progress.finished(m.name, o);
    });
  }
  const auto statuses = write_summary(dir, options, axes, members);
  say("gbssn1d sweep: summary: {} (a row per member; `gbssn1d sweep --help` names its columns)\n",
      (dir / "summary.dat").string());
  if (const int signal = stop_signal(); signal != 0) {
    say("gbssn1d sweep: interrupted by {}; rerun the same command to finish\n",
        signal_name(signal));
    return 128 + signal;
  }
  return exit_status(statuses, members.size());
}

} // namespace

int run_sweep(const SweepOptions& options, const std::vector<std::string>& evolve_args) {
  const std::vector<SweepAxis> axes = checked_axes(options);
  // a swept flag given besides as a flag common to all members: every member would refuse
  // it (given twice); refused here, before anything runs
  for (const auto& axis : axes)
    for (const auto& flag : axis.flags)
      for (const auto& arg : evolve_args)
        if (arg == "--" + flag || arg.rfind("--" + flag + "=", 0) == 0)
          throw ParamError("--sweep", flag,
                           fmt::format("is swept and also given to every member ({}): give it "
                                       "in one place",
                                       printable(arg)));
  refuse_other_commands_folder(options.out);
  check_axis_order(options.out, axes);
  // a task line (--member) builds its own member only: 10,000 members' configurations for each
  // of 10,000 lines was hours of CPU over an array job
  const bool one_member = !options.member.empty() && !options.collect && options.emit_tasks.empty();
  const std::vector<SweepMember> members =
      sweep_members(axes, evolve_args, options.out, one_member ? options.member : "");
  if (one_member && members.empty()) {
    std::size_t count = 1;
    std::vector<std::pair<std::string, std::string>> first, last;
    for (const auto& axis : axes) {
      count *= axis.values.size();
      for (std::size_t f = 0; f < axis.flags.size(); ++f) {
        first.emplace_back(axis.flags[f], axis.values.front()[f]);
        last.emplace_back(axis.flags[f], axis.values.back()[f]);
      }
    }
    throw ParamError("--member", options.member,
                     fmt::format("is not a member of this sweep (its {} members: {}{})", count,
                                 member_name(first), count > 1 ? " ... " + member_name(last) : ""));
  }
  if (options.member.empty() && !options.collect)
    for (const auto& same : same_runs(members))
      say("gbssn1d sweep: note: {}: each is run and listed, with the same results\n", same.text());
  check_some_member_valid(options, members);
  const std::string exe = fs::canonical("/proc/self/exe").string();
  if (!options.member.empty() && !options.collect && options.emit_tasks.empty())
    return run_one_member(options, axes, members, exe);
  if (options.collect) {
    const fs::path dir(options.out);
    refuse_links(dir, all_of(members), options.out);
    check_earlier_inputs(dir, all_of(members), options.out);
    const auto statuses = write_summary(dir, options, axes, members);
    say("gbssn1d sweep: {} collected from {} members (nothing was run)\n",
        (dir / "summary.dat").string(), members.size());
    return exit_status(statuses, members.size());
  }
  if (!options.emit_tasks.empty())
    return emit_tasks(options, axes, members, evolve_args, exe);
  return run_members_here(options, axes, members, exe);
}

} // namespace gbssn1d
