// `gbssn1d evolve`: its flags (the flag table's, --config, --print-config) and one run.
#include "cli/commands.hpp"
#include "cli/run_report.hpp"

#include "config/config_file.hpp"
#include "config/folder_lock.hpp"
#include "config/input_files.hpp"
#include "config/param_rules.hpp"
#include "config/params.hpp"
#include "config/paths.hpp"
#include "config/same_run.hpp"
#include "core/console.hpp"
#include "core/stop_signal.hpp"
#include "core/text.hpp"
#include "evolution/simulation.hpp"
#include "initial_data/initial_data.hpp"
#include "io/output.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace gbssn1d {

namespace {

/// With --force into a folder that is not empty: the entries an evolve run does not write (its
/// files, their temporary names, the lock), named for a warning; empty otherwise.
std::string leftovers_of_force(const Params& p) {
  namespace fs = std::filesystem;
  if (!p.force)
    return {};
  static const std::set<std::string> own = {"timeseries.dat", "profiles.dat",   "horizon.dat",
                                            "config.toml",    "checkpoint.bin", "rah-hAH-file.dat",
                                            folder_lock_name};
  std::vector<std::string> left;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(p.out, ec)) {
    const std::string name = entry.path().filename().string();
    if (!own.count(name) && !name.ends_with(".tmp") && !name.ends_with(".resume"))
      left.push_back(printable(name) + (entry.is_directory(ec) ? "/" : ""));
  }
  std::sort(left.begin(), left.end());
  if (left.size() > 6) {
    const std::size_t more = left.size() - 5;
    left.resize(5);
    left.push_back(fmt::format("and {} more", more));
  }
  return fmt::format("{}", fmt::join(left, ", "));
}

/// Warns of a horizon-adjusting shift faster than the grid's Courant limit on the initial data
/// (|beta_H| dt / dr above 1). Not a refusal: the feedback shrinks beta_H as the horizon
/// moves, and such runs can go through (1+log trumpet, N = 200, rah0 1.2: --rahA 200, a
/// Courant number of 7.6 at t = 0, reaches 1000 M; --rahA 500 leaves the physical range at
/// t = 0.06); the warning names the flag for when the run stops.
void warn_shift_courant(const Simulation& sim, const Params& p) {
  const auto c = sim.horizon_shift_courant();
  if (c && !(c->number <= 1.0))
    say("gbssn1d: warning: --rahA {}: the horizon-adjusting shift starts at beta_H = {:.3g} at "
        "r = {:.4g} (h_AH = {:.4g}, --rah0 {}), a Courant number |beta_H| dt / dr of {:.3g} "
        "above 1; if the run stops early, lower --rahA\n",
        num(p.rahA), c->beta_H, c->r, c->h_AH, num(p.rah0), c->number);
}

/// One run of the parameters as given (or its configuration printed).
int evolve(const Params& given, bool print_config) {
  const ResolvedParams p = resolve(given);
  validate(p);
  if (print_config) {
    const std::string text = config_text(p) + rule_values_line(p);
    if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0)
      throw OutputError(fmt::format("cannot write the configuration to standard output: {}",
                                    std::strerror(errno)));
    return 0;
  }
  validate_output_dir(p);
  for (const auto& w : warnings(p))
    say("gbssn1d: warning: {}\n", w);
  if (const std::string left = leftovers_of_force(p); !left.empty())
    say("gbssn1d: warning: --force: {} also holds {}, which this run does not write: left as "
        "they are, beside its own files (another command's output, e.g. a study's?)\n",
        printable(p.out), left);

  Simulation sim(evolution_config(p)); // initial data are computed before anything is written
  sim.show_progress = true;
  if (p.matter == Matter::scalar)
    say("gbssn1d: the data's ADM mass: {:.12g}\n",
        adm_mass(sim.config().initial_data, sim.state().fields()));
  warn_shift_courant(sim, p);
  for (const auto& w : empty_norm_windows(sim.composite().grid(), sim.composite_profiles().R_areal,
                                          sim.config().norms))
    say("gbssn1d: warning: {}: {}\n", w.flags, w.what);
  for (const auto& w : absent_spheres(sim.composite_profiles().R_areal, sim.config().spheres,
                                      sim.config().initial_data.M))
    say("gbssn1d: warning: {}: {}\n", w.flags, w.what);
  const std::filesystem::path dir(p.out);
  // the content of --rah-hAH-file as it was read (before the folder is made)
  const std::optional<std::string> hAH_content = prescribed_horizon_content(p);
  if (const int signal = stop_signal(); signal != 0) {
    say("gbssn1d: interrupted by {} before the run started; nothing was written\n",
        signal_name(signal));
    return 128 + signal;
  }
  // one writer per folder, from here to the process's end; then the emptiness check again, under
  // the lock: another process may have written the folder since validate_output_dir
  const FolderLock lock("--out", dir);
  if (!p.force && !folder_is_empty(dir))
    throw ParamError("--out", p.out,
                     "exists and is not empty: another process wrote it meanwhile (use --force "
                     "to overwrite)");
  if (p.force) {
    // the earlier run's files this run may not write again go (unlinked: a hard-linked backup
    // keeps them): its checkpoint would otherwise offer `resume` a run this folder no longer
    // holds, its copy of --rah-hAH-file a curve this run does not follow
    std::error_code ignored;
    std::filesystem::remove(dir / "checkpoint.bin", ignored);
    if (!hAH_content)
      std::filesystem::remove(dir / std::string(prescribed_horizon_copy), ignored);
  }
  const std::string config = config_text(p);
  write_file_atomically(dir / "config.toml", header_text("") + config + rule_values_line(p));
  if (hAH_content)
    write_file_atomically(dir / std::string(prescribed_horizon_copy), *hAH_content);
  Output out(dir, config + sim.run_facts(), sim.state().fields(), sim.config().spheres);
  sim.checkpoint_config = config + copy_hash_line(hAH_content);
  return run_and_report(sim, out, p);
}

} // namespace

int run_evolve_command(const EvolveArgs& a) {
  return evolve(a.params, a.print_config);
}

} // namespace gbssn1d
