#include "cli/commands.hpp"

#include "config/config_file.hpp"
#include "config/folder_lock.hpp"
#include "config/input_files.hpp"
#include "config/numbers.hpp"
#include "config/params.hpp"
#include "config/paths.hpp"
#include "core/console.hpp"
#include "core/registry.hpp"
#include "core/text.hpp"
#include "study/converge.hpp"

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
#include <variant>

namespace gbssn1d {

namespace {

/// An item of a comma-separated list as a number (the one reader, config/numbers.hpp), or
/// ParamError naming `flag` and the list.
template <class T>
T list_number(const std::string& flag, const std::string& list, const std::string& item) {
  if (const auto value = parse_decimal<T>(item))
    return *value;
  throw ParamError(flag, printable(list),
                   fmt::format("'{}' is not {}", printable(item), number_kind<T>()));
}

/// The items of "a,b,c"; ParamError naming `flag` for an empty list or an empty item.
std::vector<std::string> split_list(const std::string& flag, const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');)
    out.push_back(item);
  if (out.empty() || (!s.empty() && s.back() == ',')
      || std::any_of(out.begin(), out.end(), [](const auto& item) { return item.empty(); }))
    throw ParamError(flag, s.empty() ? "''" : printable(s),
                     "must be a comma-separated list without empty items");
  return out;
}

} // namespace

void check_jobs(int jobs) {
  constexpr int jobs_max = 1024;
  if (jobs < 1 || jobs > jobs_max)
    throw ParamError("-j", std::to_string(jobs), fmt::format("must lie in [1, {}]", jobs_max));
}

void refuse_repeated_flags(const std::vector<std::string>& args) {
  std::set<std::string> seen;
  for (const auto& a : args) {
    const bool short_jobs = a.rfind("-j", 0) == 0;
    if ((a.rfind("--", 0) != 0 || a == "--") && !short_jobs)
      continue;
    std::string name = a.substr(0, a.find('='));
    if (short_jobs || name == "--jobs")
      name = "-j/--jobs";
    if (name == "--sweep")
      continue;
    if (!seen.insert(name).second)
      throw ParamError(name, "is given more than once (a flag may be given once; flags given "
                             "with --config may be overridden once)");
  }
}

void refuse_empty_values(const std::vector<std::string>& args) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.size() > 2 && a.rfind("--", 0) == 0 && a.back() == '=')
      throw ParamError(a.substr(0, a.size() - 1),
                       "is given an empty value: put the value after '=', or leave the flag out");
    if (a.empty()) {
      const bool after_flag = i > 0 && args[i - 1].rfind("-", 0) == 0;
      throw ParamError(after_flag ? args[i - 1] : std::string("argument"),
                       after_flag ? "is given an empty value: give a value, or leave the flag out"
                                  : "an empty argument is not a value of any flag");
    }
  }
}

std::vector<std::string> pass_through(const CLI::App& cmd, const std::vector<std::string>& own) {
  std::vector<std::string> extras = cmd.remaining();
  for (const auto& a : extras)
    for (const auto& flag : own)
      if (a == "--" + flag || a.rfind("--" + flag + "=", 0) == 0)
        throw ParamError("--" + flag, a, "is set by the study itself for each member");
  return extras;
}

namespace {

/// --N, --factors, --fields and --scaled-times read into `options` (the times checked against
/// the run's tmax later, parse_converge_times).
void parse_converge_lists(ConvergeOptions& options, const std::string& N_list,
                          const std::string& factors, const std::string& fields) {
  options.N.clear();
  for (const auto& n : split_list("--N", N_list))
    options.N.push_back(list_number<int>("--N", N_list, n));
  if (!factors.empty()) { // a base N and factors: N_k = round(N * f_k)
    if (options.N.size() != 1)
      throw ParamError("--factors", factors, "needs a single base --N");
    const int base_N = options.N.front();
    options.N.clear();
    for (const auto& f : split_list("--factors", factors)) {
      const double factor = list_number<double>("--factors", factors, f);
      if (!(factor > 0))
        throw ParamError("--factors", factors, "factors must be > 0");
      const double n = base_N * factor;
      if (std::abs(n - std::round(n)) > 1e-9 * n || n > 1e7)
        throw ParamError(
            "--factors", factors,
            fmt::format("--N {} x {} = {} is not a whole number of cells", base_N, f, n));
      options.N.push_back(static_cast<int>(std::lround(n)));
    }
  }
  options.fields = split_list("--fields", fields);
  // each field once: a field twice would be two equal columns of every table
  for (std::size_t k = 0; k < options.fields.size(); ++k)
    for (std::size_t j = 0; j < k; ++j)
      if (options.fields[j] == options.fields[k])
        throw ParamError("--fields", printable(fields),
                         fmt::format("lists {} twice", printable(options.fields[k])));
}

/// --scaled-times: each in [0, tmax], each once (a block per time).
void check_scaled_times(const ConvergeOptions& options, const std::string& times, double tmax) {
  for (const double t : options.scaled_times)
    if (t < 0.0 || t > tmax)
      throw ParamError("--scaled-times", printable(times),
                       fmt::format("{} is outside the run's [0, tmax = {}]", t, tmax));
  // each time once: a block per time, and two equal times would write the same block twice
  for (std::size_t k = 0; k < options.scaled_times.size(); ++k)
    for (std::size_t j = 0; j < k; ++j)
      if (options.scaled_times[j] == options.scaled_times[k])
        throw ParamError("--scaled-times", printable(times),
                         fmt::format("lists {} twice", options.scaled_times[k]));
}

/// With --force into a folder of another command's output: what the study will not write,
/// said and left as it is.
void warn_of_foreign_files(const ConvergeOptions& options) {
  std::set<std::string> own = {"config.toml", "convergence.dat", "scaled_H.dat", folder_lock_name};
  for (int n : options.N)
    own.insert(fmt::format("N{}", n));
  std::vector<std::string> left;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(options.out, ec)) {
    const std::string name = entry.path().filename().string();
    if (!own.count(name) && !name.ends_with(".tmp"))
      left.push_back(printable(name) + (entry.is_directory(ec) ? "/" : ""));
  }
  std::sort(left.begin(), left.end());
  if (!left.empty())
    say("gbssn1d converge: warning: --force: {} also holds {}, which this study does not "
        "write: left as they are, beside its own files\n",
        printable(options.out), fmt::join(left, ", "));
}

