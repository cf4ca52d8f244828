#include "study/sweep_store.hpp"

#include "config/config_file.hpp"
#include "config/params.hpp"
#include "config/paths.hpp"
#include "config/same_run.hpp"
#include "core/decimal.hpp"
#include "core/text.hpp"
#include "io/output.hpp"

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

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, sep);)
    out.push_back(item);
  return out;
}

/// A member's inputs and end time: its effective configuration (defaults resolved), as its
/// config.toml would hold it, and its tmax; for a member that does not parse, its arguments
/// (and no end time).
void set_inputs(SweepMember& m) {
  try {
    Params p = parse_evolve_args({m.args.begin() + 1, m.args.end() - 2}); // without --out, --force
    p.out.clear();
    resolve_defaults(p);
    m.inputs = config_text(p);
    m.run_key = run_key(p);
    m.idle.clear();
    for (const auto& group : idle_flags(p))
      m.idle.push_back({group.warning(), group.flags});
    m.tmax = p.tmax;
  } catch (const std::exception&) {
    m.inputs = fmt::format("args = \"{}\"\n", fmt::join(m.args, " "));
    m.run_key = m.inputs;
    m.idle.clear();
    m.tmax.reset();
  }
}

/// What an earlier run of the sweep in `dir` ran member `m` with: the inputs file written when
/// it started, or (for a member folder without one) the member's config.toml; empty if nothing
/// of it is there.
std::string earlier_inputs(const fs::path& dir, const SweepMember& m) {
  std::error_code ec; // a path that cannot be examined holds nothing (its creation is refused)
  for (const fs::path& file : {dir / "logs" / (m.name + ".inputs"), dir / m.name / "config.toml"})
    if (fs::is_regular_file(file, ec)) {
      std::ifstream in(file);
      std::stringstream s;
      s << in.rdbuf();
      return s.str();
    }
  return {};
}

/// The sweep's axes in their order (OUT/logs/axes): member folders are named in that order,
/// so a rerun, --member or --collect with the axes in another order would find none of them.
std::string axis_order_text(const std::vector<SweepAxis>& axes) {
  std::string text;
  for (const auto& axis : axes)
    text += fmt::format("{}\n", fmt::join(axis.flags, ","));
  return text;
}

} // namespace

std::optional<RecordedStatus> recorded_status(const fs::path& status_file) {
  std::ifstream in(status_file);
  RecordedStatus r;
  if (!(in >> r.status >> r.wall >> r.reason))
    return std::nullopt;
  return r;
}

std::optional<std::string> member_output_problem(const fs::path& dir, const SweepMember& m,
                                                 const std::string& status) {
  if (status != "ok" && status != "blew-up")
    return std::nullopt;
  std::error_code ec;
  if (!fs::is_directory(dir / m.name, ec))
    return fmt::format("its folder {} is missing", (dir / m.name).string());
  const fs::path series = dir / m.name / "timeseries.dat";
  if (!fs::is_regular_file(series, ec))
    return fmt::format("its {} is missing", series.string());
  // the end line the run wrote last: read the file's tail only
  std::ifstream in(series, std::ios::binary);
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  const std::streamoff from = std::max<std::streamoff>(0, size - 4096);
  in.seekg(from);
  std::string tail(static_cast<std::size_t>(std::max<std::streamoff>(0, size - from)), '\0');
  in.read(tail.data(), static_cast<std::streamsize>(tail.size()));
  const std::string want = status == "ok" ? "# end: completed" : "# end: stopped";
  const auto cut = [&](const std::string& why) {
    return fmt::format("its {} is cut short ({})", series.string(), why);
  };
  // the end line counts only whole: with its line end (the run writes it in one piece, the
  // line end last), and a completed run's time read in full as the member's end time
  if (!in || tail.empty() || tail.back() != '\n')
    return cut(fmt::format("it does not end with a whole '{}' line", want));
  tail.pop_back();
  const std::string last =
      tail.substr(tail.rfind('\n') == std::string::npos ? 0 : tail.rfind('\n') + 1);
  if (last.rfind(want, 0) != 0)
    return cut(fmt::format("it does not end with '{}'", want));
  if (status == "ok") {
    const std::string at = "# end: completed at t = ";
    const auto t =
        last.rfind(at, 0) == 0 ? parse_decimal<double>(last.substr(at.size())) : std::nullopt;
    if (!t || !m.tmax || *t != *m.tmax)
      return cut(fmt::format("its end line '{}' does not say the member's end time, t = {}",
                             printable(last), m.tmax ? fmt::format("{}", *m.tmax) : "?"));
  }
  return std::nullopt;
}

bool member_done(const fs::path& dir, const SweepMember& m) {
  const auto r = recorded_status(dir / "logs" / (m.name + ".status"));
  return r && (r->status == "ok" || r->status == "invalid" || r->status == "blew-up")
         && !member_output_problem(dir, m, r->status);
}

std::string token(std::string s) {
  for (char& c : s)
    if (c == ' ' || c == '\t')
      c = '_';
  return s.empty() ? "-" : s;
}

