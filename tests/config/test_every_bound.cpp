// Every evolve flag's bounds have a test of their own numbers: every fixed limit validate()
// enforces, the flag table's rows' bounds (config/flag_rows.cpp, check_bounds()) among them, is
// refused just beyond (exit 2, the flag named, nothing written) and accepted just inside
// (--print-config, which runs the same checks); a limit that depends on the step takes dt as
// validate() computes it; every flag validate.cpp names or the table bounds has a row or a
// reason. Every tolerance flag meets its tolerance: the horizon radius found with --ah-tol lies
// within it of a much tighter search, on the uniform and the default sinh grid. (Where each flag
// acts: tests/config/test_every_flag.cpp.)
#include "../cli/cli_support.hpp"
#include "config/flag_table.hpp"
#include "config/param_rules.hpp"
#include "config/params.hpp"
#include "evolution/evolution_config.hpp"
#include "evolution/levels.hpp"
#include "gbssn/rhs_params.hpp"
#include "grid/grid.hpp"
#include "mesh/hierarchy.hpp"
#include "mesh/layout.hpp"
#include "mesh/level_steps.hpp"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace gbssn1d;
using gbssn1d::testing::resolved_evolve;
using gbssn1d::testing::run;
using gbssn1d::testing::scratch;
using gbssn1d::testing::slurp;

// its own namespace: in the sanitizers' unity build it shares a translation unit with other
// configuration tests
namespace every_bound_test {

namespace {

// cheap configurations: 32 uniform cells
const std::string rows = " --tmax 0.5 --dt-series 0.25 --dt-profiles 0.5";
const std::string pulse = "--id flat --matter scalar --grid uniform --N 32 --rmax 16" + rows;

} // namespace

namespace {

/// A number as the command line reads it back exactly (the shortest text that round-trips).
std::string text(double v) {
  return fmt::format("{}", v);
}
double up(double v) {
  return std::nextafter(v, std::numeric_limits<double>::infinity());
}
double down(double v) {
  return std::nextafter(v, -std::numeric_limits<double>::infinity());
}
/// Just beyond or inside 0: the smallest normal number (a subnormal one is refused as such).
constexpr double tiny = std::numeric_limits<double>::min();

/// The steps and spacing validate() reads for `args`: the hierarchy's whole step, the finest
/// level's step and its smallest cell, computed as validate() computes them.
struct Steps {
  double dt, dt_finest, min_spacing;
};
Steps steps_of(const std::string& args) {
  const ResolvedParams p = resolved_evolve(args);
  const EvolutionConfig config = mesh_config(p);
  const mesh::MeshLayout layout = make_layout(config);
  const Grid& finest = layout.grid(layout.levels() - 1);
  return {mesh::hierarchy_dt(layout, config.stepping), time_step(p.cfl, finest),
          finest.min_spacing()};
}

/// A row of B: `--key beyond` on `base` is refused naming `flag` (its message holding `why`),
/// `--key inside` accepted; inside "" is not run (`why_not_inside` says why).
struct Bound {
  std::string flag, base, key, beyond, inside, why;
  std::string why_not_inside = "";
};

/// The value config text gives `key` (quotes taken off), "" if none.
std::string config_value(const std::string& config, const std::string& key) {
  std::istringstream in(config);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(key + " = ", 0) == 0) {
      std::string value = line.substr(key.size() + 3);
      if (value.size() >= 2 && value.front() == '"' && value.back() == '"')
        value = value.substr(1, value.size() - 2);
      return value;
    }
  return "";
}

void check_bound(const Bound& b) {
  const bool has_tmax = b.key == "tmax" || b.base.find("--tmax") != std::string::npos;
  const std::string args = b.base + (has_tmax ? "" : " --tmax 0") + " --" + b.key + " ";
  INFO("bound of " << b.flag << ": " << args << "[" << b.beyond << " refused, " << b.inside
                   << " accepted]");
  const fs::path out = scratch("every_bound_out");
  const auto refused = run("evolve " + args + b.beyond + " --out " + out.string());
  INFO("stderr: " << refused.err);
  CHECK(refused.status == 2);
  CHECK(refused.err.rfind("gbssn1d: error: " + b.flag + " = ", 0) == 0);
  CHECK(refused.err.find(b.why) != std::string::npos);
  CHECK_FALSE(fs::exists(out));
  if (b.inside.empty()) {
    CHECK_FALSE(b.why_not_inside.empty());
    return;
  }
  const auto accepted = run("evolve " + args + b.inside + " --print-config");
  INFO("accepted? stderr: " << accepted.err);
  CHECK(accepted.status == 0);
  CHECK(config_value(accepted.out, b.key) == b.inside);
}

/// The flags validate.cpp names (each string literal that is a flag alone).
std::set<std::string> flags_validate_names() {
  const std::string source = slurp(fs::path(GBSSN1D_SOURCE_DIR) / "src/config/validate.cpp");
  const std::regex literal("\"(--[A-Za-z0-9][A-Za-z0-9-]*)\"");
  std::set<std::string> flags;
  for (auto it = std::sregex_iterator(source.begin(), source.end(), literal);
       it != std::sregex_iterator(); ++it)
    flags.insert((*it)[1].str());
  return flags;
}

/// The flags whose row of the flag table carries bounds (check_bounds()).
std::set<std::string> flags_with_table_bounds() {
  std::set<std::string> flags;
  for (const auto& spec : param_specs())
    if (spec.bounds)
      flags.insert("--" + std::string(spec.name));
  return flags;
}

/// Flags validate.cpp names that have no numeric limit of their own, and why (a choice flag's
/// names are its row's: tests/config/test_flag_bounds.cpp).
const std::map<std::string, std::string>& no_numeric_limit() {
  static const std::map<std::string, std::string> flags{
      {"--time-interp", "a choice, refused without two or more boxes: no number"},
      {"--no-subcycling", "a switch, refused without two or more boxes: no number"},
      {"--matter", "a choice, refused with other orders, stencils, data or study variants: no "
                   "number"},
      {"--upwind", "a choice, refused with a study variant of --rah-variant: no number"},
      {"--shift", "a choice, refused as zero with trumpet data or --rahA: no number"},
      {"--formulation", "a choice, refused with a study variant of --rah-variant: no number"},
      {"--gbssn-volume", "a choice, refused as eulerian with --formulation z4c: no number"},
      {"--rah-variant", "a choice and its combinations (boxes, --ah-every): no number"},
  };
  return flags;
}

} // namespace

