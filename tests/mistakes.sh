#!/usr/bin/env bash
# Deliberate mistakes that the test suite must catch. Each is applied alone to a clean copy of
# HEAD, the suite is rebuilt, and tests are run to see that some test fails.
#
# Usage: tests/mistakes.sh [--full] [--only PATTERN] [--whole-library]
#   (default, as CI runs it) for each mistake, rebuild only the targets that its named tests
#     need (the last column of the table below: the ctest names, as `ctest -N` prints them, of
#     the fastest tests known to catch it) and run only those tests; at least one of them must
#     fail. Stops at the first mistake that is not caught, naming it, with exit status 1.
#     Mostly recompiling: 923 s of processor time, 948 s on 2 idle cores beside the sanitizer
#     stage (CI, 2026-11-27, 67 mistakes, 1843e04), of which the registry's two (about 120 s
#     each: 31 of 51 library files recompile) take a quarter; a mistake in a .cpp file takes
#     3-20 s.
#   --only PATTERN  (by hand) only the mistakes whose name matches the grep -E pattern
#   --whole-library  also the three mistakes in headers that every library file includes
#     (the registry's table, the parameters' defaults; about 10 minutes) and the two slowest
#     to compile of the rest, which the default (CI) skips, naming them (whole_library below)
#   --full  (by hand, 35-60 minutes on 2 cores: the whole suite per mistake) rebuild everything and run the WHOLE suite
#     for every mistake, list every test that catches it, and report where the named tests
#     disagree: a named test that does not catch its mistake (or does not exist) is an error,
#     a catching test that is not named is only listed. Use it to choose the named tests anew
#     after changing tests.
# The copy is a git worktree of HEAD in a temporary folder; under CI (CI=true, a clean fresh
# clone) the mistakes are applied in the clone itself and its build/ from tests/run is reused,
# and the tree is restored at the end. Where ccache is installed the build uses it, so that the
# file a mistake touched compiles from the cache once restored.
set -euo pipefail
# bash reads a script as it runs it: an edit of this file during a run would change the lines
# still to come (a run of an hour invites one). It runs from a copy, which it unlinks at once
# (bash keeps reading its open file).
if [ "${GBSSN1D_MISTAKES_COPY:-}" != "$0" ]; then
  copy=$(mktemp)
  cp "$0" "$copy"
  GBSSN1D_MISTAKES_COPY=$copy GBSSN1D_MISTAKES_REPO=$(cd "$(dirname "$0")/.." && pwd) \
    exec bash "$copy" "$@"
fi
rm -f "$0"
mode=named
only=""
with_whole_library=false
while [ $# -gt 0 ]; do
  case "$1" in
    --full) mode=full ;;
    --only) only=${2:?--only needs a pattern}; shift ;;
    --whole-library) with_whole_library=true ;;
    -h|--help) sed -n '2,/^set -euo/p' "$GBSSN1D_MISTAKES_REPO/tests/mistakes.sh" | sed '$d' | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "usage: $0 [--full] [--only PATTERN] [--whole-library]" >&2; exit 2 ;;
  esac
  shift
done
repo=$GBSSN1D_MISTAKES_REPO
jobs=$(nproc)
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
if [ "${CI:-}" = true ] && [ -z "$(git -C "$repo" status --porcelain)" ] \
   && [ -f "$repo/build/CMakeCache.txt" ]; then
  # CI's fresh clone is HEAD, clean: apply the mistakes there and reuse its build
  cd "$repo"
  trap 'git -C "$repo" checkout -q -- .' EXIT
else
  work=$(mktemp -d)
  trap 'git -C "$repo" worktree remove --force "$work/src" >/dev/null 2>&1 || true; rm -rf "$work"' EXIT
  git -C "$repo" worktree add -q --detach "$work/src" HEAD
  cd "$work/src"
fi
# shellcheck source=.ci/generator.sh
source .ci/generator.sh
generator_for build
cmake -S . -B build "${generator[@]}" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" >/dev/null
if [ $mode = full ]; then
  cmake --build build -j "$jobs" >/dev/null
else
  cmake --build build -j "$jobs" --target gbssn1d_tests >/dev/null
fi

