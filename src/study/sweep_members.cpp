// A sweep's members from its axes: each axis parsed, the product's members named, each
// member's inputs and run key, which members are the same run, and which cannot run.
#include "config/config_file.hpp"
#include "config/input_files.hpp"
#include "config/params.hpp"
#include "config/same_run.hpp"
#include "core/text.hpp"
#include "study/sweep.hpp"
#include "study/sweep_store.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

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
/// config.toml would hold it, with the hash of the content of each file a flag names
/// (--rah-hAH-file: an edited file is another input, as an edited flag is), and its tmax; for a
/// member that does not parse, its arguments (and no end time).
void set_inputs(SweepMember& m) {
  try {
    Params given = parse_evolve_args({m.args.begin() + 1, m.args.end() - 2}); // no --out, --force
    given.out.clear();
    const ResolvedParams p = resolve(given);
    m.inputs = config_text(p) + input_files_text(p);
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

} // namespace

SweepAxis parse_sweep_axis(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
    throw ParamError("--sweep", text, "must look like flag=value1,value2,...");
  // an empty item (a trailing comma, "32,,40") is refused, as in converge's lists: split()
  // would drop a trailing one without a word
  const auto empty_item = [](const std::string& list) {
    return list.empty() || list.front() == ',' || list.back() == ','
           || list.find(",,") != std::string::npos;
  };
  if (empty_item(text.substr(0, eq)) || empty_item(text.substr(eq + 1)))
    throw ParamError("--sweep", printable(text),
                     "must be a comma-separated list without empty items (flag=value1,value2,...)");
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
    validate(resolve(parse_evolve_args(args)));
    return std::nullopt;
  } catch (const std::exception& e) {
    return std::string(e.what());
  }
}

} // namespace gbssn1d
