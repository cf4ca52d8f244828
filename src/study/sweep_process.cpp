#include "study/sweep_process.hpp"

#include "study/sweep_store.hpp"

#include "core/stop_signal.hpp"
#include "io/data_file.hpp"

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

extern char** environ;

namespace gbssn1d {

namespace fs = std::filesystem;

namespace {

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

std::string last_line(const fs::path& file) {
  std::ifstream in(file);
  std::string line, last;
  while (std::getline(in, line))
    if (line.find("error") != std::string::npos)
      last = line;
  return last;
}

} // namespace

MemberOutcome run_member(const fs::path& dir, const SweepMember& m, const std::string& exe,
                         const std::function<void()>& on_start) {
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
    // (a file that cannot even be examined, a loop of symbolic links, is no checkpoint: the
    // member runs afresh, and evolve refuses a folder holding a link, naming it)
    std::error_code ec;
    const bool resumable = fs::is_regular_file(member_dir / "checkpoint.bin", ec)
                           && fs::is_regular_file(member_dir / "config.toml", ec);
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

} // namespace gbssn1d
