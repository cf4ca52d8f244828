// Helpers of the command-line tests: the real executable run with arguments (to its end, or
// stopped by a signal), and what a refusal must look like.
#pragma once

#include "../test_support.hpp"
#include "config/config_file.hpp"
#include "config/params.hpp"

#include <doctest/doctest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace gbssn1d::testing {

/// What a run of the executable left: its exit status, stderr and stdout.
struct Result {
  int status;
  std::string err, out;
};

/// The words of a command line, split at white space (no quoting).
inline std::vector<std::string> command_words(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string w; in >> w;)
    out.push_back(w);
  return out;
}

/// The resolved parameters of an evolve command line (split at white space, no quoting).
inline ResolvedParams resolved_evolve(const std::string& args) {
  return resolve(parse_evolve_args(command_words(args)));
}

/// The executable run with `args` (a shell command line after the program's name).
inline Result run(const std::string& args) {
  const std::filesystem::path err = scratch("stderr"), out = scratch("stdout");
  const std::string cmd =
      std::string(GBSSN1D_EXECUTABLE) + " " + args + " >" + out.string() + " 2>" + err.string();
  const int raw = std::system(cmd.c_str());
  Result r{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(err), slurp(out)};
  std::filesystem::remove(err);
  std::filesystem::remove(out);
  return r;
}

/// When run_signalled stops its run: once each of `files` exists and is not empty (looked for
/// every `poll` seconds, and no longer once the run has ended), `settle` seconds later (0: at
/// once), by SIG`signal`. The run's stderr goes to `err`.
struct SignalWhen {
  std::vector<std::filesystem::path> files;
  std::string signal; ///< TERM, INT, KILL, ...
  double poll;
  double settle = 0.0;
  std::string err = "/dev/null";
};

/// The executable run in the background by sh with `args` (a shell command line after the
/// program's name) and sent a signal as `when` says; std::system's status, whose WEXITSTATUS is
/// the run's (128 + n when it died of signal n).
inline int run_signalled(const std::string& args, const SignalWhen& when) {
  std::ostringstream cmd;
  cmd << "sh -c '" << GBSSN1D_EXECUTABLE << " " << args << " 2>" << when.err << " & p=$!;";
  for (const std::filesystem::path& file : when.files)
    cmd << " while [ ! -s " << file.string() << " ] && kill -0 $p 2>/dev/null; do sleep "
        << when.poll << "; done;";
  if (when.settle > 0.0)
    cmd << " sleep " << when.settle << ";";
  cmd << " kill -" << when.signal << " $p; wait $p; exit $?'";
  return std::system(cmd.str().c_str());
}

/// The number a run printed after `phrase` on its stderr ("the data's ADM mass: "); fails the
/// test case when it printed none.
inline double number_after(const std::string& err, const std::string& phrase) {
  const auto at = err.find(phrase);
  REQUIRE_MESSAGE(at != std::string::npos, "no \"" << phrase << "\" in: " << err);
  return std::stod(err.substr(at + phrase.size()));
}

inline int count_lines(const std::string& s) {
  int n = 0;
  for (char c : s)
    n += c == '\n';
  return n;
}

/// A refused run: non-zero exit, one line on stderr that names `flag`, no output directory.
inline void check_refused(const std::string& args, const std::string& flag) {
  const std::filesystem::path out = scratch("out");
  const std::string tmax = args.find("--tmax") == std::string::npos ? "--tmax 0 " : "";
  const Result r = run("evolve " + tmax + "--out " + out.string() + " " + args);
  INFO("args: " << args << "\nstderr: " << r.err);
  if (flag != "more than once")
    CHECK(r.err.find("more than once") == std::string::npos); // refused for its own reason
  CHECK(r.status != 0);
  CHECK(count_lines(r.err) == 1);
  CHECK(r.err.find(flag) != std::string::npos);
  CHECK(r.err.find("error") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(out));
}

/// The file without its `out = ...` header line (the directory's own name).
inline std::string without_out(const std::filesystem::path& file) {
  std::istringstream in(slurp(file));
  std::string kept;
  for (std::string line; std::getline(in, line);)
    if (line.rfind("# out = ", 0) != 0 && line.rfind("out = ", 0) != 0)
      kept += line + "\n";
  return kept;
}

} // namespace gbssn1d::testing
