// `gbssn1d converge`: its own flags (the resolutions, fields, times, the verdict's order), the
// rest passed to every member; the study planned, checked and run (study/converge.hpp).
#include "cli/command_rules.hpp"
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
#include "study/verdict.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

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

/// The study of `options` and the lists as given on the line.
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

} // namespace

int run_converge_command(ConvergeArgs& a) {
  if (a.expect_order_given) {
    // the threshold, --expect-order - kOrderTolerance, must stay positive: at or below 0 a
    // study whose errors do not fall would meet it
    if (!std::isfinite(a.expect_order) || a.expect_order <= kOrderTolerance
        || a.expect_order > 30.0)
      throw ParamError("--expect-order", fmt::format("{}", a.expect_order),
                       fmt::format("must be a number in ({}, 30]: the verdict's threshold, "
                                   "--expect-order - {}, must stay positive",
                                   kOrderTolerance, kOrderTolerance));
    a.options.expect_order = a.expect_order;
  }
  return converge(a.options, a.N_list, a.factors, a.fields, a.scaled_times,
                  pass_through(a.extras, {"N", "out", "force"}));
}

} // namespace gbssn1d
