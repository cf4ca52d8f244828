#!/usr/bin/env bash
# Deliberate mistakes that the test suite must catch. Each is applied alone to a clean copy of
# HEAD (a git worktree in a temporary folder), the suite is rebuilt and run, and the tests that
# fail are listed; a mistake that no test catches is reported and the script exits 1.
# About 1 minute per mistake on 2 cores; CI runs it after tests/run.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'git -C "$repo" worktree remove --force "$work/src" >/dev/null 2>&1 || true; rm -rf "$work"' EXIT
git -C "$repo" worktree add -q --detach "$work/src" HEAD
cd "$work/src"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$(nproc)" >/dev/null

# name | file | text | replacement   (\n in text or replacement stands for a newline)
mistakes=(
  "K boundary speed sqrt(2) -> 1|src/core/registry.hpp|{Var::K, \"K\", +1, 0.0, Wave::slicing, 1.0}|{Var::K, \"K\", +1, 0.0, Wave::light, 1.0}"
  "Delta^r parity flipped|src/core/registry.hpp|{Var::Delta_r, \"Delta_r\", -1,|{Var::Delta_r, \"Delta_r\", +1,"
  "H and M_r columns swapped in profiles.dat|src/io/output.cpp|{d.H[k], d.M_r[k],|{d.M_r[k], d.H[k],"
  "eta dt stability limit x100|src/config/params.cpp|constexpr double eta_dt_max = 2.78;|constexpr double eta_dt_max = 278.0;"
  "driver-full-shift a no-op|src/gbssn/rhs.cpp|          gd = full_shift(p);|          ;"
  "midstep-update never firing|src/gbssn/rhs.cpp|static_cast<std::uint64_t>(4 * hs.midstep_every) == 1;|static_cast<std::uint64_t>(4 * hs.midstep_every) == 99;"
  "--rah-width ignored|src/config/params.cpp|  r.horizon_shift.width = p.rah_width;|  r.horizon_shift.width = 1.0;"
  "horizon: the innermost outer surface instead of the outermost|src/horizon/apparent_horizon.cpp|  for (const auto& s : surfaces)\n    if (s.outer)\n      return s;\n  return std::nullopt;|  std::optional<MarginalSurface> found;\n  for (const auto& s : surfaces)\n    if (s.outer)\n      found = s;\n  return found;"
  "converge ignores -j|src/study/converge.cpp|  run_tasks(m, options.jobs, member_task);|  run_tasks(m, 1, member_task);"
  "B's advective bracket with the wrong sign|src/gbssn/gauge.hpp|advection * (p.adv[Var::B] - gauge_shift.adv_Delta_r)|advection * (p.adv[Var::B] + gauge_shift.adv_Delta_r)"
  "beta's advective bracket dropped|src/gbssn/gauge.hpp|  return driver.xi * p.f[Var::B] + advection * p.adv[Var::beta];|  return driver.xi * p.f[Var::B];"
  "--advective-shift not reaching the evolution|src/config/params.cpp|  r.gauge.shift.advective = p.advective_shift;|  r.gauge.shift.advective = false;"
  "numbers read as octal again|src/config/numbers.hpp|    result = std::from_chars(text.data(), end, value, 10);|    result = std::from_chars(text.data(), end, value, text.size() > 1 && text[0] == '0' ? 8 : 10);"
  "boxes: quadratic time weights of two levels swapped|src/mesh/time_interpolation.hpp|  return {(t - t1) * (t - t2) / ((t0 - t1) * (t0 - t2)),\n          (t - t0) * (t - t2) / ((t1 - t0) * (t1 - t2)),|  return {(t - t0) * (t - t2) / ((t1 - t0) * (t1 - t2)),\n          (t - t1) * (t - t2) / ((t0 - t1) * (t0 - t2)),"
  "boxes: restriction missing after the fine steps|src/mesh/hierarchy.cpp|    restrict_level(u, l + 1);\n  }\n}|  }\n}"
  "boxes: a wrong restriction weight|src/mesh/transfer.hpp|restrict_weights = lagrange_weights<6>(-2.0, 0.5);|restrict_weights = lagrange_weights<6>(-2.0, 0.55);"
  "boxes: prolongation stencil off by one|src/mesh/transfer.hpp|    const long first = plus ? i - 2 : i - 3;|    const long first = plus ? i - 3 : i - 3;"
  "boxes: fine ghosts not refilled for output between steps|src/evolution/simulation.cpp|        stepper_.fill_ghosts(levels_u_);|        ;"
  "boxes: every box its own latest h_AH (no one h_AH(t))|src/evolution/simulation.cpp|         && hs.variant != HorizonShiftParams::Variant::box_substage;|         && false;"
  "boxes: h_AH history not restored from a checkpoint|src/evolution/simulation.cpp|    h_AH_history_ = c.h_AH_history;|    ;"
  "boxes: checkpoint without the quadratic time levels|src/evolution/simulation.cpp|      c.history.push_back(stepper_.history(l));|      c.history.emplace_back();"
  "boxes: quadratic earlier time levels made without the horizon shift|src/evolution/simulation.cpp|    if (reinitialises())\n      stepper_.initialise(levels_u_, t_);|    if (false)\n      stepper_.initialise(levels_u_, t_);"
  "boxes: composite origin ghosts from the coarsest box|src/mesh/composite.cpp|    out[i] = per_level[finest][i];|    out[i] = per_level[0][i];"
  "checkpoint written in place, not renamed over|src/io/output.cpp|  const std::filesystem::path tmp = path.string() + \".tmp\";|  const std::filesystem::path tmp = path;"
  "checkpoint drops the RHS-evaluation counter|src/evolution/simulation.cpp|  c.evaluations = evaluations_before_rhs_;|  c.evaluations = 0;"
  "checkpoint checksum not checked|src/evolution/checkpoint.cpp|  if (fnv1a(body) != stored_hash)|  if (false)"
  "sweep reruns reuse members of other inputs|src/study/sweep.cpp|    if (!diff.empty())|    if (false)"
  "--fd-order 6 differenced at 4th order|src/gbssn/rhs.cpp|  case 6:\n    evaluate<6>(u, dudt, t);|  case 6:\n    evaluate<4>(u, dudt, t);"
  "beta_H not tapered before the outer boundary|src/gbssn/horizon_shift.cpp|           * outer_taper(std::abs(grid.r()[i]) / params.r_cut, params.taper);|           * 1.0;"
  "a legacy checkpoint's old outer ghosts dropped|src/evolution/simulation.cpp|    for (std::size_t k = 0; k < n + legacy_ghosts; ++k) // interior and the old outer ghosts|    for (std::size_t k = 0; k < n; ++k)"
  "--rah-profile auto recorded without its width|src/config/params.cpp|      p.rah_width = hs.width;|      (void)hs.width;"
  "boxes take the single grid's cfl|src/config/params.cpp|    p.cfl = p.grid == \"boxes\" ? 0.25 : 0.5;|    p.cfl = 0.5;"
  "a requeued sweep member starts over instead of resuming|src/study/sweep.cpp|        resumable ? std::vector<std::string>{\"resume\", member_dir.string()} : m.args;|        m.args;"
  "invalid sweep members emitted as task lines|src/study/sweep.cpp|      if (const auto why = invalid_reason(m)) {\n        say(|      if (const auto why = invalid_reason(m); false) {\n        say("
  "converge samples reused for other radii|src/study/converge.cpp|    samples_key += fmt::format(\" {:.17g}\", r);|    (void)r;"
  "boxes: fine levels differenced at 4th order whatever --fd-order|src/mesh/layout.cpp|                        fd_order);|                        4);"
  "beta_H's quartic taper only quadratic|src/gbssn/horizon_shift.hpp|    return std::exp(-x2 * x2);|    return std::exp(-x2);"
)
uncaught=0
caught=0
for m in "${mistakes[@]}"; do
  IFS='|' read -r name file from to <<<"$m"
  git checkout -q -- .
  python3 - "$file" "$from" "$to" <<'PY' || { echo "!! $name: text not found in $file (update this script)"; uncaught=1; continue; }
import sys
path, old, new = (a.replace('\\n', '\n') for a in sys.argv[1:])  # \n in a mistake: a newline
text = open(path).read()
if old not in text:
    sys.exit(1)
open(path, 'w').write(text.replace(old, new))
PY
  if ! cmake --build build -j "$(nproc)" >/dev/null 2>&1; then
    echo "!! $name: does not compile (update this script)"; uncaught=1; continue
  fi
  failed=$(cd build && ctest -j "$(nproc)" 2>&1 | sed -n 's/^[[:space:]]*[0-9]* - \(.*\) (Failed)$/\1/p' || true)
  if [ -z "$failed" ]; then
    echo "!! $name: no test fails"; uncaught=1
  else
    echo "== $name: caught by"; echo "$failed" | sed 's/^/   /'
    caught=$((caught + 1))
  fi
done
total=${#mistakes[@]}
echo "planted mistakes: $caught passed, $((total - caught)) failed"
git checkout -q -- .
exit $uncaught
