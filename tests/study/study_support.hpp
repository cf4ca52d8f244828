// Helpers of the study tests: the real executable run with arguments, and what its folders hold.
#pragma once

#include "../test_support.hpp"

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace gbssn1d::testing {

/// The executable run with `args` (a shell command line after the program's name): its exit
/// status, and its stderr in `err` if given.
inline int run_study(const std::string& args, std::string* err = nullptr) {
  const std::filesystem::path e = scratch("stderr");
  const std::string cmd =
      std::string(GBSSN1D_EXECUTABLE) + " " + args + " >/dev/null 2>" + e.string();
  const int raw = std::system(cmd.c_str());
  if (err)
    *err = slurp(e);
  std::filesystem::remove(e);
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

/// A study that ran to its end: converging (0), not converging (4), pre-asymptotic (5) or not
/// judged (6: too short, or nothing above the round-off floor). For
/// tests about something else than the verdict, on grids too coarse to be sure of it.
inline bool completed(int status) {
  return status == 0 || status == 4 || status == 5 || status == 6;
}

/// The data rows of a summary.dat, as text (its status and reason columns are words).
inline std::vector<std::string> summary_rows(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::vector<std::string> rows;
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#')
      rows.push_back(line);
  return rows;
}

} // namespace gbssn1d::testing
