// Messages for the person at the console (stderr): best effort. A closed terminal or a pipe
// whose reader has gone (EPIPE; SIGPIPE is ignored, see cli) never stops a run or a sweep: the
// output files are authoritative and say how a run ended.
#pragma once

#include <fmt/format.h>

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

} // namespace gbssn1d
