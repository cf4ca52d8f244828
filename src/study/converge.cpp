#include "study/converge.hpp"

#include "config/paths.hpp"
#include "study/converge_member.hpp"
#include "study/converge_report.hpp"

#include "core/console.hpp"
#include "core/decimal.hpp"
#include "core/stop_signal.hpp"

#include "config/config_file.hpp"
#include "config/folder_lock.hpp"
#include "config/input_files.hpp"
#include "config/param_rules.hpp"
#include "config/params.hpp"
#include "core/registry.hpp"
#include "evolution/observe.hpp"
#include "evolution/simulation.hpp"
#include "io/output.hpp"
#include "mesh/level_steps.hpp"
#include "study/parallel.hpp"
#include "study/verdict.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <mutex>
#include <optional>
#include <sstream>
#include <string_view>

namespace gbssn1d {

namespace fs = std::filesystem;

namespace {

/// The line that marks a config.toml as a converge study's (it goes on with the N list and the
/// fields); no other command writes it.
constexpr std::string_view study_mark = "# converge: N = ";

/// Member folders (N<n>/ with a config.toml) of an earlier study into the same folder that this
/// one does not list: said, since convergence.dat will not hold them; left as they are.
void warn_of_unlisted_members(const std::string& out, const std::vector<int>& N) {
  std::vector<std::string> unlisted;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(out, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.size() < 2 || name[0] != 'N'
        || name.find_first_not_of("0123456789", 1) != std::string::npos || !entry.is_directory(ec)
        || !fs::is_regular_file(entry.path() / "config.toml", ec))
      continue;
    const auto n = parse_decimal<int>(name.substr(1));
    if (!n || std::find(N.begin(), N.end(), *n) == N.end())
      unlisted.push_back(name);
  }
  if (unlisted.empty())
    return;
  std::sort(unlisted.begin(), unlisted.end());
  say("gbssn1d converge: warning: {} holds {} member folder{} of an earlier study that this one "
      "(N = {}) does not list ({}): left as {}, and not in convergence.dat or scaled_H.dat\n",
      out, unlisted.size(), unlisted.size() == 1 ? "" : "s", fmt::join(N, ","),
      fmt::join(unlisted, ", "), unlisted.size() == 1 ? "it is" : "they are");
}

/// Where a member's round-off floor is estimated: its composite cells, the coordinate window,
/// the points of the areal window on its initial data (outer sheet) and the sampled radii.
MemberCells member_cells(const ResolvedParams& p, const std::vector<double>& radii) {
  const Simulation sim(evolution_config(p));
  const Grid& g = sim.composite().grid();
  const mesh::MeshLayout& layout = sim.layout();
  MemberCells c;
  c.dr_min = layout.grid(layout.levels() - 1).min_spacing(); // as its headers write dr-min
  for (std::size_t i = g.first_interior(); i < g.end_interior(); ++i) {
    c.r.push_back(g.r()[i]);
    c.dr.push_back(g.dr()[i]);
  }
  const NormWindows& w = sim.config().norms;
  c.ext = {w.rmin, w.rmax};
  const std::vector<double> R = sim.composite_profiles().R_areal;
  c.areal = {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (std::size_t k = outer_sheet_begin(R); k < R.size(); ++k)
    if (R[k] >= w.Rmin && R[k] <= w.Rmax) {
      c.areal.lo = std::min(c.areal.lo, c.r[k]);
      c.areal.hi = std::max(c.areal.hi, c.r[k]);
    }
  c.samples = {radii.front(), radii.back()};
  return c;
}

/// The study's members and what each samples: the fields at the coarsest member's interior
/// points (of the composite of its boxes) inside the exterior region; and each member's cells
/// (member_cells).
ConvergeStudy plan_study(const Params& base, const ConvergeOptions& options) {
  ConvergeStudy s{base, options, converge_members(base, options), {}, {}, {}, {}, 0, {}};
  const mesh::MeshLayout coarse_layout = make_layout(evolution_config(s.members.front()));
  const Grid coarse = mesh::Composite(coarse_layout).grid();
  for (std::size_t i = coarse.first_interior(); i < coarse.end_interior(); ++i)
    if (coarse.r()[i] >= s.members.front().norm_rmin
        && coarse.r()[i] <= s.members.front().norm_rmax())
      s.radii.push_back(coarse.r()[i]);
  if (s.radii.empty())
    throw ParamError("--norm-rmin", fmt::format("{}", s.members.front().norm_rmin),
                     "the exterior region holds no grid point of the coarsest member");
  { // the areal window, on the coarsest member's initial data: H_L2_R and M_L2_R are judged
    const Simulation coarsest(evolution_config(s.members.front()));
    for (const auto& w :
         empty_norm_windows(coarsest.composite().grid(), coarsest.composite_profiles().R_areal,
                            coarsest.config().norms))
      if (w.flags.starts_with("--norm-Rmin"))
        throw ParamError(
            "--norm-Rmin", fmt::format("{}", s.members.front().norm_Rmin),
            fmt::format("{} for the coarsest member, and converge judges them", w.what));
  }
  for (const auto& name : options.fields)
    s.fields.push_back(*var_from_name(name));
  // the layout of the saved series rows is part of what the samples file must match
  s.samples_key =
      fmt::format("row = {} doubles\nfields = {}\nradii =", sizeof(SeriesRow) / sizeof(double),
                  fmt::join(options.fields, ","));
  for (double r : s.radii)
    s.samples_key += fmt::format(" {:.17g}", r);
  s.records.resize(s.members.size());
  for (const ResolvedParams& p : s.members)
    s.cells.push_back(member_cells(p, s.radii));
  return s;
}

/// Members on subcycled boxes whose hierarchies step by different dt, with a horizon shift that
/// follows the searches: h_AH(t) is held or extrapolated over a step of the hierarchy, so each
/// such step is a slightly different gauge, a floor under the fields' differences
/// (docs/horizon-shift-study.md, Sec. 6.7); held every n steps, each member holds it for its own
/// time (Sec. 13). With --ah-interval T every member holds it for T, unless T is no whole number
/// of some member's step. Empty when the steps agree or do not matter.
std::string hierarchy_step_warning(const std::vector<ResolvedParams>& members) {
  const ResolvedParams& p = members.front();
  if (p.grid != RadialGrid::boxes || p.levels() < 2 || p.no_subcycling || !shift_on(p)
      || uses_hAH_file(p))
    return {};
  std::vector<std::string> steps, uneven;
  bool differ = false;
  double first = 0.0, dt_max = 0.0; // the cap, the same in every member (it depends not on N)
  for (const ResolvedParams& m : members) {
    const EvolutionConfig c = evolution_config(m);
    const double dt = mesh::hierarchy_dt(make_layout(c), c.stepping);
    if (steps.empty()) {
      first = dt;
      dt_max = c.stepping.dt_max;
    }
    differ = differ || std::abs(dt - first) > 1e-12 * first;
    steps.push_back(fmt::format("N = {}: {:.4g} M", m.N, dt));
    if (m.ah_interval) {
      const double k = *m.ah_interval / dt;
      if (std::abs(k - std::round(k)) > 1e-9 * std::max(1.0, k))
        uneven.push_back(fmt::format("N = {}: {:.4g} M", m.N, dt));
    }
  }
  if (p.ah_interval) {
    if (uneven.empty())
      return {};
    return fmt::format(
        "--ah-interval {} is no whole number of the hierarchy's step of {}: those members hold "
        "h_AH for whole steps, so their holds alternate around {} and differ from the others'; "
        "a T that every member's step divides holds it equally long in every member",
        num(*p.ah_interval), fmt::join(uneven, ", "), num(*p.ah_interval));
  }
  if (!differ)
    return {};
  if (p.ah_every != SearchEvery::substage && p.ah_every != SearchEvery::extrapolated)
    return fmt::format(
        "the members' hierarchies step by different dt ({}): with --ah-every {} each member "
        "holds h_AH for its own number of steps, a different time in each, so the members evolve "
        "different gauges (docs/horizon-shift-study.md, Sec. 13); --ah-interval T holds it for "
        "the same time in every member",
        fmt::join(steps, ", "), p.ah_every.name());
  return fmt::format(
      "the members' hierarchies step by different dt ({}): on subcycled boxes the coarse boxes "
      "extrapolate h_AH over a step of the hierarchy, so each member's gauge differs from the "
      "others' by that extrapolation's error (about 2e-6 in r_AH for the stretch to 0.89 M: "
      "docs/horizon-shift-study.md, Sec. 6.7), and its fields converge to the others' only "
      "while their errors are larger; members whose hierarchies step alike (N in power-of-two "
      "ratios, each small enough that the cap dt_max = {:.4g} M on the coarse boxes' step "
      "binds in all of them; where it binds in none the steps halve with N), --no-subcycling "
      "or --rah-hAH-file avoid it",
      fmt::join(steps, ", "), dt_max);
}

} // namespace

std::vector<ResolvedParams> converge_members(const Params& base, const ConvergeOptions& options) {
  if (options.N.size() < 3)
    throw ParamError("--N", fmt::format("{}", fmt::join(options.N, ",")),
                     "needs at least three resolutions");
  for (std::size_t k = 1; k < options.N.size(); ++k)
    if (!(options.N[k] > options.N[k - 1]))
      throw ParamError("--N", fmt::format("{}", fmt::join(options.N, ",")),
                       "resolutions must increase");
  for (const auto& name : options.fields) {
    const auto v = var_from_name(name);
    if (!v)
      throw ParamError("--fields", name, "is not an evolved variable");
    if (!Fields(base.formulation.value(), base.matter.value()).holds(*v))
      throw ParamError("--fields", name,
                       fmt::format("is not evolved with --formulation {} --matter {} ({})",
                                   base.formulation.name(), base.matter.name(),
                                   Fields(base.formulation.value(), Matter::scalar).holds(*v)
                                       ? "--matter scalar evolves it"
                                       : "another --formulation evolves it"));
  }
  std::vector<ResolvedParams> members;
  for (int n : options.N) {
    Params p = base;
    p.N = n; // the map does not depend on N, so this is a refinement on either grid
    p.out = (fs::path(options.out) / fmt::format("N{}", n)).string();
    p.force = true;
    members.push_back(resolve(p));
    validate(members.back());
  }
  return members;
}

std::string study_resolutions(const std::string& out) {
  std::ifstream in(fs::path(out) / "config.toml", std::ios::binary);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(study_mark, 0) == 0) {
      line = line.substr(study_mark.size());
      return line.substr(0, line.find(", fields"));
    }
  return {};
}

