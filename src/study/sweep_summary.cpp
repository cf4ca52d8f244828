#include "study/sweep_summary.hpp"

#include "study/sweep_store.hpp"

#include "config/numbers.hpp"
#include "core/console.hpp"
#include "io/data_file.hpp"
#include "io/table.hpp"
#include "study/orders.hpp"

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

namespace {

/// Whether `flag` is idle in member `m`: given where it does nothing.
bool idle_in(const SweepMember& m, const std::string& flag) {
  return std::any_of(m.idle.begin(), m.idle.end(), [&](const SweepMember::Idle& i) {
    return std::find(i.flags.begin(), i.flags.end(), flag) != i.flags.end();
  });
}

/// The warnings of member `m` about flags that the sweep itself made idle: each flag the
/// warning names acts in another member (e.g. rah0 in a sweep over rahA = 0, 0.5), so the
/// member is a reference by design, not a user's slip.
std::set<std::string> idle_by_design(const SweepMember& m, const std::vector<SweepMember>& all) {
  std::set<std::string> out;
  for (const auto& idle : m.idle)
    if (std::all_of(idle.flags.begin(), idle.flags.end(), [&](const std::string& flag) {
          return std::any_of(all.begin(), all.end(),
                             [&](const SweepMember& o) { return &o != &m && !idle_in(o, flag); });
        }))
      out.insert(idle.warning);
  return out;
}

} // namespace

/// Each distinct `gbssn1d: warning:` line of the members' logs, once, with the members that
/// gave it (but the warnings about flags that the sweep itself made idle: idle_by_design).
void report_warnings(const fs::path& dir, const std::vector<SweepMember>& members) {
  const std::string prefix = "gbssn1d: warning: ";
  std::vector<std::string> order;
  std::map<std::string, std::vector<std::string>> who;
  for (const auto& m : members) {
    std::ifstream log(dir / "logs" / (m.name + ".log"));
    std::set<std::string> seen; // a member counts once per warning
    const std::set<std::string> by_design = idle_by_design(m, members);
    for (std::string line; std::getline(log, line);) {
      if (line.rfind(prefix, 0) != 0)
        continue;
      const std::string text = line.substr(prefix.size());
      if (by_design.count(text))
        continue;
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

/// The order of the final H_L2_ext over each group of finished members that differ only in the
/// axis of N (`resolution_axis`), for every member of the group; NaN elsewhere.
std::vector<double> final_H_orders(const std::vector<SweepMember>& members,
                                   const std::vector<std::string>& resolution_axis,
                                   const std::vector<std::string>& statuses,
                                   const std::vector<MemberResult>& results) {
  std::vector<double> orders(members.size(), NAN);
  if (resolution_axis.empty())
    return orders;
  std::map<std::string, std::vector<std::size_t>> groups;
  for (std::size_t k = 0; k < members.size(); ++k) {
    std::string key;
    for (const auto& [flag, value] : members[k].values)
      if (std::find(resolution_axis.begin(), resolution_axis.end(), flag) == resolution_axis.end())
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
  return orders;
}

/// What each member's folder and log say: its status, wall time, reason and results.
struct MemberStates {
  std::vector<MemberResult> results;
  std::vector<std::string> statuses, reasons;
  std::vector<double> walls;
};

MemberStates read_member_states(const fs::path& dir, const std::vector<SweepMember>& members) {
  MemberStates m;
  m.results.resize(members.size());
  m.statuses.resize(members.size());
  m.reasons.resize(members.size());
  m.walls.assign(members.size(), 0.0);
  for (std::size_t k = 0; k < members.size(); ++k) {
    std::ifstream in(dir / "logs" / (members[k].name + ".status"));
    in >> m.statuses[k] >> m.walls[k] >> m.reasons[k];
    if (m.statuses[k].empty()) {
      const auto why = invalid_reason(members[k]);
      m.statuses[k] = why ? "invalid" : "missing";
      m.reasons[k] = why ? token(*why) : "-";
    }
    // a member recorded ok or blew-up whose output is gone or cut short is not a result
    if (const auto why = member_output_problem(dir, members[k], m.statuses[k])) {
      m.statuses[k] = "missing";
      m.reasons[k] = token(*why);
    }
    m.results[k] = read_result(dir / members[k].name / "timeseries.dat");
  }
  return m;
}

/// summary.dat's header: the members that are the same run, the sweep, and the columns' meaning.
std::string summary_header(const SweepOptions& options, const std::vector<SweepMember>& members) {
  std::string same;
  for (const auto& g : same_runs(members))
    same += g.text() + "\n";
  return same
         + fmt::format("sweep over {} members: {}\nr_ah_final is the last r_ah; "
                       "M_ah_drift = max |M_ah - M_ah(first)|; M_ah_err_max = max |M_ah - M|; "
                       "H_L2_ext_max, H_L2_R_max over the run; t_end the last time; "
                       "order_H_final fitted over N for members that differ only in N\n"
                       "flag: spike for a finished member whose H_L2_R_max is more than {:g} "
                       "times the median of its neighbours along an axis (the finished "
                       "members that differ from it in that axis' values only; not along an "
                       "axis of N), '-' otherwise; the reason says along which axis\n",
                       members.size(), fmt::join(options.sweeps, " "), kSpikeFactor);
}

} // namespace

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

  MemberStates states = read_member_states(dir, members);
  const std::vector<MemberResult>& results = states.results;
  std::vector<std::string>& statuses = states.statuses;
  std::vector<std::string>& reasons = states.reasons;
  const std::vector<double>& walls = states.walls;
  const std::vector<double> orders = final_H_orders(members, resolution_axis, statuses, results);
  const std::vector<Spike> spikes = find_spikes(axes, resolution_axis, members, statuses, results);
  for (const auto& sp : spikes)
    reasons[sp.member] =
        token(fmt::format("spike: H_L2_R_max {:.2e} is {:.0f} times the median "
                          "{:.2e} of its neighbours along {}",
                          results[sp.member].H_R_max, sp.factor, sp.median, sp.axis));
  DataFile summary(dir / "summary.dat", summary_header(options, members), cols);
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
        "{} neighbour(s) along {}; flagged in summary.dat{}\n",
        members[sp.member].name, results[sp.member].H_R_max, sp.factor, sp.median, sp.neighbours,
        sp.axis,
        sp.neighbours == 1 ? fmt::format(" (with two values of {} a spike and a trend look alike: "
                                         "a third value tells them apart)",
                                         sp.axis)
                           : std::string());
  report_warnings(dir, members);
  return statuses;
}

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

} // namespace gbssn1d