SweepAxis parse_sweep_axis(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
    throw ParamError("--sweep", text, "must look like flag=value1,value2,...");
  SweepAxis axis;
  axis.flags = split(text.substr(0, eq), ',');
  for (const auto& flag : axis.flags) {
    if (!is_parameter_name(flag))
      throw ParamError("--sweep", text, fmt::format("'{}' is not an evolve flag", flag));
    if (flag == "out" || flag == "force")
      throw ParamError("--sweep", text, "the sweep chooses each member's --out itself");
  }
  if (std::any_of(text.begin(), text.end(), [](unsigned char c) { return c < 0x20 || c == 0x7f; }))
    throw ParamError("--sweep", printable(text),
                     "holds a control character (a value must be one line of text)");
  for (const auto& point : split(text.substr(eq + 1), ',')) {
    std::vector<std::string> values = split(point, ':');
    if (values.size() != axis.flags.size()
        || std::any_of(values.begin(), values.end(), [](const auto& v) { return v.empty(); }))
      throw ParamError(
          "--sweep", text,
          fmt::format("'{}' must give {} value(s) joined by ':'", point, axis.flags.size()));
    for (const auto& v : values)
      if (v.find_first_of(" \t") != std::string::npos)
        throw ParamError("--sweep", printable(text),
                         fmt::format("the value '{}' holds white space (a value is one word: "
                                     "summary.dat's columns are separated by spaces)",
                                     printable(v)));
    axis.values.push_back(values);
  }
  return axis;
}

std::string member_name(const std::vector<std::pair<std::string, std::string>>& values) {
  std::string name;
  for (const auto& [flag, value] : values) {
    std::string part = flag + "=" + value;
    for (char& c : part)
      if (c == '/' || c == ' ')
        c = '_';
    name += (name.empty() ? "" : "_") + part;
  }
  return name;
}

std::vector<SweepMember> sweep_members(const std::vector<SweepAxis>& axes,
                                       const std::vector<std::string>& evolve_args,
                                       const std::string& out, const std::string& only) {
  std::vector<SweepMember> members{SweepMember{}};
  for (const auto& axis : axes) {
    std::vector<SweepMember> next;
    for (const auto& m : members)
      for (const auto& point : axis.values) {
        SweepMember n = m;
        for (std::size_t f = 0; f < axis.flags.size(); ++f)
          n.values.emplace_back(axis.flags[f], point[f]);
        next.push_back(n);
      }
    members = next;
  }
  for (auto& m : members)
    m.name = member_name(m.values);
  if (!only.empty()) {
    // one member: its name must be one member's alone (the full sweep, emitting its lines,
    // checked every name and configuration)
    std::vector<SweepMember> one;
    for (auto& m : members)
      if (m.name == only)
        one.push_back(std::move(m));
    if (one.size() > 1)
      throw ParamError("--member", printable(only), "names more than one member's folder");
    members = std::move(one);
  }
  for (auto& m : members) {
    m.args = {"evolve"};
    m.args.insert(m.args.end(), evolve_args.begin(), evolve_args.end());
    for (const auto& [flag, value] : m.values)
      m.args.push_back("--" + flag + "=" + value);
    m.args.push_back("--out=" + (fs::path(out) / m.name).string());
    m.args.push_back("--force");
    set_inputs(m);
  }
  // Two members in one folder would share (and overwrite) their results, and two members of
  // one configuration would run the same thing twice and repeat it in the summary.
  std::map<std::string, const SweepMember*> by_name, by_config;
  auto values_text = [](const SweepMember& m) {
    std::string s;
    for (const auto& [flag, value] : m.values)
      s += (s.empty() ? "" : " ") + flag + "=" + value;
    return printable(s);
  };
  for (const auto& m : members) {
    // the folder, and logs/NAME.inputs, .status, .lock, .log: each a name of at most 255 bytes
    if (m.name.size() + std::string(".inputs").size() > 255)
      throw ParamError("--sweep", values_text(m),
                       fmt::format("gives a member folder name of {} bytes; with its log files' "
                                   "suffixes the system's limit of 255 is passed (shorter values)",
                                   m.name.size()));
    if (const auto [it, fresh] = by_name.emplace(m.name, &m); !fresh)
      throw ParamError("--sweep", values_text(m),
                       fmt::format("gives the member folder '{}' of '{}' again", printable(m.name),
                                   values_text(*it->second)));
    if (const auto [it, fresh] = by_config.emplace(m.inputs, &m); !fresh)
      throw ParamError(
          "--sweep", values_text(m),
          fmt::format("runs the same configuration as '{}'", values_text(*it->second)));
  }
  return members;
}

std::string SameRun::text() const {
  return fmt::format("{} are the same run ({} {} nothing there)", fmt::join(members, " = "),
                     fmt::join(flags, ", "), flags.size() == 1 ? "does" : "do");
}