# name | file | text | replacement | tests   (\n in text or replacement stands for a newline;
# tests: ctest names separated by ';', which no test name holds; text and replacement hold no '|')
mistakes=(
  "K boundary speed sqrt(2) -> 1|src/core/registry.hpp|{Var::K, \"K\", +1, 0.0, Wave::slicing, 1.0}|{Var::K, \"K\", +1, 0.0, Wave::light, 1.0}|outer boundary: K and alpha leave at the gauge speed sqrt(2), the rest at 1"
  "Delta^r parity flipped|src/core/registry.hpp|{Var::Delta_r, \"Delta_r\", -1,|{Var::Delta_r, \"Delta_r\", +1,|parities: the registry matches the tensor types (Sec. 7)"
  "timeseries.dat's Phi_center read from Pi's row|src/evolution/observe.cpp|centre_grid, Var::Phi), centre_grid) : nan;|centre_grid, Var::Pi), centre_grid) : nan;|timeseries.dat's Phi_center follows the flat wave at the centre, A (f(t) + t f'(t)) for the time-symmetric pulse f, within 1e-3 A at N = 400, and vacuum runs have no such column"
  "--shift zero not reaching the equations (the Gamma-driver still moves beta)|src/config/param_convert.cpp|    r.gauge.shift.xi = 0.0;|    r.gauge.shift.xi = r.gauge.shift.xi;|--shift zero: beta stays exactly 0 through a collapse to a black hole (B is driven but never reaches it), where the Gamma-driver's shift does not"
  "H and M_r columns swapped in profiles.dat|src/io/output.cpp|{d.H[k], d.M_r[k],|{d.M_r[k], d.H[k],|output columns: each named column holds that quantity (H, M_r, fields, norms)"
  "eta dt stability limit x100|src/config/param_rules.hpp|inline constexpr double eta_dt_max = 2.78;|inline constexpr double eta_dt_max = 278.0;|the Gamma-driver damping limit: eta dt = 2.7 runs, 2.8 is refused as unstable"
  "driver-full-shift a no-op|src/gbssn/rhs_study.cpp|      gd = full_shift(p);|      ;|driver-full-shift changes B's driver where beta_H is non-zero, and only B"
  "boxes' tapered buffer never applied|src/mesh/hierarchy.cpp|    taper_from_parent(u, l + 1);\n|\n|the tapered buffer absorbs the wormhole's gauge pulse where it returns from a box end"
  "a recorded config without box-taper resumed with today's default|src/config/config_file.cpp|  static const std::map<std::string, std::string> values{{\"box-taper\", \"0\"}, {\"kappa1-hole\", \"0\"}};|  static const std::map<std::string, std::string> values{{\"kappa1-hole\", \"0\"}};|a boxes run recorded before --box-taper existed resumes without the taper it never had, and today's default is another configuration"
  "a recorded Z4c config without kappa1-hole resumed with today's default|src/config/config_file.cpp|  static const std::map<std::string, std::string> values{{\"box-taper\", \"0\"}, {\"kappa1-hole\", \"0\"}};|  static const std::map<std::string, std::string> values{{\"box-taper\", \"0\"}};|a Z4c run recorded before --kappa1-hole existed resumes with kappa1 everywhere, and today's default is another configuration"
  "midstep-update never firing|src/evolution/horizon_tracker.cpp|static_cast<std::uint64_t>(4 * s.every_steps) == 1|static_cast<std::uint64_t>(4 * s.every_steps) == 99|midstep-update searches inside the step: the shrink moves the horizon"
  "--rah-width ignored|src/config/param_convert.cpp|  r.horizon_shift.width = p.rah_width;|  r.horizon_shift.width = 1.0;|--rah-width reaches the shift: f(r) = (r/w)/(1 + (r/w)^2) with the width given;evolution_config: each flag reaches its field, areal windows scale with M"
  "an empty norm window's norm 0 again|src/diagnostics/constraints.cpp|? std::sqrt(sum / width) : std::numeric_limits<double>::quiet_NaN();|? std::sqrt(sum / width) : 0.0;|l2_norm: cell-width weights, the range selects points, an empty range gives NaN;the areal and interior norms of an empty window are NaN, not 0"
  "a quantity without a value judged as converging|src/study/verdict.cpp|: j.valued == 0 ? ConvergenceClass::unjudged|: j.valued == 0 ? ConvergenceClass::converges|verdict: a norm without a value at any time (an empty window) is not judged, never 'converges'"
  "--force keeps the earlier run's checkpoint|src/cli/evolve_command.cpp|    std::filesystem::remove(dir / \"checkpoint.bin\", ignored);|    (void)ignored;|--force leaves hard-linked copies of the earlier run as they were, and drops its checkpoint"
  "horizon: the search near a seed keeps the innermost outer surface|src/horizon/apparent_horizon.cpp|    return s.outer;\n  };|    return false;\n  };|with several marginal surfaces the horizon is the outermost outer one"
  "horizon: --ah-every extrapolated extrapolates from its first radius|src/evolution/horizon_extrapolated.cpp|history_.size() < 4;|history_.size() < 1;|--ah-every extrapolated: h_AH from the last four radii converges at 4th order in dt to the substage search's"
  "resume: the checkpoint looked for before the folder's lock|src/cli/resume_command.cpp|  const FolderLock lock(\"DIR\", dir);\n  check_resume_dir(dir_name, true);|  check_resume_dir(dir_name, true);\n  const FolderLock lock(\"DIR\", dir);|one writer per folder: a folder another process writes is refused by evolve and resume, with or without --force, nothing written, the lock ends with its holder"
  "horizon: after --ah-tmax each box holds its own last extrapolation|src/evolution/horizon_extrapolated.cpp|  // different one on each box, and not the one the output reported\n  if (!config_.horizon_search.in_window(t)|  // different one on each box, and not the one the output reported\n  if (!config_.horizon_search.in_window(t))\n    return held;\n  if (false|--ah-every extrapolated after --ah-tmax: every box holds the h_AH the output reports, the last radius found"
  "horizon: the output extrapolates from fewer than four radii|src/evolution/horizon_extrapolated.cpp|  if (!searches_stages()|  if (true|--ah-every extrapolated: in the first steps after --ah-tmin the output's h_AH is searched for, as the evolution's is"
  "checkpoint: a single grid's h_AH history left out|src/evolution/simulation_checkpoint.cpp|  c.h_AH_history = tracker_->history(); // boxes|  // boxes|resume: a run continued from its checkpoint is bit-identical to an uninterrupted one"
  "horizon: the substage search's areal radius 0 instead of NaN|src/horizon/apparent_horizon.cpp|areal_radius ? lagrange6(x, R_rows, j0, x_root) : std::numeric_limits<double>::quiet_NaN();|areal_radius ? lagrange6(x, R_rows, j0, x_root) : 0.0;|the substage search without the areal radius finds the full search's r, bit for bit"
  "horizon: the innermost outer surface instead of the outermost|src/horizon/apparent_horizon.cpp|  for (const auto& s : surfaces)\n    if (s.outer)\n      return s;\n  return std::nullopt;|  std::optional<MarginalSurface> found;\n  for (const auto& s : surfaces)\n    if (s.outer)\n      found = s;\n  return found;|with several marginal surfaces the horizon is the outermost outer one"
  "converge's round-off floor scaled with M/dr_min instead of its square|src/study/verdict.cpp|  return std::numeric_limits<double>::epsilon() * ratio * ratio;|  return std::numeric_limits<double>::epsilon() * ratio;|the round-off floor: eps (M/dr_min)^2, as measured on the stationary trumpet;converge: a member at the round-off floor converges until the floor (exit 0), and the verdict names it and the floor's estimate"
  "converge ignores -j|src/study/converge.cpp|  run_tasks(s.members.size(), options.jobs,|  run_tasks(s.members.size(), 1,|converge -j runs that many members at once"
  "B's advective bracket with the wrong sign|src/gbssn/gauge.hpp|advection * (p.adv[Var::B] - gauge_shift.adv_Delta_r)|advection * (p.adv[Var::B] + gauge_shift.adv_Delta_r)|--advective-shift adds beta beta' to d_t beta and beta (B' - Delta') to d_t B"
  "beta's advective bracket dropped|src/gbssn/gauge.hpp|  return driver.xi * p.f[Var::B] + advection * p.adv[Var::beta];|  return driver.xi * p.f[Var::B];|--advective-shift adds beta beta' to d_t beta and beta (B' - Delta') to d_t B"
  "the flags whose rows name their field not copied there (--advective-shift, --ko-sigma, --tmax, ...)|src/config/param_convert.cpp|  copy_into(p, c);|  static_cast<void>(0);|evolution_config: each flag reaches its field, areal windows scale with M;--advective-shift adds beta beta' to d_t beta and beta (B' - Delta') to d_t B"
  "numbers read as octal again|src/core/decimal.hpp|    result = std::from_chars(text.data(), end, value, 10);|    result = std::from_chars(text.data(), end, value, text.size() > 1 && text[0] == '0' ? 8 : 10);|numbers are decimal on every path: 032 is 32 in flags, config files, sweeps, lists"
  "boxes: quadratic time weights of two levels swapped|src/mesh/time_interpolation.hpp|  return {(t - t1) * (t - t2) / ((t0 - t1) * (t0 - t2)),\n          (t - t0) * (t - t2) / ((t1 - t0) * (t1 - t2)),|  return {(t - t0) * (t - t2) / ((t1 - t0) * (t1 - t2)),\n          (t - t1) * (t - t2) / ((t0 - t1) * (t0 - t2)),|quadratic time interpolation is exact for quadratics, linear for lines;gauge pulse, quadratic time interpolation with buffers: converges, time error limits the order"
  "boxes: restriction missing after the fine steps|src/mesh/hierarchy.cpp|    restrict_level(u, l + 1);\n    taper_from_parent(u, l + 1);|    taper_from_parent(u, l + 1);|gauge pulse across refinement boundaries, RK4 stage values: 4th order, reflections converge away;the 1+log trumpet on five boxes converges at 4th order through refinement boundaries (RMS over time of H, three resolutions)"
  "boxes: a wrong restriction weight|src/mesh/transfer.hpp|restrict_weights = lagrange_weights<6>(-2.0, 0.5);|restrict_weights = lagrange_weights<6>(-2.0, 0.55);|restriction is exact for degree 5 with parity, and r^6 leaves (225/64) dr_f^6;prolongation, restriction and restriction after prolongation: 6th order"
  "boxes: prolongation stencil off by one|src/mesh/transfer.hpp|    const long first = plus ? i - 2 : i - 3;|    const long first = plus ? i - 3 : i - 3;|prolongation is exact for polynomials of degree 5 with parity, next to r = 0 too;prolongation of r^6: the error is the Lagrange remainder (10395/4096) dr^6"
  "boxes: fine ghosts not refilled for output between steps|src/evolution/simulation.cpp|      stepper_.fill_ghosts(levels_u_);|      ;|output between the steps of boxes agrees with a run that steps onto the output time"
  "boxes: every box its own latest h_AH (no one h_AH(t))|src/evolution/horizon_tracker.cpp|(layout.levels() > 1 && s.schedule != SearchSchedule::box_substage))|(layout.levels() > 1 && false))|a horizon stretched to 2 M on six boxes: RK4 stage values converge at 4th order at cfl 0.25 and 0.5 alike, quadratic time interpolation at cfl 0.25 too, and at cfl 0.5 it loses its order"
  "boxes: h_AH history not restored from a checkpoint|src/evolution/horizon_extrapolated.cpp|  history_ = history;|  (void)history;|a box run resumed from a checkpoint is bit-identical on every level"
  "boxes: checkpoint without the quadratic time levels|src/evolution/simulation_checkpoint.cpp|      c.history.push_back(std::move(history));|      c.history.emplace_back();|a box run resumed from a checkpoint is bit-identical on every level"
  "evolve --force: the files it leaves beside the run not named|src/cli/evolve_command.cpp|  if (!p.force)\n    return {};|  if (true)\n    return {};|hostile inputs: each refused cleanly, naming its flag, nothing written or damaged"
  "converge --force: the files it leaves beside the study not named|src/cli/converge_command.cpp|  if (options.force && !continuing) // what|  if (false) // what|hostile inputs: each refused cleanly, naming its flag, nothing written or damaged"
  "resume: the output files' rows not compared with the checkpoint's hashes|src/io/output.cpp|  if (!m.hashed)|  if (true)|resume refuses output files whose rows were edited or replaced since the checkpoint (same length), changing nothing, and a format-3 checkpoint resumes by lengths alone"
  "boxes: the start's pilot seeds nothing (h_AH from one, two and three radii again)|src/evolution/horizon_extrapolated.cpp|  seed_start(std::move(nodes));|  nodes.clear();|subcycled boxes with the horizon shift start from a pilot without subcycling: their r_AH follows the unsubcycled run's, the difference falling with N"
  "boxes: the pilot's h_AH from its first four radii at every time (no local cubic)|src/evolution/horizon_extrapolated.cpp|std::clamp<std::ptrdiff_t>((after - nodes.begin()) - 2, 0, last_start);|std::clamp<std::ptrdiff_t>(0, 0, last_start);|subcycled boxes with the horizon shift start from a pilot without subcycling: their r_AH follows the unsubcycled run's, the difference falling with N"
  "boxes: quadratic earlier time levels made without the horizon shift|src/evolution/simulation.cpp|    if (reinitialises())\n      stepper_.initialise(levels_u_, t_);|    if (false)\n      stepper_.initialise(levels_u_, t_);|a horizon stretched to 2 M on six boxes: RK4 stage values converge at 4th order at cfl 0.25 and 0.5 alike, quadratic time interpolation at cfl 0.25 too, and at cfl 0.5 it loses its order"
  "boxes: composite origin ghosts from the coarsest box|src/mesh/composite.cpp|    out[i] = per_level[finest][i];|    out[i] = per_level[0][i];|the composite of boxes tiles [0, rmax] with each r from the finest box covering it"
  "checkpoint written in place, not renamed over|src/io/data_file.cpp|  const std::filesystem::path tmp = path.string() + \".tmp\";|  const std::filesystem::path tmp = path;|resume: a run continued from its checkpoint is bit-identical to an uninterrupted one"
  "checkpoint drops the RHS-evaluation counter|src/evolution/simulation_checkpoint.cpp|  c.evaluations = evaluations_before_rhs_;|  c.evaluations = 0;|resume checks the checkpoint and every file before it changes any: corrupt, patched, foreign or incomplete input is refused and the run is left byte for byte;a box run resumed from a checkpoint is bit-identical on every level"
  "checkpoint checksum not checked|src/evolution/checkpoint.cpp|  if (fnv1a(body) != stored_hash)|  if (false)|resume checks the checkpoint and every file before it changes any: corrupt, patched, foreign or incomplete input is refused and the run is left byte for byte"
  "sweep reruns reuse members of other inputs|src/study/sweep_store.cpp|    if (!all.empty())|    if (false)|sweep: a rerun with other inputs is refused, naming the member and the flags that changed, before anything runs or changes, the same inputs continue the sweep"
  "--upwind biased evaluated with the lopsided pair|src/gbssn/dispatch.hpp|    return fn.template operator()<fd::Upwind::biased>();|    return fn.template operator()<fd::Upwind::lopsided>();|--upwind biased: the advection terms converge at p + 1, the right-hand sides at p"
  "--upwind biased's warnings silenced|src/config/param_warnings.cpp|  if (p.upwind != fd::Upwind::biased|  if (true|--upwind biased warns where it measured worse: a throat coarser than M/12, a shrink"
  "--upwind not passed on to the equations|src/config/param_convert.cpp|  r.upwind = p.upwind.value();|  (void)p.upwind.value();|evolution_config: each flag reaches its field, areal windows scale with M"
  "the biased pair's sum replaced by the lopsided one in the point loop|src/gbssn/rhs_loop.hpp|    pd.adv[v] = fd::advect_from<p, upwind>(beta_r, fd::upwind_sum<p, upwind>(f), ko[v]);|    pd.adv[v] = fd::advect_from<p, upwind>(beta_r, fd::upwind_sum<p, fd::Upwind::lopsided>(f), ko[v]);|--upwind biased: the advection terms converge at p + 1, the right-hand sides at p"
  "--fd-order 6 differenced at 4th order|src/gbssn/dispatch.hpp|  case 6:\n    return fn.template operator()<6>();|  case 6:\n    return fn.template operator()<4>();|every --fd-order: stationary spacetimes' right-hand sides converge at that order"
  "beta_H not tapered before the outer boundary|src/gbssn/horizon_shift.cpp|           * outer_taper(std::abs(grid.r()[i]) / params.r_cut, params.taper);|           * 1.0;|beta_H is tapered to zero before the outer boundary: quartic (default) and step"
  "a legacy checkpoint's old outer ghosts dropped|src/evolution/checkpoint.cpp|    for (std::size_t k = 0; k < n + legacy_ghosts; ++k) // interior and the old outer ghosts|    for (std::size_t k = 0; k < n; ++k)|a checkpoint with the 3 ghosts of earlier versions resumes as if never stopped"
  "--rah-profile auto recorded without its width|src/config/params.cpp|      p.rah_width = hs.width;|      (void)hs.width;|--rah-profile auto: rational with w = 3 max(h, M) to stretch, gauss with w = 1 M to shrink"
  "boxes without their default taper|src/config/params.cpp|    p.box_taper = p.grid == RadialGrid::boxes && p.levels.value_or(1) > 1 ? 0.5 : 0.0;|    p.box_taper = 0.0;|the tapered buffer absorbs the wormhole's gauge pulse where it returns from a box end"
  "a requeued sweep member starts over instead of resuming|src/study/sweep_process.cpp|        resumable ? std::vector<std::string>{\"resume\", member_dir.string()} : m.args;|        m.args;|sweep on a cluster: emitted lines run from any folder, resume, --collect summarises"
  "invalid sweep members emitted as task lines|src/study/sweep_tasks.cpp|    if (const auto why = invalid_reason(m)) {\n      say(|    if (const auto why = invalid_reason(m); false) {\n      say(|sweep on a cluster: emitted lines run from any folder, resume, --collect summarises"
  "converge samples reused for other radii|src/study/converge.cpp|    s.samples_key += fmt::format(\" {:.17g}\", r);|    (void)r;|converge: samples saved with a member's checkpoint are reused only for the same fields and radii (a rerun with another coarsest member gives a fresh run's numbers)"
  "boxes: fine levels differenced at 4th order whatever --fd-order|src/mesh/layout.cpp|                        fd_order);|                        4);|mesh layout: every level differences at the order asked, and boxes offer 2, 4 and 6"
  "beta_H's quartic taper only quadratic|src/gbssn/horizon_shift.hpp|    return std::exp(-x2 * x2);|    return std::exp(-x2);|beta_H is tapered to zero before the outer boundary: quartic (default) and step"
  "B's matched driver term without its beta_H correction (B driven by the full shift)|src/gbssn/rhs_loop.hpp|      + driver_w.matched * (p.adv[Var::Delta_r] - beta_H * d1_scale * fd::d1_centred<order>(Delta));|      + driver_w.matched * (p.adv[Var::Delta_r]);|B's driver term: the matched and centred stencils discretise one equation (B agrees to truncation error, falling with N), unlike B driven by the full shift"
  "the published driver stencil as the default again|src/config/params.hpp|  DriverStencilChoice driver_advection = AdvectionStencil::matched;|  DriverStencilChoice driver_advection = AdvectionStencil::upwind_gd;|B's driver term under refinement: the published upwind-gd stencil blows up at a time that falls with the spacing, the matched stencil (default) runs"
  "the areal window's outer sheet from the global minimum of R|src/diagnostics/constraints.cpp|  while (throat > 0 && R_areal[throat - 1] <= R_areal[throat])\n    --throat;|  throat = static_cast<std::size_t>(std::min_element(R_areal.begin(), R_areal.end()) - R_areal.begin());|areal-radius norms: weights the areal widths, select by R, only the outer sheet, and the interior window"
  "empty flag values accepted again|src/cli/cli.cpp|    refuse_empty_values(words);\n|    (void)refuse_empty_values;\n|hostile inputs: each refused cleanly, naming its flag, nothing written or damaged"
  "a resumed box run's finer levels count RHS evaluations without their subcycling factor|src/evolution/simulation_checkpoint.cpp|          + 4 * static_cast<std::uint64_t>(c.step) * static_cast<std::uint64_t>(stepper_.steps(l));|          + 4 * static_cast<std::uint64_t>(c.step);|a box run resumed from a checkpoint is bit-identical on every level"
  "sweep: failed members done for good (a killed member never resumed)|src/study/sweep_store.cpp| r->status == \"blew-up\")| r->status == \"blew-up\" or r->status == \"failed\")|sweep: a failed or killed member runs again from its checkpoint, a blown-up one does not, and one process at a time runs a member"
  "sweep: blown-up members run again on a rerun|src/study/sweep_store.cpp| r->status == \"blew-up\")| false)|sweep: a failed or killed member runs again from its checkpoint, a blown-up one does not, and one process at a time runs a member"
  "sweep: no member lock (one member run by two processes at once)|src/study/sweep_process.cpp|  if (::flock(lock, LOCK_EX|  if (false && ::flock(lock, LOCK_EX|sweep: a failed or killed member runs again from its checkpoint, a blown-up one does not, and one process at a time runs a member"
  "a study task's exception leaves its thread (abort)|src/study/parallel.hpp|            first = std::current_exception();|            throw;|run_tasks: every task once, and a task's exception is rethrown to the caller, later tasks are not started"
  "config strings: escapes read as the escaped letter|src/config/config_reader.cpp|      value += it->second;|      value += e;|config files read back every string exactly: '#', quotes, backslashes, newlines"
  "a removed output folder not noticed (exit 0, nothing on disk)|src/io/data_file.cpp|    throw OutputError(fmt::format(\"{} was removed|    (void)(fmt::format(\"{} was removed|the output folder removed during a run: the run stops with exit 1 and says why"
  "converge interrupted: the same command refused instead of continuing|src/cli/converge_command.cpp|    continuing = true;|    continuing = false;|converge interrupted: exit 130, and its files and message say they are partial"
  "sweep --emit-tasks overwrites a file of other content|src/study/sweep_tasks.cpp|    if (text.str() != lines)|    if (false)|hostile inputs: each refused cleanly, naming its flag, nothing written or damaged"
  "--upwind biased: Delta^r's stencil with the lopsided pair's ratio|src/gbssn/rhs_loop.hpp|half_diff = (0.5 * fd::Order<p>::template upwind_ratio_of<u>)*diff;|half_diff = (0.5 * fd::Order<p>::upwind_ratio)*diff;|Delta^r's advection in the point loop is the upwind stencil of the pair asked, every order"
  "boxes: h_AH extrapolated through three radii instead of four|src/evolution/horizon_extrapolated.cpp|    if (history_.size() > 4)|    if (history_.size() > 3)|boxes' extrapolated h_AH: the cubic through the last four radii found, exact for a horizon moving as a cubic in t"
  "converge: each verdict window drops its last time|src/study/verdict.cpp|end = (w + 1) * j.judged / j.windows;|end = (w + 1) * j.judged / j.windows - 1;|verdict: the windows tile every judged time, the last one too: one bad time anywhere is found by its window"
  "sweep: a spike's median includes the member itself|src/study/sweep_summary.cpp|          if (j != k)\n            others.push_back|          if (true)\n            others.push_back|sweep spikes: the median is the neighbours' alone, so a two-member sweep flags its spike"
  "config files: a bare value not ended by a carriage return (CRLF files refused)|src/config/config_reader.cpp|line.find_first_of(\" \t\r#\", k);|line.find_first_of(\" \t#\", k);|a config file with CRLF line ends reads as the same file with LF ones"
  "6-point interpolation one node off centre|src/grid/interpolation.hpp|const std::size_t start = k >= 2 ? k - 2 : 0;|const std::size_t start = k >= 1 ? k - 1 : 0;|6-point interpolation at radius: the error on x^6 is the remainder of the centred six nodes, next to the ends too"
  "resume: a quadratic time level at or after the checkpoint's time accepted|src/evolution/checkpoint.cpp| !(h.t < c.t))| false)|resume refuses a checkpoint whose quadratic time level is not before its time"
  "--dr-inner called idle on the sinh grid (two runs of other spacings called the same run)|src/config/flag_rows.cpp|       Acts::on_sinh, above(0.0)},|       Acts::on_boxes, above(0.0)},|the same run: a flag the table calls idle changes no number the run writes, and where it acts it changes them and the run key"
  "--lapse0 said to act on every data set (no idle-flag warning, trumpets with other lapse0 told apart)|src/config/flag_rows.cpp| precollapsed\", Acts::with_wormhole},| precollapsed\"},|the same run: a flag the table calls idle changes no number the run writes, and where it acts it changes them and the run key"
  "Z4c's diagnostics read K-hat instead of the ADM K|src/gbssn/diagnostic_rows.cpp|    pd = diagnosed<formulation>(pd);|    pd = diagnosed<Formulation::bssn>(pd);|Z4c: the constraints and the expansion read K-hat + 2 Theta, the ADM trace"
  "adm_point_data reads K-hat instead of the ADM K|src/gbssn/rhs.cpp|  return adm ? diagnosed<f>(pd) : pd;|  return pd;|diagnostic rows agree with the constraints and expansion computed point by point, and the finder's rows without the constraints with them"
  "Z4c's damping near the hole not capped by the cell width|src/gbssn/z4c.hpp|        std::max(params.kappa1, std::min(params.kappa1_hole, Z4cParams::kappa1_dr_max * p.inv_dr));|        std::max(params.kappa1, params.kappa1_hole);|robust stability: random noise around flat data stays bounded for 1000 M, and grows where the grid does not resolve the damping"
  "Z4c's damping near the hole read in the coordinate radius|src/gbssn/z4c.hpp|    const double q = areal_radius(p) / params.hole_radius, q2 = q * q;|    const double q = p.r / params.hole_radius, q2 = q * q;|Z4c's damping near the hole: its profile in the areal radius, and the cell's cap"
  "a study that judged nothing passes as at the round-off floor|src/study/verdict.cpp|      !v.items.empty()|      false && !v.items.empty()|verdict: times at round-off are not judged, and a study that judged nothing is no pass"
  "Z4c's Theta undamped|src/gbssn/z4c.hpp|        - p.f[alpha] * kappa1 * (2.0 + params.kappa2) * theta;|        - 0.0 * theta;|Z4c: kappa1 damps the constraints"
  "the check after each step passes every level (its vectorised count ignored)|src/evolution/observe.cpp|  return outside == 0;|  return outside >= 0;|check_physical_range: each bad value named with its box, radius and time"
  "boxes' fused stage fill: the pair's plus and minus prolongation weights exchanged|src/mesh/prolong_rows.cpp|        minus += prolong_weights_minus[m] * cm[m];\n        plus += prolong_weights_plus[m] * cm[m + 1];|        minus += prolong_weights_plus[m] * cm[m];\n        plus += prolong_weights_minus[m] * cm[m + 1];|prolong_combination is the combination prolonged, bit for bit, near r = 0 and away"
  "boxes: a parent's skipped cells reach R (not 3R, the four stages compounded) below the lowest cell read|src/mesh/hierarchy.cpp|  return static_cast<std::size_t>(std::max(0L, lowest - 3 * R));|  return static_cast<std::size_t>(std::max(0L, lowest - R));|a parent box skipping the cells under its child changes no bit of any level"
  "the point loop's first cell not rounded down to whole vectors (points change code path, and last bits)|src/gbssn/rhs.cpp|  first_cell_ = cell / vector_points * vector_points;|  first_cell_ = cell;|a parent box skipping the cells under its child changes no bit of any level"
  "boxes: the stage fills' weights memo ignores the parent's step (a shortened step reuses the full step's weights)|src/mesh/hierarchy.cpp|    if (!(memo->theta == theta && memo->ratio == ratio && memo->dt == P.dt)) {\n      memo = &L.weights_memo[1];\n      if (!(memo->theta == theta && memo->ratio == ratio && memo->dt == P.dt)) {|    if (!(memo->theta == theta && memo->ratio == ratio)) {\n      memo = &L.weights_memo[1];\n      if (!(memo->theta == theta && memo->ratio == ratio)) {|a box run resumed from a checkpoint is bit-identical on every level"
  "boxes: a stage fill with trailing zero weights reads u0 alone, k1's weight dropped|src/mesh/hierarchy.cpp|        if (w[1] == 0.0)\n          fill_from_parent(l, x, {&P.u0}, {w[0]}, j_begin);|        if (w[1] == w[1])\n          fill_from_parent(l, x, {&P.u0}, {w[0]}, j_begin);|gauge pulse across refinement boundaries, RK4 stage values: 4th order, reflections converge away"
  "loop_mix --mca reads llvm-mca's header row as the port pressures|bench/loop_mix.py|values = lines[at + 2].split()|values = lines[at + 1].split()|loop_mix.py --mca reads llvm-mca's cycles and ports of the point loop"
  "loop_mix --mca divides llvm-mca's cycles by one iteration too few|bench/loop_mix.py|.group(1)) / iterations|.group(1)) / (iterations - 1)|loop_mix.py --mca reads llvm-mca's cycles and ports of the point loop"
  "loop_mix --mca names the least busy ports|bench/loop_mix.py|key=lambda kv: -kv[1])[:4]|key=lambda kv: kv[1])[:4]|loop_mix.py --mca reads llvm-mca's cycles and ports of the point loop"
  "the biased pair's point loops not vectorised|src/gbssn/rhs_biased.cpp|#include \"gbssn/rhs_bssn_equations.hpp\" // IWYU pragma: keep (PointEquations<bssn>, for the instances)|#pragma GCC optimize(\"no-tree-vectorize\")\n#include \"gbssn/rhs_bssn_equations.hpp\" // IWYU pragma: keep (PointEquations<bssn>, for the instances)|every instance of the point loop and of beta_H's loop is vectorised"
  "s^r through the divider again (sqrt(chi / a))|src/gbssn/horizon_shift.cpp|    const double beta_H = f[i] * amplitude * shift_normal(normal, chi[i], a[i], chi_smooth);|    const double beta_H = f[i] * amplitude * std::sqrt(std::max(chi[i], 0.0) / a[i]);|every instance of the point loop and of beta_H's loop is vectorised"
  "the finder's Newton-form interpolant with a first-level denominator at level 3|src/grid/interpolation.hpp|    c3 = (c3 - c2) / (x3 - x0);|    c3 = (c3 - c2) / (x3 - x2);|Lagrange6Newton: quintics exactly, and lagrange6's values to round-off"
  "boxes' extrapolated h_AH with first-level divided differences throughout|src/evolution/horizon_extrapolated.cpp| / (h[j][0] - h[j - level][0]);| / (h[j][0] - h[j - 1][0]);|boxes' extrapolated h_AH: the cubic through the last four radii found, exact for a horizon moving as a cubic in t"
  "diagnostic rows: the constraints never computed (the finder's instance for every call)|src/gbssn/diagnostic_rows.cpp|diagnostic_rows_at<p, formulation, matter, true>(|diagnostic_rows_at<p, formulation, matter, false>(|diagnostic rows agree with the constraints and expansion computed point by point, and the finder's rows without the constraints with them"
  "an unused include copied into a study file|src/study/verdict.cpp|#include \"study/orders.hpp\"\n|#include \"study/orders.hpp\"\n#include \"evolution/simulation.hpp\"\n|include rules: down the floors, parameter headers without the equations, no unused include"
  "Z4c's ADM-K lapse driven by K-hat + Theta|src/gbssn/z4c.hpp|lapse_theta(p.lapse_adm_K ? 2.0 : 0.0)|lapse_theta(p.lapse_adm_K ? 1.0 : 0.0)|Z4c: --z4c-lapse-adm drives the lapse by K-hat + 2 Theta, without it by K-hat"
  "--z4c-lapse-adm's table row: idle without damping|src/config/flag_rows.cpp|\"slicing) instead of K-hat\",\n       Acts::with_z4c, std::nullopt,|\"slicing) instead of K-hat\",\n       Acts::with_z4c_damping, std::nullopt,|--z4c-lapse-adm acts in Z4c without damping: its own run key, config line and numbers, idle in BSSN alone"
  "Z4c's damping limit twice as loose|src/config/validate_steps.cpp|rate * dt_finest > eta_dt_max)|rate * dt_finest > 2.0 * eta_dt_max)|Z4c's damping limit: kappa1 (2 + kappa2) dt just inside RK4's limit runs, just beyond it is refused, naming the flag"
  "a checkpoint's flag byte of 2 accepted|src/evolution/checkpoint.cpp|    if (v > 1)|    if (v > 2)|a checkpoint's flag bytes: 0 and 1 read back, any other value is refused as corrupt, naming the flag;resume refuses a checkpoint whose flag byte is neither 0 nor 1, naming the flag, and leaves the run as it was"
  "the horizon's root tolerance divided by dx/dr|src/horizon/apparent_horizon.cpp|params.tolerance * grid.inv_dr_dx()|params.tolerance / grid.inv_dr_dx()|--ah-tol bounds the error of the horizon's radius in r, on the sinh and the uniform grid"
  "the maximal trumpet's puncture series from u = 1e-7|src/initial_data/maximal_trumpet.cpp|  if (ln_u_small < std::log(1e-17))|  if (ln_u_small < std::log(1e-7))|MaximalTrumpet near the puncture: alpha, R and the initial data's fields to round-off across the switch to the puncture limit"
  "the start's pilot interpolating one node off centre|src/evolution/horizon_extrapolated.cpp|(after - nodes.begin()) - 2, 0, last_start)|(after - nodes.begin()) - 1, 0, last_start)|the start's pilot: h_AH between the pilot's radii is the cubic through the two radii before t and the two after"
  "the horizon scan stopping where the lower node of a cell is inside r_min|src/horizon/apparent_horizon.cpp|    if (grid.r()[grid.first_interior() + k] < params.r_min)|    if (grid.r()[grid.first_interior() + lo] < params.r_min)|a horizon in the cell that straddles the scan's inner limit is found: the wormhole's throat on the edge of the finest box"
  "a resumed run forgetting it reported the horizon|src/evolution/simulation_checkpoint.cpp|  reported_ = c.reported;|  reported_ = false;|resume of a completed run to its own tmax does nothing and changes no file, and a resumed run does not report its start's horizon again"
  "resume of a completed run to its own tmax runs again|src/cli/resume_command.cpp|p.tmax <= written.t_last)) {|p.tmax < written.t_last)) {|resume of a completed run to its own tmax does nothing and changes no file, and a resumed run does not report its start's horizon again"
  "config \\u escapes up to 00FF read|src/config/config_reader.cpp|code > 0x7f)|code > 0xff)|config files read back every string exactly: '#', quotes, backslashes, newlines"
  "the areal norm's interior cells weighted by their neighbours' whole distance|src/diagnostics/constraints.cpp|    const double dR = std::abs(R_areal[hi] - R_areal[lo]) / static_cast<double>(hi - lo);|    const double dR = std::abs(R_areal[hi] - R_areal[lo]);|the areal norm weights an end cell by its one-sided dR, an interior cell by half its neighbours' distance"
  "beta_GD's second derivative with the map's term of the wrong sign|src/gbssn/rhs_loop.hpp|                     + fd::d1_centred<order>(f) * inv_dx * d2_fx[i];|                     - fd::d1_centred<order>(f) * inv_dx * d2_fx[i];|the horizon shift on with h_AH held at h is the run without it, on the uniform and the sinh grid"
  "dissipation at sigma/dx, not the cell's sigma/dr|src/gbssn/rhs_loop.hpp|      const double ko = ko_scale * inv_rx[i];|      const double ko = ko_scale;|Kreiss-Oliger dissipation damps the highest grid mode of each field at sigma/dr, that field alone, every order, both formulations, uniform and sinh grids"
  "--gbssn-volume eulerian evolving the Lagrangian equations|src/gbssn/bssn_eulerian.hpp|    return gbssn_rhs<Volume::eulerian, M>(p, gauge, gauge_shift);|    return gbssn_rhs<Volume::lagrangian, M>(p, gauge, gauge_shift);|the Eulerian volume choice: point-wise RHS agrees with the symbolic reference"
  "the Eulerian (E3e) with the sign of alpha b A_a flipped|src/gbssn/equations.hpp|    rhs[b] = p.adv[b] + 2.0 * p.f[b] * p.f[beta] * p.inv_r + p.f[alpha] * p.f[b] * p.f[A_a];|    rhs[b] = p.adv[b] + 2.0 * p.f[b] * p.f[beta] * p.inv_r - p.f[alpha] * p.f[b] * p.f[A_a];|the Eulerian volume choice: point-wise RHS agrees with the symbolic reference"
  "midstep-update searching on the 3rd RK substage|src/evolution/horizon_tracker.cpp|% static_cast<std::uint64_t>(4 * s.every_steps) == 1|% static_cast<std::uint64_t>(4 * s.every_steps) == 2|--rah-variant midstep-update searches on the 2nd RK substage of every n-th step only"
  "resume refusing --tmax equal to its checkpoint's time|src/cli/resume_command.cpp|  if (p.tmax < c.t)|  if (p.tmax <= c.t)|resume --tmax equal to the checkpoint's time is not before it"
  "flag suggestions within one edit, not two|src/cli/cli.cpp|d = edit_distance(name.substr(2), known); d <= 2)|d = edit_distance(name.substr(2), known); d <= 1)|unknown flags are named as typed, with the nearest flags, and flags before the subcommand are told to follow it"
  "converge accepting a resolution given twice|src/study/converge.cpp|if (!(options.N[k] > options.N[k - 1]))|if (!(options.N[k] >= options.N[k - 1]))|hostile inputs: each refused cleanly, naming its flag, nothing written or damaged"
  "--gbssn-volume eulerian not passed on to the right-hand side|src/config/param_convert.cpp|? Formulation::bssn_eulerian|? Formulation::bssn|every flag acts where its table row says it acts: a number the run writes and the run key change with it, and the flags that change no number by design do what they do"
  "profiles' beta written as beta_GD alone|src/io/output.cpp|v = beta_GD + beta_H[i];|v = beta_GD;|profiles.dat: beta is beta_GD + beta_H, beta_GD the evolved shift, with the horizon shift on"
  "converge judged against 4th order whatever --fd-order|src/study/converge_verdict.cpp|s.options.expect_order.value_or(static_cast<double>(s.base.fd_order))|s.options.expect_order.value_or(4.0)|converge: the expected order is --fd-order's unless --expect-order is given"
  "a checkpoint at the run's last step refused|src/evolution/checkpoint.cpp|c.step > run.n_steps)|c.step >= run.n_steps)|SIGTERM: the run finishes its step, keeps complete files, says so, exits 143"
  "a flag's open lower bound taken as closed|src/config/flag_table.cpp|  const bool low = lo && (lo_open ? !(v > *lo) : !(v >= *lo));|  const bool low = lo && !(v >= *lo);|a flag's bounds: the refusal names the bound and its note, the edges as the row says"
  "the optional number flags' bounds skipped (NaN --eta accepted)|src/config/flag_table.cpp|            if (p.*member)\n              check(*(p.*member), num(*(p.*member)));|            if (false)\n              check(*(p.*member), num(*(p.*member)));|every bounded real flag refuses NaN given through the library, naming itself"
  "choice flags' names not checked by their rows|src/config/flag_table.cpp|              require_choice(flag, p.*member);|              (void)flag;|every choice flag refuses a name none of its choices has, listing them"
  "a given --kappa1 replaced by its rule when resolved|src/config/params.cpp|  r.kappa1_ = p.kappa1.value_or(kappa1_rule(p));|  r.kappa1_ = kappa1_rule(p);|every flag's bound: each limit validate() enforces is refused just beyond and accepted just inside"
  "the conformal factor's source twice the Hamiltonian constraint's|src/initial_data/scalar_pulse.cpp|- std::numbers::pi * dphi * dphi|- 2.0 * std::numbers::pi * dphi * dphi|the scalar field's data: the Hamiltonian constraint with its source converges at 4th order at t = 0 (the conformal factor from the constraint), far below 16 pi rho"
  "a sphere's energy flux interpolated from the Misner-Sharp mass's profile|src/evolution/observe.cpp|Lagrange6Newton(g.x(), F_l, k0)(x)};|Lagrange6Newton(g.x(), m_l, k0)(x)};|flux_R20 over t is the change of m_R20 (Hayward's identity on the constraints), at 4th order, and carries the pulse's ADM mass across R = 20"
  "converge's members written without their --flux-R spheres|src/study/converge_member.cpp|    out_storage.emplace(p.out, config + sim.run_facts(), sim.state().fields(),\n                        sim.config().spheres);|    out_storage.emplace(p.out, config + sim.run_facts(), sim.state().fields(),\n                        std::vector<double>{});|converge with --flux-R: every member completes and its series carries the sphere's columns"
  "the scalar field's K Pi term with the wrong sign|src/gbssn/matter.hpp|    rhs[Pi] = p.adv[Pi] + p.f[alpha] * trace_K * p.f[Pi]|    rhs[Pi] = p.adv[Pi] - p.f[alpha] * trace_K * p.f[Pi]|the scalar field: point-wise RHS of BSSN and Z4c with matter agree with the symbolic reference (Sec. 19, V10)"
  "B driven without the stress-energy's Delta^r term|src/gbssn/equations.hpp|rhs_Delta_r<volume>(p, m, gauge_shift) + matter.Delta_r,|rhs_Delta_r<volume>(p, m, gauge_shift),|the scalar field: point-wise RHS of BSSN and Z4c with matter agree with the symbolic reference (Sec. 19, V10)"
)

