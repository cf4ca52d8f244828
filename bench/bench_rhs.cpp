// Right-hand-side throughput: grid points x RHS evaluations per second, one core.
//
//   build/gbssn1d_bench [--seconds S] [--N 256,1024,4096] [--sections rhs,shift-cost,peak,...]
//                                                               (--help for the options)
//
// Evaluates the full grid RHS (derivatives, upwinding, equations, dissipation, boundary) on
// 1+log-trumpet data on a sinh grid, for N = 256, 1024, 4096, and also one RK4 step's cost;
// for the plain Gamma-driver and with the horizon-adjusting shift (rahA = 0.5, rah0 = 0.89:
// the horizon search on every evaluation and the shift's pass included). --sections shift-cost
// measures that cost paired, in alternating chunks, with and without the search. Also each
// --fd-order, each --upwind pair, each --formulation, and whole runs on nested boxes
// (--sections picks some; --sections peak measures the core's ceilings, machine_ceilings.cpp;
// docs/roofline.md reads them together).
#include "config/params.hpp"
#include "evolution/simulation.hpp"
#include "horizon/apparent_horizon.hpp"
#include "machine_ceilings.hpp"
#include "stencil_windows.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

using namespace gbssn1d;

namespace {

/// 1+log-trumpet data on `grid_flag`'s grid, plain or with the horizon-adjusting shift
/// (rahA = 0.5, rah0 = 0.89), validated as the command line would.
Params trumpet(int n, double rmax, const std::string& grid_flag, bool horizon_shift) {
  Params p;
  p.N = n;
  p.rmax = rmax;
  p.grid = GridChoice::parse(grid_flag);
  p.id = InitialDataKind::onelog_trumpet;
  if (horizon_shift) {
    p.rahA = 0.5;
    p.rah0 = 0.89;
  }
  return p;
}

/// The evolution's configuration of `p`, its defaults resolved and validated as the command
/// line does (ParamError otherwise).
EvolutionConfig validated_config(const Params& p) {
  const ResolvedParams run = resolve(p);
  validate(run);
  return evolution_config(run);
}

/// Full-grid RHS evaluations of `sim`'s state, repeated for at least `seconds` (one RHS with
/// the run's horizon locator, so that the shift's searches count).
/// Each evaluation is timed on its own as well (a clock read costs about 20 ns, 0.1% of an
/// evaluation at N = 1024): `fastest` and `decile` are the least and the 10th-percentile time
/// of one evaluation. On a shared host the run's mean holds the moments when another tenant
/// shares the core; the fastest evaluations are those on a quiet core.
struct RhsTiming {
  long evaluations = 0;
  double seconds = 0.0, fastest = 0.0, decile = 0.0;
};
RhsTiming time_rhs(const Simulation& sim, double seconds) {
  GbssnRhs rhs(sim.rhs());  // a copy: with the run's horizon locator
  State dudt = sim.state(); // its shape (the right-hand side writes every value)
  using clock = std::chrono::steady_clock;
  RhsTiming t;
  std::vector<double> each;
  const auto start = clock::now();
  auto before = start;
  do {
    for (int k = 0; k < 50; ++k) {
      rhs(sim.state(), dudt, 0.0);
      const auto after = clock::now();
      each.push_back(std::chrono::duration<double>(after - before).count());
      before = after;
    }
    t.evaluations += 50;
    t.seconds = std::chrono::duration<double>(before - start).count();
  } while (t.seconds < seconds);
  std::sort(each.begin(), each.end());
  t.fastest = each.front();
  t.decile = each[each.size() / 10];
  return t;
}

/// The cost of the horizon shift, paired: chunks of 20 evaluations of the plain and of the
/// horizon-shift right-hand side, alternating for at least `seconds`, so that both see the same
/// state of a shared host (which drifts by tens of percent within minutes). Returns the
/// ratio of the summed times and the median of the chunks' ratios.
struct PairedRatio {
  double summed = 0.0, median = 0.0;
  long chunks = 0;
  double fastest = 0.0; ///< the fastest chunk of `other` over the fastest of `plain`
};
/// Alternates chunks of 20 calls of `plain` and of `other` for at least `seconds`.
template <class Plain, class Other>
PairedRatio paired_chunks(Plain&& plain, Other&& other, double seconds) {
  using clock = std::chrono::steady_clock;
  const auto chunk = [](auto&& call) {
    const auto start = clock::now();
    for (int k = 0; k < 20; ++k)
      call();
    return std::chrono::duration<double>(clock::now() - start).count();
  };
  double total_plain = 0.0, total_other = 0.0, fastest_plain = 1e300, fastest_other = 1e300;
  std::vector<double> ratios;
  const auto start = clock::now();
  do {
    const double t_plain = chunk(plain);
    const double t_other = chunk(other);
    total_plain += t_plain;
    total_other += t_other;
    fastest_plain = std::min(fastest_plain, t_plain);
    fastest_other = std::min(fastest_other, t_other);
    ratios.push_back(t_other / t_plain);
  } while (std::chrono::duration<double>(clock::now() - start).count() < seconds);
  std::nth_element(ratios.begin(), ratios.begin() + static_cast<long>(ratios.size() / 2),
                   ratios.end());
  return {total_other / total_plain, ratios[ratios.size() / 2], static_cast<long>(ratios.size()),
          fastest_other / fastest_plain};
}

PairedRatio time_shift_cost(const Simulation& plain, const Simulation& shifted, double seconds,
                            bool with_search) {
  // with the runs' horizon locators (the search on every evaluation, as --ah-every substage),
  // or without (the shift's loop and its pass alone: no h_AH, beta_H = 0 by the same loop)
  GbssnRhs rhs_plain = with_search ? plain.rhs() : GbssnRhs(plain.grid(), plain.rhs().params());
  GbssnRhs rhs_shifted =
      with_search ? shifted.rhs() : GbssnRhs(shifted.grid(), shifted.rhs().params());
  State dudt = plain.state(); // its shape (the right-hand side writes every value)
  return paired_chunks([&] { rhs_plain(plain.state(), dudt, 0.0); },
                       [&] { rhs_shifted(shifted.state(), dudt, 0.0); }, seconds);
}

/// The horizon search of one RK substage (find_horizon_near from the last radius, as the
/// single grid's locator calls it) against one plain evaluation, paired.
PairedRatio time_search_cost(const Simulation& plain, const Simulation& shifted,
                             const HorizonFinderParams& finder, double seconds) {
  GbssnRhs rhs_plain(plain.grid(), plain.rhs().params());
  State dudt = plain.state(); // its shape (the right-hand side writes every value)
  const auto first = find_horizon_near(shifted.state(), shifted.grid(), finder, 0.89);
  if (!first)
    throw std::runtime_error("search-cost: no horizon on the benchmark's data");
  const double seed = first->r;
  double sink = 0.0;
  const PairedRatio r = paired_chunks(
      [&] { rhs_plain(plain.state(), dudt, 0.0); },
      [&] { sink += find_horizon_near(shifted.state(), shifted.grid(), finder, seed)->r; },
      seconds);
  if (!(sink > 0.0))
    throw std::runtime_error("search-cost: the search lost the horizon");
  return r;
}

} // namespace