std::vector<SameRun> same_runs(const std::vector<SweepMember>& members) {
  std::map<std::string, std::vector<const SweepMember*>> groups;
  std::vector<std::string> order;
  for (const auto& m : members) {
    auto& g = groups[m.run_key];
    if (g.empty())
      order.push_back(m.run_key);
    g.push_back(&m);
  }
  std::vector<SameRun> out;
  for (const auto& key : order) {
    const auto& g = groups[key];
    if (g.size() < 2)
      continue;
    SameRun same;
    std::set<std::string> flags;
    for (const SweepMember* m : g) {
      same.members.push_back(m->name);
      for (const auto& change : config_differences(g.front()->inputs, m->inputs))
        flags.insert(change.substr(0, change.find(':')));
    }
    same.flags.assign(flags.begin(), flags.end());
    out.push_back(same);
  }
  return out;
}

/// Why `m` cannot run (its flags do not validate), or nullopt.
std::optional<std::string> invalid_reason(const SweepMember& m) {
  try {
    std::vector<std::string> args(m.args.begin() + 1, m.args.end());
    Params p = parse_evolve_args(args);
    resolve_defaults(p);
    validate(p);
    return std::nullopt;
  } catch (const std::exception& e) {
    return std::string(e.what());
  }
}

/// A folder that holds members run with other inputs is refused (naming them) before anything
/// is written or launched: results of other inputs are never reused or mixed in.
void check_earlier_inputs(const fs::path& dir, const std::vector<const SweepMember*>& members,
                          const std::string& out) {
  std::vector<std::string> changed;
  std::map<std::string, std::set<std::string>> ran_with; // key -> the values the members had
  for (const SweepMember* m : members) {
    const std::string before = earlier_inputs(dir, *m);
    if (before.empty())
      continue;
    const auto diff = config_differences(before, m->inputs);
    if (!diff.empty())
      changed.push_back(fmt::format("{} ({})", m->name, fmt::join(diff, ", ")));
    for (const auto& d : diff) // "key: old -> new"
      if (const auto colon = d.find(": "), arrow = d.find(" -> ");
          colon != std::string::npos && arrow != std::string::npos)
        ran_with[d.substr(0, colon)].insert(d.substr(colon + 2, arrow - colon - 2));
  }
  if (changed.empty())
    return;
  // The likelier slip is a flag left out of (or changed in) a rerun of the same sweep: name the
  // flags the members ran with, where they agree, before the remedies that discard results.
  std::vector<std::string> flags;
  for (const auto& [key, values] : ran_with) {
    if (values.size() != 1 || *values.begin() == "(unset)")
      continue;
    std::string value = *values.begin();
    if (value.size() >= 2 && value.front() == '"' && value.back() == '"')
      value = value.substr(1, value.size() - 2);
    flags.push_back(fmt::format("--{} {}", key, value));
  }
  const std::string same_sweep =
      flags.empty() ? ""
                    : fmt::format("If this is the same sweep, give the flags they ran with ({}); ",
                                  fmt::join(flags, " "));
  throw ParamError(
      "--out", out,
      fmt::format("holds members run with other inputs: {}; nothing was run or changed. {}to "
                  "run other inputs, use another --out (or remove those members' folders and "
                  "logs/ files to rerun them)",
                  fmt::join(changed.begin(),
                            changed.begin() + std::min<std::ptrdiff_t>(changed.size(), 3), "; "),
                  same_sweep)
          + (changed.size() > 3 ? fmt::format(" (and {} more)", changed.size() - 3) : ""));
}

std::vector<const SweepMember*> all_of(const std::vector<SweepMember>& members) {
  std::vector<const SweepMember*> all;
  for (const auto& m : members)
    all.push_back(&m);
  return all;
}

void record_axis_order(const std::string& out, const std::vector<SweepAxis>& axes) {
  const fs::path file = fs::path(out) / "logs" / "axes";
  create_output_dir("--out", file.parent_path());
  std::error_code ec; // written only where nothing is, not even a link (a loop included)
  if (!fs::exists(fs::symlink_status(file, ec)))
    write_file_atomically(file, axis_order_text(axes));
}

/// Refuses axes in another order than the folder's sweep (or other axes), naming its order.
void check_axis_order(const std::string& out, const std::vector<SweepAxis>& axes) {
  std::ifstream in(fs::path(out) / "logs" / "axes");
  if (!in)
    return; // a new sweep, or one from before the axes were recorded
  std::ostringstream text;
  text << in.rdbuf();
  const std::string now = axis_order_text(axes);
  if (text.str() == now)
    return;
  std::vector<std::string> before, given;
  std::istringstream a(text.str()), b(now);
  for (std::string line; std::getline(a, line);)
    before.push_back(line);
  for (std::string line; std::getline(b, line);)
    given.push_back(line);
  auto sorted = [](std::vector<std::string> v) {
    std::sort(v.begin(), v.end());
    return v;
  };
  throw ParamError(
      "--sweep", fmt::format("{}", fmt::join(given, " ")),
      sorted(before) == sorted(given)
          ? fmt::format("gives the axes of the sweep in {} in another order: give them as it "
                        "did, {} (member folders are named in that order)",
                        printable(out), fmt::join(before, " then "))
          : fmt::format("{} holds a sweep over other flags ({}): use another --out", printable(out),
                        fmt::join(before, " then ")));
}

} // namespace gbssn1d