# Every test of the build, one a line: its number for `ctest -I`, the build target it needs
# (a doctest case: gbssn1d_tests, which builds gbssn1d too; a run of the binary: gbssn1d;
# anything else, e.g. a script: all), its name.
list_tests() {
  (cd build && ctest -N --show-only=json-v1) | python3 -c '
import json, os, sys
for number, test in enumerate(json.load(sys.stdin)["tests"], 1):
    exe = os.path.basename((test.get("command") or [""])[0])
    target = exe if exe in ("gbssn1d_tests", "gbssn1d") else "all"
    print(number, target, test["name"], sep="\t")'
}
# The tests that failed in ctest's output on stdin, one name a line (whatever the failure:
# a failed check, a crash or a timeout; not a test that could not be started).
failed_tests() {
  sed -n '/^The following tests FAILED:/,$ s/^[[:space:]]*[0-9]* - \(.*\) (\([^()]*\))$/\2\t\1/p' \
    | awk -F'\t' '$1 != "Not Run" && $1 != "Disabled" {print $2}'
}

# named mode: the test file of every doctest case, so that a mistake's doctest cases run from
# their file's own executable (gbssn1d_tests_<file>, tests/CMakeLists.txt), whose rebuild after
# a header's mistake is the library and that one file
declare -A file_of
if [ $mode = named ]; then
  for src in tests/*/test_*.cpp; do
    stem=$(basename "$src" .cpp)
    while IFS= read -r case_name; do
      file_of["$case_name"]=$stem
    done < <(build/tests/gbssn1d_tests --list-test-cases --source-file="*/$src" \
               | sed -n '3,$p' | sed '/^=====/,$d')
  done
