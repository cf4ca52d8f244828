// Messages for the person at the console (stderr): best effort. A closed terminal or a pipe
// whose reader has gone (EPIPE; SIGPIPE is ignored, see cli) never stops a run or a sweep: the
// output files are authoritative and say how a run ended.
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <utility>

namespace gbssn1d {

template <class... T>
void say(fmt::format_string<T...> format, T&&... args) noexcept {
  try {
    fmt::print(stderr, format, std::forward<T>(args)...);
  } catch (...) { // the console is gone: nothing to tell, nothing to stop
  }
}

/// `s` as one word of a POSIX shell: as it is if it holds only safe characters, else in single
/// quotes (a ' inside as '\''), so that a printed command works as pasted.
inline std::string shell_quote(const std::string& s) {
  if (!s.empty()
      && s.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                             "0123456789-_=.,/:+")
             == std::string::npos)
    return s;
  std::string q = "'";
  for (char c : s)
    q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

/// The program as the user invoked it (argv[0]: `gbssn1d` when found on PATH, or a path such
/// as ./build/gbssn1d), for commands printed as hints; set once by the command line.
inline std::string& invoked_as() {
  static std::string name = "gbssn1d";
  return name;
}

/// "`PROGRAM resume DIR`" as a command that works as pasted from the current folder.
inline std::string resume_command(const std::string& dir) {
  return shell_quote(invoked_as()) + " resume " + shell_quote(dir);
}

/// The progress line on stderr (when it is a terminal): simulated time, the speed since this
/// run (or resume) started, and the time left at that speed.
class ProgressLine {
public:
  ProgressLine(bool on, double t_start, double t_end)
      : on_(on), t_start_(t_start), t_end_(t_end), start_(std::chrono::steady_clock::now()),
        last_(start_) {}
  void update(double t, bool last) {
    const auto now = std::chrono::steady_clock::now();
    if (!on_ || (!last && now - last_ <= std::chrono::milliseconds(500)))
      return;
    last_ = now;
    const double wall = std::chrono::duration<double>(now - start_).count();
    const double speed = (t - t_start_) / std::max(wall, 1e-9); // simulated M per wall second
    say("\r  t = {:.2f} / {:g} M   {:.1f} M/s   {:.0f} s left   ", t, t_end_, speed,
        (t_end_ - t) / std::max(speed, 1e-300));
    if (last)
      say("\n");
  }

private:
  bool on_;
  double t_start_, t_end_;
  std::chrono::steady_clock::time_point start_, last_;
};

} // namespace gbssn1d