bool holds_this_study(const std::string& out, const std::string& base_config,
                      const std::string& files_text) {
  const fs::path file = fs::path(out) / "config.toml";
  std::error_code ec; // a path that cannot be examined is refused by validate_output_dir
  if (!fs::is_regular_file(file, ec))
    return false;
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  const std::string old = text.str();
  const bool study = old.rfind(study_mark, 0) == 0
                     || old.find("\n" + std::string(study_mark)) != std::string::npos;
  if (!study)
    throw ParamError("--out", out,
                     fmt::format("is not a converge study's folder (its config.toml has no "
                                 "'{}...' line: an evolve run, a sweep's member or a study's "
                                 "member); nothing was changed: use another --out, or --force "
                                 "to run the study into it",
                                 study_mark));
  auto diff = config_differences(old, base_config, {"out", "force", "N"});
  for (const auto& d : input_file_differences(old, files_text)) // an edited --rah-hAH-file
    diff.push_back(d);
  if (!diff.empty())
    throw ParamError("--out", out,
                     fmt::format("holds a converge study of other inputs ({}); use another "
                                 "--out, or --force to rerun into it",
                                 fmt::join(diff, ", ")));
  return true;
}

int run_converge(const Params& base, const ConvergeOptions& options,
                 const std::string& base_config) {
  ConvergeStudy s = plan_study(base, options);
  if (const std::string w = hierarchy_step_warning(s.members); !w.empty())
    say("gbssn1d converge: warning: {}\n", w);
  // --rah-hAH-file read once for every member, and its content's hash recorded with the study
  const std::optional<std::string> hAH = prescribed_horizon_content(base);
  const std::string files_text = copy_hash_line(hAH);
  const FolderLock lock("--out", options.out); // one writer per study folder
  // what the folder holds again, under the lock: another process may have written it since it
  // was checked (an evolve run of the same flags is no study to continue)
  if (!options.force && !holds_this_study(options.out, base_config, files_text)
      && !folder_is_empty(options.out))
    throw ParamError("--out", options.out,
                     "exists and is not empty: another process wrote it meanwhile (use --force "
                     "to overwrite)");
  // the study's inputs first: a rerun after any stop (SIGKILL included) recognises its folder
  // and continues the members from their checkpoints
  const std::string study_config =
      header_text("")
      + fmt::format("{}{}, fields {}\n", study_mark, fmt::join(options.N, ","),
                    fmt::join(options.fields, ","))
      + base_config + files_text;
  write_file_atomically(fs::path(options.out) / "config.toml", study_config);
  // one writer per member folder too, held until the study ends: a member that has finished
  // stays the study's (an evolve --force or resume of it while the study runs is refused, and
  // convergence.dat never describes a run no longer in the folder)
  std::vector<FolderLock> member_locks;
  member_locks.reserve(s.members.size());
  for (const Params& m : s.members)
    member_locks.emplace_back("--out", m.out);
  warn_of_unlisted_members(options.out, options.N);
  std::mutex log_mutex;
  install_stop_handlers(); // members stop between steps; the partial files stay
  run_tasks(s.members.size(), options.jobs,
            [&](std::size_t k) { run_converge_member(s, k, hAH, log_mutex); });
  // times common to all members
  s.n_times = s.records.front().rows.size();
  for (const auto& rec : s.records)
    s.n_times = std::min(s.n_times, rec.rows.size());
  const StudyEnding e = study_ending(s);
  const StudyVerdict v = judge_study(s, e);
  write_convergence_dat(s, base_config, e, v);
  write_scaled_H(s, base_config, e);
  const int signal = e.signal;
  const std::string& failed = e.failed;
  const std::string& ending = e.ending;
  const std::string& judged = v.judged;
  const double t_common = e.t_common;
  if (signal != 0) {
    say("gbssn1d converge: N = {} {}; the partial norms and orders are in {}/convergence.dat\n",
        fmt::join(options.N, ", "), ending, options.out);
    return 128 + signal;
  }
  if (e.write_failed) {
    say("gbssn1d converge: N = {} {}; a member's output could not be written, so the study is "
        "incomplete (not judged as a failure to converge); see {}/convergence.dat\n",
        fmt::join(options.N, ", "), ending, options.out);
    return 1;
  }
  if (!failed.empty()) {
    say("gbssn1d converge: N = {} {}; does not converge; see {}/convergence.dat\n",
        fmt::join(options.N, ", "), ending, options.out);
    return 3;
  }
  if (!v.converges) {
    say("gbssn1d converge: N = {} completed at t = {}, but {}; norms, orders and the verdict in "
        "{}/convergence.dat\n",
        fmt::join(options.N, ", "), t_common, judged, options.out);
    return v.kind == ConvergenceClass::pre_asymptotic ? 5
           : v.kind == ConvergenceClass::unjudged     ? 6
                                                      : 4;
  }
  say("gbssn1d converge: N = {} completed at t = {}; {}; norms, orders and the verdict in "
      "{}/convergence.dat\n",
      fmt::join(options.N, ", "), t_common, judged, options.out);
  return 0;
}

} // namespace gbssn1d