TEST_CASE("every flag's bound: each limit validate() enforces is refused just beyond and accepted "
          "just inside") {
  const std::string uniform = "--id 1log-trumpet --grid uniform --N 32 --rmax 16";
  const std::string boxes3 = "--id 1log-trumpet --grid boxes --N 32 --rmax 16";
  const std::string sinh = "--id 1log-trumpet"; // the default grid: sinh, N 400, rmax 1000
  const std::string z4c_uniform = uniform + " --formulation z4c";
  const Params defaults;
  std::vector<Bound> bounds{
      // the grid
      {"--N", "--id 1log-trumpet --grid uniform --rmax 16", "N", "15", "16",
       "must be at least 16 cells"},
      {"--N", "--id 1log-trumpet --grid uniform --rmax 16", "N", std::to_string(N_max + 1), "",
       fmt::format("at most {} cells", N_max),
       "accepting it builds the grid of N_max cells (12 s, 0.9 GB)"},
      {"--N", "--id 1log-trumpet --grid boxes --rmax 16 --levels 3", "N", "33", "34",
       "must be even with --grid boxes"},
      {"--levels", "--id 1log-trumpet --grid boxes --N 16 --rmax 16", "levels", "0", "1",
       fmt::format("must lie in [1, {}]", levels_max)},
      // (the finest of 30 boxes of 16 cells is 16/2^29/16 = 1.9e-9, above 1e-10 x rmax)
      {"--levels", "--id 1log-trumpet --grid boxes --N 16 --rmax 16", "levels",
       std::to_string(levels_max + 1), std::to_string(levels_max),
       fmt::format("must lie in [1, {}]", levels_max)},
      {"--box-taper", boxes3, "box-taper", text(-tiny), "0", "must lie in [0, 0.5]"},
      {"--box-taper", boxes3, "box-taper", text(up(0.5)), "0.5", "must lie in [0, 0.5]"},
      {"--box-taper-from", boxes3, "box-taper-from", text(-tiny), "0",
       "must be >= 0 (a radius in units of M)"},
      {"--dr-inner", sinh, "dr-inner", "0", "", "must be > 0",
       "the smallest positive width gives no usable grid: the grid's own row below"},
      {"--fd-order", uniform, "fd-order", "10", "8", "must be 2, 4, 6 or 8"},
      {"--fd-order", boxes3, "fd-order", "8", "6", "must be 2, 4 or 6 with --grid boxes"},
      // lengths in units of M: rmax / M at most rmax_over_M_max (no damping: eta dt would
      // refuse such cells first)
      {"--rmax", "--id 1log-trumpet --grid uniform --N 32 --eta 0", "rmax",
       text(up(rmax_over_M_max)), text(rmax_over_M_max), "is beyond"},
      {"--M", "--id 1log-trumpet --grid uniform --N 32 --rmax 1 --eta 0 --norm-rmin 0", "M",
       text(1.0 / rmax_over_M_max * (1 - 1e-9)), text(1.0 / rmax_over_M_max * (1 + 1e-9)),
       "gives --rmax / M"},
      {"--M", "--id 1log-trumpet --grid uniform --N 32 --rmax 1 --eta 0 --norm-rmin 0", "M", "0",
       text(1.0 / rmax_over_M_max * (1 + 1e-9)), "must be > 0"},
      {"--rmax", "--id 1log-trumpet --grid uniform --N 32", "rmax", "0", "", "must be > 0",
       "a radius just above 0 lies inside the black hole: the row below"},
      {"--rmax", "--id 1log-trumpet --grid uniform --N 32", "rmax", text(down(4.0)), "4",
       "the outer boundary must lie outside the black hole"},
      {"--rmax", "--id 1log-trumpet --grid sinh --N 32 --dr-inner 0.04", "rmax",
       text(0.04 * static_cast<double>(sinh_reference_N)),
       text(up(0.04 * static_cast<double>(sinh_reference_N))), "the sinh map with --dr-inner"},
      // the gauge, numerics, times and output cadences
      {"--eta", uniform, "eta", text(-tiny), "0", "must be >= 0"},
      {"--cfl", uniform, "cfl", text(down(cfl_min)), text(cfl_min), "such steps only accumulate"},
      {"--cfl", uniform, "cfl", text(up(cfl_max)), text(cfl_max), "outside the stable range"},
      {"--ko-sigma", uniform, "ko-sigma", text(-tiny), "0", "must lie in [0, 1]"},
      {"--ko-sigma", uniform, "ko-sigma", text(up(1.0)), "1", "must lie in [0, 1]"},
      {"--chi-floor", uniform, "chi-floor", text(-tiny), "0", "must lie in [0, 1)"},
      {"--chi-floor", uniform, "chi-floor", "1", text(down(1.0)), "must lie in [0, 1)"},
      {"--tmax", uniform, "tmax", text(-tiny), "0", "must be >= 0"},
      {"--dt-series", uniform, "dt-series", "0", text(tiny), "must be > 0"},
      {"--dt-series", uniform + " --tmax 1", "dt-series", text(1.0 / rows_max * (1 - 1e-9)),
       text(1.0 / rows_max * (1 + 1e-9)), "rows to --tmax"},
      {"--dt-profiles", uniform, "dt-profiles", "0", text(tiny), "must be > 0"},
      {"--dt-profiles", uniform + " --tmax 1", "dt-profiles", text(100.0 / rows_max * (1 - 1e-9)),
       text(100.0 / rows_max * (1 + 1e-9)), "profile blocks to --tmax"},
      {"--checkpoint-every", uniform, "checkpoint-every", text(-tiny), "0", "must be >= 0"},
      // the norm windows
      {"--norm-rmin", uniform, "norm-rmin", text(-tiny), "0", "must be >= 0"},
      {"--norm-rmax", uniform + " --norm-rmin 1", "norm-rmax", "1", text(up(1.0)),
       "must be > --norm-rmin"},
      {"--norm-rmax", uniform, "norm-rmax", text(up(16.0)), "16", "must not exceed --rmax"},
      {"--norm-Rmin", uniform, "norm-Rmin", "0", text(tiny), "must be > 0"},
      {"--norm-Rmax", uniform, "norm-Rmax", text(defaults.norm_Rmin), text(up(defaults.norm_Rmin)),
       "must be > --norm-Rmin"},
      {"--norm-Rint", uniform, "norm-Rint", "0", text(tiny), "must be > 0"},
      // the horizon-adjusting shift (validated with the shift off too: the values are recorded)
      {"--rahA", uniform, "rahA", text(-tiny), "0", "must be >= 0"},
      {"--rah0", uniform, "rah0", "0", text(tiny), "must be > 0"},
      {"--rah0", uniform + " --rahA 0.5 --rah-rcut 64", "rah0", "16", text(down(16.0)),
       "must be below --rmax"},
      {"--rah-width", uniform, "rah-width", "0", text(tiny), "must be > 0"},
      {"--rah-rcut", uniform, "rah-rcut", "0", text(tiny), "must be > 0"},
      {"--rah-chi-smooth", uniform, "rah-chi-smooth", "0", text(tiny), "must be > 0"},
      {"--rah-ramp", uniform, "rah-ramp", text(-tiny), "0", "must be >= 0"},
      // the scalar field's pulse: on the grid, and with time-symmetric data
      {"--scalar-amp", pulse, "scalar-amp", "0.3", "0.1", "gives no time-symmetric data"},
      {"--scalar-r0", pulse, "scalar-r0", text(-tiny), "0", "must be >= 0"},
      {"--scalar-r0", pulse, "scalar-r0", "16", text(down(16.0)), "must lie below --rmax"},
      {"--scalar-width", pulse, "scalar-width", "0", "", "must be > 0",
       "a width just above 0 is a pulse no grid holds: accepted, not run here"},
      {"--scalar-width", pulse, "scalar-width", "16", text(down(16.0)), "must lie below --rmax"},
      // Z4c's damping
      {"--kappa1", z4c_uniform, "kappa1", text(-tiny), "0", "must be >= 0"},
      {"--kappa1-hole", z4c_uniform + " --kappa1 0.5", "kappa1-hole", text(down(0.5)), "0.5",
       "must be 0 (off) or at least --kappa1"},
      {"--kappa2", z4c_uniform, "kappa2", "-1", text(up(-1.0)), "must be > -1"},
      // the horizon searches
      {"--ah-tol", uniform, "ah-tol", "0", text(tiny), "must be > 0"},
      {"--ah-every", uniform, "ah-every", "0", "1", "a whole number of steps >= 1"},
      {"--ah-interval", uniform, "ah-interval", "0", text(tiny), "must be > 0"},
      {"--ah-tmin", uniform, "ah-tmin", text(-tiny), "0", "must be >= 0"},
      {"--ah-tmax", uniform + " --ah-tmin 1", "ah-tmax", text(down(1.0)), "1",
       "must be >= --ah-tmin"},
  };

  {
    // the shift must act at the horizon: rcut at least 4 max(rah0, M)
    const std::string shift = uniform + " --rahA 0.5 --rah0 1.2";
    const Params p = resolved_evolve(shift);
    const double rcut = 4.0 * std::max(p.rah0, p.M);
    bounds.push_back({"--rah-rcut", shift, "rah-rcut", text(down(rcut)), text(rcut),
                      "must be at least 4 max(rah0, M)"});
  }
  // the limits that depend on the grid and the step, computed as validate() computes them
  for (const std::string& grid : {uniform, boxes3, sinh}) {
    const Steps s = steps_of(grid);
    // a step to take: tmax/dt above 1e-9, at most steps_max steps
    bounds.push_back({"--tmax", grid, "tmax", text(s.dt * 1e-9 * (1 - 1e-6)),
                      text(s.dt * 1e-9 * (1 + 1e-6)), "the run would take no step"});
    bounds.push_back({"--tmax", grid + " --dt-series 1e300 --dt-profiles 1e300", "tmax",
                      text(s.dt * (steps_max + 0.5)), text(s.dt * (steps_max - 0.5)),
                      "would take"});
    // checkpoints between whole steps of the hierarchy
    bounds.push_back({"--checkpoint-every", grid, "checkpoint-every", text(s.dt * (1 - 1e-9)),
                      text(s.dt), "is shorter than the time step"});
    // the horizon found within 1e-3 of the smallest cell
    const double ah_tol = ah_tol_over_spacing_max * s.min_spacing;
    bounds.push_back(
        {"--ah-tol", grid, "ah-tol", text(up(ah_tol)), text(ah_tol), "must be at most"});
    // the Gamma-driver's damping, eta dt_finest at most eta_dt_max (the flag named: --cfl)
    const double eta = eta_dt_max / s.dt_finest;
    bounds.push_back({"--cfl", grid, "eta", text(eta * (1 + 1e-9)), text(eta * (1 - 1e-9)),
                      "RK4 limit of the Gamma-driver damping"});
  }
  {
    // Z4c's constraint damping, kappa1 max(2, 2 + kappa2) dt_finest at most eta_dt_max, named
    // by the flag that makes it too fast; and near the hole (kappa1-hole > kappa1), max(2, 2 +
    // kappa2) min(kappa1_dr_max cfl, kappa1-hole dt_finest)
    const Steps s = steps_of(z4c_uniform);
    const double kappa1 = eta_dt_max / (2.0 * s.dt_finest);
    bounds.push_back({"--kappa1", z4c_uniform + " --kappa1-hole 0", "kappa1",
                      text(kappa1 * (1 + 1e-9)), text(kappa1 * (1 - 1e-9)),
                      "RK4 limit of the constraint damping"});
    const double kappa2 = eta_dt_max / (1.0 * s.dt_finest);
    bounds.push_back({"--kappa2", z4c_uniform + " --kappa1-hole 0 --kappa1 1", "kappa2",
                      text(kappa2 * (1 + 1e-9) - 2.0), text(kappa2 * (1 - 1e-9) - 2.0),
                      "RK4 limit of the constraint damping"});
    const ResolvedParams p = resolved_evolve(z4c_uniform);
    const double near = std::min(Z4cParams::kappa1_dr_max * p.cfl, p.kappa1_hole() * s.dt_finest);
    bounds.push_back({"--kappa2", z4c_uniform, "kappa2", text(eta_dt_max / near * (1 + 1e-9) - 2.0),
                      text(eta_dt_max / near * (1 - 1e-9) - 2.0), "the damping near the hole"});
    // (that refusal names --kappa1-hole where kappa2 <= 0: unreachable, the rate per step is
    // then at most 2 kappa1_dr_max cfl_max)
    CHECK(2.0 * Z4cParams::kappa1_dr_max * cfl_max <= eta_dt_max);
  }
  {
    // the smallest cell, at least min_spacing_over_rmax x rmax: the sinh grid's innermost width
    // (its spacings scale with --dr-inner) and the boxes' finest level
    const std::string base = "--id 1log-trumpet --grid sinh --N 400 --rmax 16";
    const double least = min_spacing_over_rmax * 16.0;
    // bisected in the width (the map is not linear in it), to 1e-9 relative
    double beyond = 1e-10, inside = 1e-8;
    REQUIRE(steps_of(base + " --dr-inner " + text(beyond)).min_spacing < least);
    REQUIRE(steps_of(base + " --dr-inner " + text(inside)).min_spacing >= least);
    while (inside / beyond - 1.0 > 1e-9) {
      const double mid = std::sqrt(beyond * inside);
      (steps_of(base + " --dr-inner " + text(mid)).min_spacing < least ? beyond : inside) = mid;
    }
    bounds.push_back({"--dr-inner", base, "dr-inner", text(beyond), text(inside),
                      "which double precision cannot difference"});
    int levels = 1;
    while (levels < levels_max
           && steps_of(boxes3 + " --levels " + std::to_string(levels + 1)).min_spacing >= least)
      ++levels;
    REQUIRE(levels < levels_max);
    bounds.push_back({"--levels", boxes3, "levels", std::to_string(levels + 1),
                      std::to_string(levels), "which double precision cannot difference"});
  }
  // boxes of too few cells for the order's buffer and transfer stencils: an even --N (odd ones
  // are refused first) below mesh::min_cells; where that lies below --N's minimum of 16 the
  // limit cannot be reached
  for (const int order : {2, 4, 6}) {
    const int least = static_cast<int>(mesh::min_cells(order));
    INFO("--fd-order " << order << ": at least " << least << " cells a box");
    if (least <= 16)
      continue;
    const int beyond = least % 2 == 0 ? least - 2 : least - 1, inside = beyond + 2;
    CHECK(beyond >= 16);
    bounds.push_back(
        {"--N", "--id 1log-trumpet --grid boxes --rmax 16 --fd-order " + std::to_string(order), "N",
         std::to_string(beyond), std::to_string(inside),
         fmt::format("must be at least {} with --grid boxes", least)});
  }

  for (const auto& b : bounds)
    check_bound(b);

  // every flag validate.cpp names or the flag table bounds has a bound row, or no numeric limit
  // (and why)
  std::set<std::string> named = flags_validate_names();
  const std::set<std::string> table_bounds = flags_with_table_bounds();
  CHECK(table_bounds.size() > 25);
  named.insert(table_bounds.begin(), table_bounds.end());
  CHECK(named.size() > 40);
  std::set<std::string> with_row;
  for (const auto& b : bounds) {
    with_row.insert(b.flag);
    INFO(b.flag << " is not named in validate.cpp");
    CHECK(named.count(b.flag) == 1);
  }
  for (const auto& flag : named) {
    INFO(flag << " is named in validate.cpp: give it a bound row, or say why it has no limit");
    CHECK(with_row.count(flag) + no_numeric_limit().count(flag) == 1);
  }
  for (const auto& [flag, why] : no_numeric_limit()) {
    INFO(flag << " (" << why << ") is not named in validate.cpp");
    CHECK(named.count(flag) == 1);
  }
  // a table row's bounds, where they bound (not only finiteness, which the number reader
  // ensures on the command line), each have a row of their own refusal's form
  for (const auto& spec : param_specs()) {
    if (!spec.bounds || (!spec.bounds->lo && !spec.bounds->hi))
      continue;
    const std::string flag = "--" + std::string(spec.name);
    INFO(flag << ": its table bounds have no row here");
    CHECK(std::any_of(bounds.begin(), bounds.end(), [&](const Bound& b) {
      return b.flag == flag
             && (b.why.rfind("must be > ", 0) == 0 || b.why.rfind("must be >= ", 0) == 0
                 || b.why.rfind("must lie in [", 0) == 0);
    }));
  }
}

