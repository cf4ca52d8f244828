// A convergence study's member (study/converge_member.hpp): run, continued from its checkpoint,
// or taken from what it kept when it completed with the same inputs.
#include "study/converge_member.hpp"

#include "config/config_file.hpp"
#include "config/input_files.hpp"
#include "config/params.hpp"
#include "config/same_run.hpp"
#include "core/console.hpp"
#include "core/registry.hpp"
#include "core/stop_signal.hpp"
#include "evolution/observe.hpp"
#include "evolution/simulation.hpp"
#include "io/output.hpp"
#include "study/converge_records.hpp"

#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace gbssn1d {

namespace fs = std::filesystem;

namespace {

/// A member with a checkpoint of its own configuration (`config`, with the record of the
/// content of --rah-hAH-file the member runs with), and the samples saved with it, is
/// continued from there: `sim` restored, `rec` the saved samples; nothing otherwise, with the
/// reason in `afresh` when a checkpoint was there but is not used.
std::optional<Checkpoint> resume_member(Simulation& sim, const Params& p, const std::string& config,
                                        const std::string& samples_key, MemberRecord& rec,
                                        std::string& afresh) {
  const fs::path samples_file = fs::path(p.out) / "converge_samples.bin";
  const fs::path checkpoint_file = fs::path(p.out) / "checkpoint.bin";
  std::optional<Checkpoint> from;
  // a checkpoint that cannot even be examined (a loop of symbolic links) is unusable like any
  // other: the member starts afresh (its first checkpoint replaces the file)
  std::error_code ec;
  const fs::file_status st = fs::status(checkpoint_file, ec);
  if (ec && ec != std::errc::no_such_file_or_directory)
    afresh = fmt::format("its {} cannot be examined: {}", checkpoint_file.string(), ec.message());
  else if (fs::exists(st) && !fs::is_regular_file(st))
    afresh = fmt::format("its {} is not a regular file", checkpoint_file.string());
  else if (!fs::exists(st) && fs::exists(fs::path(p.out) / "timeseries.dat"))
    afresh = "it has no checkpoint (a member that completed keeps none, nor does one stopped "
             "before its first)";
  if (fs::is_regular_file(st)) {
    try {
      Checkpoint c = read_checkpoint(checkpoint_file);
      if (!config_differences(c.config, config, {"tmax", "out", "force"}).empty() || c.t > p.tmax)
        afresh = "its checkpoint belongs to other inputs";
      else if (const auto files = input_file_differences(c.config, config); !files.empty())
        afresh = fmt::format("its checkpoint was made with another --rah-hAH-file ({})",
                             fmt::join(files, ", "));
      else if (auto saved = read_samples(samples_file, samples_key, c.step)) {
        Output::check_resumable(p.out, c.marks);
        sim.restore(c);
        rec = std::move(*saved);
        from = std::move(c);
      } else {
        afresh = "its converge_samples.bin does not belong to its checkpoint (missing, another "
                 "step or fields, or its checksum does not match)";
      }
    } catch (const CheckpointError& e) { // not resumable: the member starts afresh
      afresh = e.what();
    } catch (const OutputError& e) {
      afresh = e.what();
    }
  }
  return from;
}

/// One output time of a member: its timeseries row, the fields and H at the study's radii.
void record_samples(Simulation& s, const std::vector<Var>& fields, const std::vector<double>& radii,
                    MemberRecord& rec) {
  const std::vector<DerivedProfiles> levels_d = s.level_profiles();
  rec.rows.push_back(s.series_row(s.composite_profiles(levels_d)));
  std::vector<double> samples;
  for (Var v : fields)
    for (double r : radii)
      samples.push_back(s.at_radius(v, r));
  rec.field_samples.push_back(std::move(samples));
  std::vector<double> H_samples;
  for (double r : radii)
    H_samples.push_back(s.H_at_radius(levels_d, r));
  rec.H_samples.push_back(std::move(H_samples));
}

/// A member that completed with these inputs (`member_config`), whose output files are as it
/// left them, is not run again: its records are taken from what it kept into `rec` (true).
/// Otherwise a completed-file it has is removed, and why it is not used said.
bool take_completed_records(const Params& p, const std::string& samples_key,
                            const std::string& member_config, MemberRecord& rec,
                            std::mutex& log_mutex) {
  const fs::path completed_file = fs::path(p.out) / completed_file_name;
  std::string not_reused;
  std::error_code examined;
  const fs::file_status record = fs::symlink_status(completed_file, examined);
  if (examined || !fs::exists(record))
    return false;
  const fs::file_status target = fs::status(completed_file, examined);
  if (examined)
    not_reused = fmt::format("it cannot be examined: {}", examined.message());
  else if (!fs::is_regular_file(target))
    not_reused = "it is not a regular file";
  else if (auto kept = read_samples(completed_file, completed_key(samples_key, member_config),
                                    output_files_hash(p.out), &not_reused)) {
    rec = std::move(*kept);
    const std::lock_guard lock(log_mutex);
    say("gbssn1d converge: member N = {} completed earlier: its records are taken from its "
        "{} (its inputs and output files unchanged since)\n",
        p.N, completed_file_name);
    return true;
  }
  std::error_code ignored;
  fs::remove(completed_file, ignored); // the member runs (or continues) now
  const std::lock_guard lock(log_mutex);
  say("gbssn1d converge: member N = {} is run: its {} is not used ({})\n", p.N, completed_file_name,
      not_reused == samples_other_step
          ? "its output files changed since it completed: another command wrote its folder"
          : not_reused);
  return false;
}

/// Member p evolved (or continued from its checkpoint) into its folder, recording into `rec`,
/// with the study's fields, radii and samples key; the records kept as completed at its end.
/// Throws what stopped it.
void evolve_member(const ConvergeStudy& study, const ResolvedParams& p,
                   const std::optional<std::string>& hAH, const std::string& config,
                   const std::string& member_config, MemberRecord& rec, std::mutex& log_mutex) {
  const auto start = std::chrono::steady_clock::now();
  {
    const std::lock_guard lock(log_mutex);
    say("gbssn1d converge: member N = {} started\n", p.N);
  }
  const fs::path copy = fs::path(p.out) / std::string(prescribed_horizon_copy);
  Params from_copy = p.flags();
  if (hAH) {
    write_file_atomically(copy, *hAH);
    from_copy.rah_hAH_file = copy.string();
  } else { // an earlier run's copy would be a curve this member does not follow
    std::error_code ignored;
    fs::remove(copy, ignored);
  }
  Simulation sim(evolution_config(resolve(from_copy)));
  // as evolve writes it: `gbssn1d resume` continues the member alone from its checkpoint
  write_file_atomically(fs::path(p.out) / "config.toml",
                        header_text("") + config + rule_values_line(p));
  sim.on_series = [&](Simulation& s) { record_samples(s, study.fields, study.radii, rec); };
  sim.checkpoint_config = member_config;
  sim.label = fmt::format(" converge N={}", p.N);
  const fs::path samples_file = fs::path(p.out) / "converge_samples.bin";
  sim.on_checkpoint = [&](const Checkpoint& c) {
    write_samples(samples_file, study.samples_key, c.step, rec);
  };
  // A member with a checkpoint of this configuration, and its samples, continues from it.
  std::string afresh;
  const std::optional<Checkpoint> from =
      resume_member(sim, p, sim.checkpoint_config, study.samples_key, rec, afresh);
  if (!afresh.empty()) {
    const std::lock_guard lock(log_mutex);
    say("gbssn1d converge: member N = {} starts afresh: {}\n", p.N, afresh);
  }
  std::optional<Output> out_storage;
  if (from) {
    const std::lock_guard lock(log_mutex);
    say("gbssn1d converge: member N = {} resumes at t = {}\n", p.N, from->t);
    out_storage.emplace(p.out, config + sim.run_facts(), sim.state().fields(), sim.config().spheres,
                        from->marks);
  } else {
    out_storage.emplace(p.out, config + sim.run_facts(), sim.state().fields(),
                        sim.config().spheres);
  }
  Output& out = *out_storage;
  try {
    sim.run(&out);
    out.write_end(fmt::format("completed at t = {}", sim.time()));
  } catch (const OutputError&) {
    throw;
  } catch (const std::exception& e) { // stopped or interrupted: say so in the file too
    out.write_end(fmt::format("stopped: {}", e.what()));
    throw;
  }
  out_storage.reset(); // its files closed: what a rerun compares
  write_samples(fs::path(p.out) / completed_file_name,
                completed_key(study.samples_key, member_config), output_files_hash(p.out), rec);
  const std::lock_guard lock(log_mutex);
  say("gbssn1d converge: member N = {} completed at t = {} ({:.1f} s)\n", p.N, sim.time(),
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
}

} // namespace

void run_converge_member(ConvergeStudy& study, std::size_t k, const std::optional<std::string>& hAH,
                         std::mutex& log_mutex) {
  const ResolvedParams& p = study.members[k]; // its folder locked by the study (run_converge)
  MemberRecord& rec = study.records[k];
  if (stop_signal() != 0) { // interrupted: start no new member (a rerun continues the study)
    rec.error = "not started: the study was interrupted";
    return;
  }
  try {
    const std::string config = config_text(p); // the member's own configuration
    const std::string member_config = config + copy_hash_line(hAH);
    if (take_completed_records(p, study.samples_key, member_config, rec, log_mutex))
      return;
    evolve_member(study, p, hAH, config, member_config, rec, log_mutex);
  } catch (const OutputError& e) {
    rec.error = e.what();
    rec.write_failed = true;
    const std::lock_guard lock(log_mutex);
    say("gbssn1d converge: member N = {} could not write its output: {}\n", p.N, e.what());
    return;
  } catch (const Interrupted& e) { // a stop signal: kept with a checkpoint, not a failure
    rec.error = e.what();
    const std::lock_guard lock(log_mutex);
    say("gbssn1d converge: member N = {} stopped: {} (a checkpoint kept)\n", p.N, e.what());
  } catch (const std::exception& e) {
    rec.error = e.what();
    const std::lock_guard lock(log_mutex);
    say("gbssn1d converge: member N = {} failed: {}\n", p.N, e.what());
  }
}

} // namespace gbssn1d
