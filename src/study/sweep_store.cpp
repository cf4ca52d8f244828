#include "study/sweep_store.hpp"

#include "config/config_file.hpp"
#include "config/input_files.hpp"
#include "config/params.hpp"
#include "config/paths.hpp"
#include "core/decimal.hpp"
#include "core/text.hpp"
#include "io/data_file.hpp"

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

/// What an earlier run of the sweep in `dir` ran member `m` with: the inputs file written when
/// it started (`inputs_file`), or (for a member folder without one) the member's config.toml;
/// empty if nothing of it is there.
struct EarlierInputs {
  std::string text;
  bool inputs_file = false;
};
EarlierInputs earlier_inputs(const fs::path& dir, const SweepMember& m) {
  std::error_code ec; // a path that cannot be examined holds nothing (its creation is refused)
  for (const fs::path& file : {dir / "logs" / (m.name + ".inputs"), dir / m.name / "config.toml"})
    if (fs::is_regular_file(file, ec)) {
      std::ifstream in(file);
      std::stringstream s;
      s << in.rdbuf();
      return {s.str(), file.extension() == ".inputs"};
    }
  return {};
}

/// Where member `m`'s folder differs from its inputs: the keys of its config.toml, and the
/// content of its copy of --rah-hAH-file, each "... in its folder's ..." (nothing for a folder
/// without them: a member not run yet, or invalid).
std::vector<std::string> folder_differences(const fs::path& dir, const SweepMember& m) {
  std::vector<std::string> diff;
  std::error_code ec;
  const auto text = [](const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  };
  const fs::path config = dir / m.name / "config.toml";
  if (fs::is_regular_file(config, ec))
    for (const auto& d : config_differences(text(config), m.inputs))
      diff.push_back(d + " in its folder's config.toml");
  const fs::path copy = dir / m.name / std::string(prescribed_horizon_copy);
  if (recorded_copy_hash(m.inputs) && fs::is_regular_file(copy, ec))
    for (const auto& d : input_file_differences(copy_hash_line(text(copy)), m.inputs))
      diff.push_back(d + " in its folder's " + std::string(prescribed_horizon_copy));
  return diff;
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

/// A folder that holds members run with other inputs is refused (naming them) before anything
/// is written or launched: results of other inputs are never reused or mixed in.
void check_earlier_inputs(const fs::path& dir, const std::vector<const SweepMember*>& members,
                          const std::string& out) {
  std::vector<std::string> changed;
  std::map<std::string, std::set<std::string>> ran_with; // key -> the values the members had
  for (const SweepMember* m : members) {
    const EarlierInputs before = earlier_inputs(dir, *m);
    if (before.text.empty())
      continue;
    const auto diff = config_differences(before.text, m->inputs);
    // and the content of the files flags name, as the inputs file records it (a member's
    // config.toml, read when that file is gone, records none: its run's copy is resume's check)
    std::vector<std::string> all = diff;
    if (before.inputs_file)
      for (const auto& d : input_file_differences(before.text, m->inputs))
        all.push_back(d);
    // the member's folder as its own config.toml (and copy of --rah-hAH-file) says it ran,
    // where the inputs file agrees: a folder replaced by another run is not the member,
    // whatever its status file says
    if (before.inputs_file && all.empty())
      for (const auto& d : folder_differences(dir, *m))
        all.push_back(d);
    if (!all.empty())
      changed.push_back(fmt::format("{} ({})", m->name, fmt::join(all, ", ")));
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

void refuse_links(const fs::path& dir, const std::vector<const SweepMember*>& members,
                  const std::string& out) {
  std::vector<fs::path> paths{dir / "logs", dir / "summary.dat", dir / "logs" / "axes"};
  for (const SweepMember* m : members) {
    paths.push_back(dir / m->name);
    for (const char* suffix : {".inputs", ".status", ".log", ".lock"})
      paths.push_back(dir / "logs" / (m->name + suffix));
  }
  for (const fs::path& path : paths) {
    std::error_code ec;
    if (fs::is_symlink(fs::symlink_status(path, ec)))
      throw ParamError(
          "--out", printable(out),
          fmt::format("holds a symbolic link, {}: a sweep writes no file through a link (a "
                      "member run there would overwrite what it points at, or report it as the "
                      "member); nothing was run or changed: remove the link, or give another --out",
                      printable(path.lexically_relative(dir).string())));
  }
}

void record_axis_order(const std::string& out, const std::vector<SweepAxis>& axes) {
  const fs::path file = fs::path(out) / "logs" / "axes";
  create_output_dir("--out", file.parent_path());
  std::error_code ec; // written only where nothing is, not even a link (a loop included)
  if (!fs::exists(fs::symlink_status(file, ec)))
    write_file_atomically(file, axis_order_text(axes));
}

/// Refuses a folder that holds another command's output (an evolve run, a converge study: their
/// config.toml at its top), as evolve and converge refuse a folder that is not theirs.
void refuse_other_commands_folder(const std::string& out) {
  std::error_code ec;
  if (fs::exists(fs::symlink_status(fs::path(out) / "config.toml", ec)))
    throw ParamError("--out", printable(out),
                     "holds another command's output (its config.toml: an evolve run or a "
                     "converge study), beside which a sweep would write its members and "
                     "summary; nothing was run or changed: give another --out");
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