int main(int argc, char** argv) {
  CLI::App app{"gbssn1d RHS throughput: points x RHS evaluations per second on one core, "
               "plain and with the horizon-adjusting shift",
               "gbssn1d_bench"};
  double seconds = 1.0;
  std::vector<int> sizes{256, 1024, 4096};
  app.add_option("--seconds", seconds, "timing per size and shift (s)")
      ->capture_default_str()
      ->check(CLI::Range(0.01, 600.0));
  std::vector<std::string> sections{"rhs",    "shift-cost",  "fd-order",
                                    "upwind", "formulation", "boxes"};
  app.add_option("--sections", sections,
                 "sections to run: rhs (plain and horizon shift, each N), shift-cost (the horizon "
                 "shift's cost against plain, in alternating chunks: a paired ratio), fd-order, "
                 "upwind, "
                 "formulation (on the largest N), boxes (whole runs), peak (the core's "
                 "ceilings: clock, FMA, multiply and division throughput, bandwidth; about 20 s, "
                 "not run by default), stencils (the point loop's stencils alone, as GCC "
                 "vectorises them against explicit SIMD windows: an experiment of "
                 "docs/roofline.md; not run by default)")
      ->delimiter(',')
      ->capture_default_str()
      ->check(CLI::IsMember(
          {"rhs", "shift-cost", "fd-order", "upwind", "formulation", "boxes", "peak", "stencils"}));
  double fma_latency = 4.0;
  app.add_option("--fma-latency", fma_latency,
                 "peak: cycles of one FMA's latency, which turns a chain of them into a clock")
      ->capture_default_str()
      ->check(CLI::Range(1.0, 16.0));
  app.add_option("--N", sizes, "grid sizes")
      ->delimiter(',')
      ->capture_default_str()
      ->check(CLI::Range(16, 10'000'000));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2; // usage errors: exit status 2, as gbssn1d
  }
  const auto wanted = [&](const char* name) {
    return std::find(sections.begin(), sections.end(), name) != sections.end();
  };
  if (wanted("peak"))
    print_machine_ceilings(0.2, fma_latency);
  if (wanted("stencils"))
    print_stencil_windows(seconds);
  if (std::all_of(sections.begin(), sections.end(),
                  [](const std::string& s) { return s == "peak" || s == "stencils"; }))
    return 0;
  fmt::print("# gbssn1d {} RHS benchmark (1+log trumpet, sinh grid rmax = 100 M)\n",
             GBSSN1D_VERSION);
  if (wanted("rhs")) {
    fmt::print("# shift N evaluations seconds points_x_rhs_per_s ns_per_point rk4_steps_per_s "
               "fastest_ns_per_point decile_ns_per_point (of single evaluations)\n");
    for (const bool horizon_shift : {false, true})
      for (int n : sizes) {
        Params p = trumpet(n, 100.0, "sinh", horizon_shift);
        p.dr_inner = 0.01; // one sinh map for every N (innermost 0.01 M at N = 400)
        p.tmax = 0.0;
        Simulation sim(validated_config(p));
        const RhsTiming timing = time_rhs(sim, seconds);
        const long evals = timing.evaluations;
        const double elapsed = timing.seconds;
        const double rate = static_cast<double>(evals) * n / elapsed;
        using clock = std::chrono::steady_clock;

        long steps = 0;
        const auto start_steps = clock::now();
        double elapsed_steps = 0;
        do {
          for (int k = 0; k < 10; ++k)
            sim.step(1e-6);
          steps += 10;
          elapsed_steps = std::chrono::duration<double>(clock::now() - start_steps).count();
        } while (elapsed_steps < 0.5 * seconds);
        fmt::print("{} {} {} {:.3f} {:.4e} {:.2f} {:.1f} {:.2f} {:.2f}\n",
                   horizon_shift ? "horizon" : "plain", n, evals, elapsed, rate, 1e9 / rate,
                   steps / elapsed_steps, 1e9 * timing.fastest / n, 1e9 * timing.decile / n);
      }
  }
  // The horizon shift's cost per evaluation against plain (issue: at most 1.1 times), paired
  if (wanted("shift-cost")) {
    fmt::print("# shift-cost: horizon / plain time per evaluation, alternating chunks of 20\n");
    fmt::print(
        "# what N chunks summed_ratio median_chunk_ratio fastest_chunk_ratio (the fastest "
        "chunk of each, a quiet core; loop: the shift's point loop "
        "and its pass, no search; with-search: the search on every evaluation too; search: one "
        "substage's horizon search alone against a plain evaluation)\n");
    for (int n : sizes) {
      const auto config = [n](bool horizon_shift) {
        Params p = trumpet(n, 100.0, "sinh", horizon_shift);
        p.dr_inner = 0.01;
        p.tmax = 0.0;
        return validated_config(p);
      };
      const EvolutionConfig shifted_config = config(true);
      const Simulation plain(config(false)), shifted(shifted_config);
      for (const bool with_search : {false, true}) {
        const PairedRatio r = time_shift_cost(plain, shifted, seconds, with_search);
        fmt::print("{} {} {} {:.4f} {:.4f} {:.4f}\n", with_search ? "with-search" : "loop", n,
                   r.chunks, r.summed, r.median, r.fastest);
      }
      const PairedRatio r =
          time_search_cost(plain, shifted, shifted_config.horizon_search.finder, seconds);
      fmt::print("search {} {} {:.4f} {:.4f} {:.4f}\n", n, r.chunks, r.summed, r.median, r.fastest);
    }
  }
  // Every finite-difference order (--fd-order), plain Gamma-driver, on the largest size: the
  // wider stencils' cost per point.
  if (wanted("fd-order")) {
    fmt::print("# --fd-order: plain shift, N = {}\n", sizes.back());
    fmt::print("# fd_order N evaluations seconds points_x_rhs_per_s ns_per_point "
               "fastest_ns_per_point decile_ns_per_point\n");
    for (const int order : {2, 4, 6, 8}) {
      const int n = sizes.back();
      Params p = trumpet(n, 100.0, "sinh", false);
      p.dr_inner = 0.01;
      p.tmax = 0.0;
      p.fd_order = order;
      Simulation sim(validated_config(p));
      const RhsTiming t = time_rhs(sim, seconds);
      const double rate = static_cast<double>(t.evaluations) * n / t.seconds;
      fmt::print("{} {} {} {:.3f} {:.4e} {:.2f} {:.2f} {:.2f}\n", order, n, t.evaluations,
                 t.seconds, rate, 1e9 / rate, 1e9 * t.fastest / n, 1e9 * t.decile / n);
    }
  }
  // The upwind pairs (--upwind), plain and with the horizon shift, on the largest size.
  if (wanted("upwind")) {
    fmt::print("# --upwind: N = {}\n", sizes.back());
    fmt::print("# upwind shift N evaluations seconds points_x_rhs_per_s ns_per_point "
               "fastest_ns_per_point decile_ns_per_point\n");
    for (const bool horizon_shift : {false, true})
      for (const char* upwind : {"lopsided", "biased"}) {
        const int n = sizes.back();
        Params p = trumpet(n, 100.0, "sinh", horizon_shift);
        p.dr_inner = 0.01;
        p.tmax = 0.0;
        p.upwind = UpwindChoice::parse(upwind);
        Simulation sim(validated_config(p));
        const RhsTiming t = time_rhs(sim, seconds);
        const double rate = static_cast<double>(t.evaluations) * n / t.seconds;
        fmt::print("{} {} {} {} {:.3f} {:.4e} {:.2f} {:.2f} {:.2f}\n", upwind,
                   horizon_shift ? "horizon" : "plain", n, t.evaluations, t.seconds, rate,
                   1e9 / rate, 1e9 * t.fastest / n, 1e9 * t.decile / n);
      }
  }
  if (wanted("formulation")) {
    // The formulations (--formulation): Z4c evolves Theta besides, plain and with the horizon
    // shift, on the largest size.
    fmt::print("# --formulation: N = {}\n", sizes.back());
    fmt::print("# formulation shift N evaluations seconds points_x_rhs_per_s ns_per_point "
               "fastest_ns_per_point decile_ns_per_point\n");
    for (const bool horizon_shift : {false, true})
      for (const char* formulation : {"bssn", "z4c"}) {
        const int n = sizes.back();
        Params p = trumpet(n, 100.0, "sinh", horizon_shift);
        p.dr_inner = 0.01;
        p.tmax = 0.0;
        p.formulation = FormulationChoice::parse(formulation);
        Simulation sim(validated_config(p));
        const RhsTiming t = time_rhs(sim, seconds);
        const double rate = static_cast<double>(t.evaluations) * n / t.seconds;
        fmt::print("{} {} {} {} {:.3f} {:.4e} {:.2f} {:.2f} {:.2f}\n", formulation,
                   horizon_shift ? "horizon" : "plain", n, t.evaluations, t.seconds, rate,
                   1e9 / rate, 1e9 * t.fastest / n, 1e9 * t.decile / n);
      }
  }
  if (wanted("boxes")) {
    // Nested boxes: whole runs of the hierarchy to 100 M (every level, subcycled, with
    // prolongation, restriction, stage-value time interpolation, the horizon searches and the
    // output-free diagnostics), counted as cells x RHS evaluations of all levels (the cells
    // under a child box, which a parent's point loop skips, included: the hierarchy's rate,
    // comparable with the counts before that skip).
    fmt::print("# boxes: 9 levels to rmax 1024 M, N cells each, a run to t = 100 M\n");
    fmt::print("# shift N hierarchy_steps seconds points_x_rhs_per_s hierarchy_steps_per_s\n");
    for (const bool horizon_shift : {false, true})
      for (int n : {32, 64, 128}) {
        Params p = trumpet(n, 1024.0, "boxes", horizon_shift);
        p.levels = 9;
        p.tmax = 100.0;
        Simulation sim(validated_config(p));
        using clock = std::chrono::steady_clock;
        const auto start = clock::now();
        sim.run(nullptr);
        const double elapsed = std::chrono::duration<double>(clock::now() - start).count();
        const double points = static_cast<double>(sim.point_evaluations());
        const long steps = sim.schedule().n_steps;
        fmt::print("{} {} {} {:.3f} {:.4e} {:.1f}\n", horizon_shift ? "horizon" : "plain", n, steps,
                   elapsed, points / elapsed, static_cast<double>(steps) / elapsed);
      }
  }
}