/// The members' warnings (as evolve's), each once, naming the members it concerns when not all.
void say_member_warnings(const std::vector<ResolvedParams>& members) {
  std::vector<std::pair<std::string, std::vector<int>>> said;
  for (const ResolvedParams& m : members)
    for (const auto& w : warnings(m)) {
      auto it = std::find_if(said.begin(), said.end(), [&](const auto& x) { return x.first == w; });
      if (it == said.end())
        said.push_back({w, {m.N}});
      else
        it->second.push_back(m.N);
    }
  for (const auto& [w, Ns] : said)
    say("gbssn1d converge: warning{}: {}\n",
        Ns.size() == members.size() ? std::string() : fmt::format(" (N = {})", fmt::join(Ns, ", ")),
        w);
}

} // namespace

int converge(const ConvergeOptions& options_in, const std::string& N_list,
             const std::string& factors, const std::string& fields, const std::string& times,
             const std::vector<std::string>& evolve_args) {
  ConvergeOptions options = options_in;
  parse_converge_lists(options, N_list, factors, fields);
  options.scaled_times.clear();
  if (!times.empty())
    for (const auto& t : split_list("--scaled-times", times))
      options.scaled_times.push_back(list_number<double>("--scaled-times", times, t));
  if (!std::isfinite(options.order) || options.order <= 0.0 || options.order > 30.0)
    throw ParamError("--order", fmt::format("{}", options.order),
                     "must be a number in (0, 30] (H is scaled by (N/N_0)^order)");
  check_jobs(options.jobs);
  Params given = parse_evolve_args(evolve_args);
  given.N = options.N.front(); // the first member; each member sets its own
  given.out = options.out;
  const ResolvedParams base = resolve(given);
  check_scaled_times(options, times, base.tmax);
  check_path("--out", options.out);
  bool continuing = false;
  // A folder of another command's run, or a converge study of other inputs: refused, saying
  // which, so that nobody takes --force lightly (with --force the members rerun; a member
  // resumes only from a checkpoint of its own inputs). The same study (an interrupted one, as
  // its message says): its members continue from their checkpoints, each checked against its
  // own inputs.
  if (!options.force && holds_this_study(options.out, config_text(base), input_files_text(base))) {
    continuing = true;
    // another list of N (a study extended, or a member dropped) is said: a member folder of
    // the earlier list that this one does not name is left beside the new ones (run_converge
    // names it)
    const std::string earlier = study_resolutions(options.out);
    const std::string now = fmt::format("{}", fmt::join(options.N, ","));
    say("gbssn1d converge: {} holds this study (same inputs{}): a completed member whose "
        "output files are unchanged keeps its records, the others continue from their last "
        "checkpoints; a member without one runs again\n",
        options.out,
        earlier == now ? "" : fmt::format(" but N: {} where it ran N = {}", now, earlier));
  }
  validate_output_dir([&] {
    Params o = base.flags();
    o.force = options.force || continuing;
    return o;
  }());
  if (options.force && !continuing) // what --force leaves of another command's output
    warn_of_foreign_files(options);
  // validates every member before anything is written
  const std::vector<ResolvedParams> members = converge_members(base, options);
  say_member_warnings(members);
  return run_converge(base, options, config_text(base));
}

} // namespace gbssn1d