fi
# Runs one doctest case from its file's executable; prints its output; fails if it fails (or
# matches no case)
run_case() {
  local exe=$1 name=$2 out status=0
  # a doctest filter separates names at ',': escaped
  out=$(cd build/tests && timeout 1500 "./$exe" --test-case="${name//,/\\,}" 2>&1) || status=$?
  echo "$out"
  if ! grep -q "test cases: *1 |" <<<"$out"; then
    echo "(no test case matched)"
    return 99
  fi
  return $status
}

start=$(date +%s)
caught=0
problems=0
wrong=0
# a mistake not caught, not applied or not compiling: in the default mode the run stops there
problem() {
  echo "!! $1"
  problems=$((problems + 1))
  if [ $mode = named ]; then
    echo "planted mistakes: stopped at '$name' ($caught of $total caught before it)"
    exit 1
  fi
}
# The mistakes in headers that nearly every library file includes (the registry's table, the
# parameters' defaults): each recompiles the whole library, 190-234 s apiece beside the sanitizer
# stage (CI on a fresh clone, 2026-11-27: 627 s of the stage's 1557). They run with
# --whole-library, --full or --only, not by default, so that CI stays under its 25 minutes; their
# tests run in every CI's tests stage.
# With them, by hand as well: those whose files take longest to compile beside the sanitizer
# stage (every point-loop instance: 55 s; evolve_resume.cpp: 25 s; CI on a fresh clone,
# 2026-11-28, build stage 302 s) and the later rows in headers that every point loop includes
# (rhs_loop.hpp, equations.hpp, bssn_eulerian.hpp, gauge.hpp, dispatch.hpp: each such row
# recompiles all 38 point-loop instances, about 35 s of compiler time; each verified caught when
# added) and in core/decimal.hpp (55 s), so that CI stays under 25 minutes: CI on a fresh clone
# at 419a0cb took 1820 s, its mistakes stage 1435 s of it, these eight rows about 300 s of
# compiler time (measured per object file, 2026-12-07). The row in config/param_rules.hpp (eta
# dt's limit), which eight config files include since the flag table's rows carry bounds: 73 s
# (CI on a fresh clone of a1fd425, caught there).
whole_library=("K boundary speed sqrt(2) -> 1" "Delta^r parity flipped"
               "eta dt stability limit x100"
               "the scalar field's K Pi term with the wrong sign"
               "B driven without the stress-energy's Delta^r term"
               "the published driver stencil as the default again"
               "--force keeps the earlier run's checkpoint"
               "Z4c's ADM-K lapse driven by K-hat + Theta"
               "beta_GD's second derivative with the map's term of the wrong sign"
               "dissipation at sigma/dx, not the cell's sigma/dr"
               "--gbssn-volume eulerian evolving the Lagrangian equations"
               "the Eulerian (E3e) with the sign of alpha b A_a flipped"
               "B's advective bracket with the wrong sign" "beta's advective bracket dropped"
               "--upwind biased evaluated with the lopsided pair"
               "--fd-order 6 differenced at 4th order"
               "the biased pair's sum replaced by the lopsided one in the point loop"
               "B's matched driver term without its beta_H correction (B driven by the full shift)"
               "--upwind biased: Delta^r's stencil with the lopsided pair's ratio"
               "numbers read as octal again")
