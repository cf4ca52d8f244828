// Messages for the person at the console (stderr): best effort. A closed terminal or a pipe
// whose reader has gone (EPIPE; SIGPIPE is ignored, see cli) never stops a run or a sweep: the
// output files are authoritative and say how a run ended.
#pragma once

#include <fmt/format.h>

#include <cstdio>
#include <utility>

namespace gbssn1d {

template <class... T>
void say(fmt::format_string<T...> format, T&&... args) noexcept {
  try {
    fmt::print(stderr, format, std::forward<T>(args)...);
  } catch (...) { // the console is gone: nothing to tell, nothing to stop
  }
}

} // namespace gbssn1d