TEST_CASE("every flag's tolerance is met: the horizon radius with --ah-tol lies within it of a "
          "much tighter search, on the uniform and the default sinh grid") {
  // --ah-tol is the one evolve flag that sets a tolerance (flag_table.cpp). Without the shift the
  // searches change nothing of the evolution, so the two runs search the same states, at every
  // row of horizon.dat.
  const double tight = 1e-14;
  auto radii = [](const std::string& args) {
    const fs::path out = scratch("every_tolerance_out");
    const auto r = run("evolve " + args + " --out " + out.string());
    INFO(args << "\n" << r.err);
    REQUIRE(r.status == 0);
    const auto table = gbssn1d::testing::read_table((out / "horizon.dat").string());
    std::vector<double> r_ah;
    for (std::size_t k = 0; k < table.rows.size(); ++k)
      r_ah.push_back(table.at(k, "r_ah"));
    fs::remove_all(out);
    return r_ah;
  };
  // the uniform grid, the default sinh grid (N 400, rmax 1000, dr-inner 0.02), and its map at
  // 64 cells
  const std::vector<std::string> grids{"--grid uniform --N 64 --rmax 16", "", "--N 64"};
  double loose_worst = 0.0; // at the loosest tolerance: the tolerance reached the finder
  for (const std::string& grid : grids) {
    for (const std::string id : {"1log-trumpet", "maximal-trumpet", "wormhole"}) {
      const std::string base = grid + " --id " + id + " --tmax 1 --dt-series 0.25 --dt-profiles 1";
      const std::vector<double> exact = radii(base + " --ah-tol " + text(tight));
      REQUIRE(exact.size() == 5);
      // the loosest tolerance validate() accepts, and tighter ones
      const double loosest = ah_tol_over_spacing_max * steps_of(base).min_spacing;
      for (const double tol : {loosest, 1e-6, 1e-8, 1e-10}) {
        const std::vector<double> found = radii(base + " --ah-tol " + text(tol));
        REQUIRE(found.size() == exact.size());
        for (std::size_t k = 0; k < exact.size(); ++k) {
          INFO(base << " --ah-tol " << tol << ": row " << k << ", r_ah " << found[k] << " against "
                    << exact[k]);
          REQUIRE(std::isfinite(exact[k]));
          CHECK(std::abs(found[k] - exact[k]) <= tol + tight);
          if (tol == loosest)
            loose_worst = std::max(loose_worst, std::abs(found[k] - exact[k]));
        }
      }
    }
  }
  CHECK(loose_worst > 0.0);
}

} // namespace every_bound_test