if [ -n "$only" ]; then
  selected=()
  for m in "${mistakes[@]}"; do
    grep -Eq -- "$only" <<<"${m%%|*}" && selected+=("$m")
  done
  mistakes=("${selected[@]}")
elif [ $mode = named ] && ! $with_whole_library; then
  selected=()
  skipped=0
  for m in "${mistakes[@]}"; do
    if printf '%s\n' "${whole_library[@]}" | grep -Fxq -- "${m%%|*}"; then
      skipped=$((skipped + 1))
    else
      selected+=("$m")
    fi
  done
  [ $skipped -eq ${#whole_library[@]} ] \
    || { echo "mistakes.sh: a whole-library mistake was renamed (update whole_library)" >&2; exit 1; }
  echo "planted mistakes: the $skipped that rebuild the whole library or take longest to compile skipped (--whole-library runs them)"
  mistakes=("${selected[@]}")
fi
total=${#mistakes[@]}
for m in "${mistakes[@]}"; do
  IFS='|' read -r name file from to named <<<"$m"
  git checkout -q -- .
  t0=$(date +%s)
  if ! python3 - "$file" "$from" "$to" <<'PY'
import sys
path, old, new = (a.replace('\\n', '\n') for a in sys.argv[1:])  # \n in a mistake: a newline
text = open(path).read()
if old not in text:
    sys.exit(1)
open(path, 'w').write(text.replace(old, new))
PY
  then
    problem "$name: text not found in $file (update this script)"; continue
  fi
  tests=$(list_tests)
  IFS=';' read -ra named_tests <<<"$named"
  numbers=() targets=() cases=() missing=()
  for t in "${named_tests[@]}"; do
    row=$(awk -F'\t' -v t="$t" '$3 == t' <<<"$tests")
    if [ -z "$row" ]; then missing+=("$t"); continue; fi
    target=$(cut -f2 <<<"$row")
    if [ $mode = named ] && [ "$target" = gbssn1d_tests ] && [ -n "${file_of[$t]:-}" ]; then
      cases+=("$t")
      targets+=("gbssn1d_tests_${file_of[$t]}")
    else
      numbers+=("$(cut -f1 <<<"$row")")
      targets+=("$target")
    fi
  done
  if [ ${#named_tests[@]} -eq 0 ] || [ ${#missing[@]} -gt 0 ]; then
    problem "$name: no test named, or a named test does not exist: ${missing[*]:-(none named)} (update this script)"
  fi
  if [ $mode = full ] || [[ " ${targets[*]} " == *" all "* ]]; then
    targets=(all)
  else
    mapfile -t targets < <(printf '%s\n' "${targets[@]}" | sort -u)
  fi
  if ! cmake --build build -j "$jobs" --target "${targets[@]}" >/dev/null 2>&1; then
    problem "$name: does not compile (update this script)"; continue
  fi
  t1=$(date +%s)
  if [ $mode = full ]; then
    out=$(cd build && ctest -j "$jobs" 2>&1 || true)
  else
    # doctest cases from their files' executables; the rest (runs of the binary, scripts)
    # through ctest -I Start,End,Stride,number,...: exactly those tests, by number
    out="" failed=""
    for t in "${cases[@]}"; do
      case_status=0
      case_out=$(run_case "gbssn1d_tests_${file_of[$t]}" "$t") || case_status=$?
      if [ $case_status -eq 99 ]; then
        problem "$name: the filter for '$t' matches no test case (update this script)"
      elif [ $case_status -ne 0 ]; then
        failed+="$t"$'\n'
        out+="$case_out"$'\n'
      fi
    done
    if [ ${#numbers[@]} -gt 0 ]; then
      ctest_out=$(cd build && ctest -j "$jobs" -I "0,0,0,$(IFS=,; echo "${numbers[*]}")" 2>&1 || true)
      out+="$ctest_out"
      failed+=$(failed_tests <<<"$ctest_out")
    fi
    failed=$(sed '/^$/d' <<<"$failed")
  fi
  if [ $mode = full ]; then
    failed=$(failed_tests <<<"$out")
  fi
  t2=$(date +%s)
  times="build $((t1 - t0)) s, tests $((t2 - t1)) s"
  if [ $mode = named ]; then
    catching=$(printf '%s\n' "${named_tests[@]}" | grep -Fxf <(printf '%s\n' "$failed") || true)
    if [ -z "$failed" ] || [ -z "$catching" ]; then
      echo "$out" | tail -n 20
      problem "$name: none of its named tests fails (${named_tests[*]})"; continue
    fi
    echo "== $name: caught by ($times)"; echo "$catching" | sed 's/^/   /'
    printf '%s\n' "${named_tests[@]}" | grep -Fxvf <(printf '%s\n' "$catching") | sed 's/^/   (named, not failing) /' || true
    caught=$((caught + 1))
    continue
  fi
  if [ -z "$failed" ]; then
    problem "$name: no test fails ($times)"; continue
  fi
  echo "== $name: caught by ($times; * named)"
  while IFS= read -r t; do
    if printf '%s\n' "${named_tests[@]}" | grep -Fxq -- "$t"; then echo " * $t"; else echo "   $t"; fi
  done <<<"$failed"
  caught=$((caught + 1))
  for t in "${named_tests[@]}"; do
    printf '%s\n' "$failed" | grep -Fxq -- "$t" \
      || { problem "$name: its named test '$t' does not catch it"; wrong=$((wrong + 1)); }
  done
done
git checkout -q -- .
echo "planted mistakes: $caught passed, $((total - caught)) failed$([ $mode = named ] || echo ", $wrong named tests not catching theirs") ($(( $(date +%s) - start )) s)"
[ $problems -eq 0 ]
