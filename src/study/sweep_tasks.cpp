#include "study/sweep_tasks.hpp"

#include "config/params.hpp"
#include "config/paths.hpp"
#include "core/console.hpp"
#include "core/text.hpp"
#include "io/data_file.hpp"
#include "study/sweep_store.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace gbssn1d {

namespace fs = std::filesystem;

namespace {

/// The command lines of the valid members, one per line: each the one-member form of this
/// very sweep, which runs that member (resuming its checkpoint when requeued) and writes its
/// results, log and status into the sweep's folder, from whatever folder the scheduler starts
/// it in. Invalid members are not emitted; --collect marks them.
std::string task_lines(const SweepOptions& options, const std::vector<SweepMember>& members,
                       const std::vector<std::string>& evolve_args, const std::string& exe,
                       std::size_t& emitted) {
  const std::string cwd = fs::current_path().string();
  const std::string abs_out = fs::absolute(options.out).lexically_normal().string();
  std::string lines;
  emitted = 0;
  for (const auto& m : members) {
    if (const auto why = invalid_reason(m)) {
      say("gbssn1d sweep: {} not emitted: {}\n", m.name, *why);
      continue;
    }
    lines += "cd " + shell_quote(cwd) + " && " + shell_quote(exe) + " sweep --out "
             + shell_quote(abs_out) + " --member " + shell_quote(m.name) + " --progress-every 0";
    for (const auto& sw : options.sweeps)
      lines += " --sweep " + shell_quote(sw);
    for (const auto& a : evolve_args)
      lines += ' ' + shell_quote(a);
    lines += '\n';
    ++emitted;
  }
  return lines;
}

} // namespace

/// `sweep ... --emit-tasks FILE`: the task lines written to FILE (nothing is run).
int emit_tasks(const SweepOptions& options, const std::vector<SweepAxis>& axes,
               const std::vector<SweepMember>& members, const std::vector<std::string>& evolve_args,
               const std::string& exe) {
  const fs::path dir(options.out);
  check_earlier_inputs(dir, all_of(members), options.out);
  {
    // the folder every line runs its member into must be able to be one: refused here, not
    // by each task on the cluster (a sweep's folder may hold members already: a rerun)
    Params o;
    o.out = options.out;
    o.force = true;
    validate_output_dir(o);
  }
  std::size_t emitted = 0;
  const std::string lines = task_lines(options, members, evolve_args, exe, emitted);
  const std::string abs_out = fs::absolute(options.out).lexically_normal().string();
  if (abs_out.find_first_of("\n\r") != std::string::npos)
    throw ParamError("--out", printable(options.out),
                     "holds a line break, which would split its task lines");
  // `-`: the lines go to standard output (a pipe into a scheduler), not to a file named '-'
  if (options.emit_tasks == "-") {
    if (std::fwrite(lines.data(), 1, lines.size(), stdout) != lines.size()
        || std::fflush(stdout) != 0)
      throw OutputError(fmt::format("--emit-tasks -: the command lines could not be written to "
                                    "standard output: {}",
                                    std::strerror(errno)));
    record_axis_order(options.out, axes);
    say("gbssn1d sweep: {} member command lines written to standard output (of {} members); "
        "then `gbssn1d sweep ... --collect` with the same flags builds summary.dat\n",
        emitted, members.size());
    return 0;
  }
  check_path("--emit-tasks", options.emit_tasks);
  // the task file must not take the place of the folder its lines run members into
  {
    const fs::path tasks_path = fs::absolute(options.emit_tasks).lexically_normal();
    for (fs::path p = fs::absolute(options.out).lexically_normal(); p.has_relative_path();
         p = p.parent_path())
      if (p == tasks_path || p.string() + "/" == tasks_path.string())
        throw ParamError("--emit-tasks", printable(options.emit_tasks),
                         "names --out's folder (or one it lies in): the task lines would take "
                         "its place");
  }
  // an existing file is not overwritten unless it holds these very lines (a rerun of the
  // same emit); a device or FIFO (/dev/stdout into a pipe) is written to as it is
  if (std::error_code ec; fs::is_regular_file(options.emit_tasks, ec)) {
    std::ifstream old(options.emit_tasks, std::ios::binary);
    std::ostringstream text;
    text << old.rdbuf();
    if (text.str() != lines)
      throw ParamError("--emit-tasks", printable(options.emit_tasks),
                       "exists and holds something else: nothing was written (name a new "
                       "file, or remove this one)");
  }
  std::ofstream tasks(options.emit_tasks);
  if (!tasks)
    throw ParamError("--emit-tasks", options.emit_tasks, "cannot be written");
  tasks << lines;
  tasks.close(); // flushes: a full disk shows here
  if (!tasks)
    throw OutputError(
        fmt::format("--emit-tasks {}: the command lines could not be written", options.emit_tasks));
  record_axis_order(options.out, axes); // (the folder is made once the lines are written)
  say("gbssn1d sweep: {} member command lines written to {} (of {} members); then "
      "`gbssn1d sweep ... --collect` with the same flags builds summary.dat\n",
      emitted, options.emit_tasks, members.size());
  return 0;
}

} // namespace gbssn1d
