// Right-hand-side throughput: grid points x RHS evaluations per second, one core.
//
//   build/gbssn1d_bench [seconds-per-size]
//
// Evaluates the full grid RHS (derivatives, upwinding, equations, dissipation, boundary) on
// 1+log-trumpet data on a sinh grid, for N = 256, 1024, 4096, and also one RK4 step's cost;
// for the plain Gamma-driver and with the horizon-adjusting shift (rahA = 0.5, rah0 = 0.89:
// the horizon search on every evaluation and the split shift included).
#include "cli/params.hpp"
#include "evolution/simulation.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cstdlib>

using namespace gbssn1d;

int main(int argc, char** argv) {
  const double seconds = argc > 1 ? std::atof(argv[1]) : 1.0;
  fmt::print("# gbssn1d {} RHS benchmark (1+log trumpet, sinh grid rmax = 100 M)\n",
             GBSSN1D_VERSION);
  fmt::print("# shift N evaluations seconds points_x_rhs_per_s ns_per_point rk4_steps_per_s\n");
  for (const bool horizon_shift : {false, true})
    for (int n : {256, 1024, 4096}) {
      Params p;
      p.N = n;
      p.rmax = 100.0;
      p.grid = "sinh";
      p.dr_inner = 4.0 / n;
      p.id = "1log-trumpet";
      p.tmax = 0.0;
      if (horizon_shift) {
        p.rahA = 0.5;
        p.rah0 = 0.89;
      }
      resolve_defaults(p);
      validate(p);
      Simulation sim(p);
      GbssnRhs rhs(sim.grid(), rhs_params(p));
      State dudt(sim.state().size());
      using clock = std::chrono::steady_clock;
      long evals = 0;
      const auto start = clock::now();
      double elapsed = 0;
      do {
        for (int k = 0; k < 50; ++k)
          rhs(sim.state(), dudt, 0.0);
        evals += 50;
        elapsed = std::chrono::duration<double>(clock::now() - start).count();
      } while (elapsed < seconds);
      const double rate = static_cast<double>(evals) * n / elapsed;

      long steps = 0;
      const auto start_steps = clock::now();
      double elapsed_steps = 0;
      do {
        for (int k = 0; k < 10; ++k)
          sim.step(1e-6);
        steps += 10;
        elapsed_steps = std::chrono::duration<double>(clock::now() - start_steps).count();
      } while (elapsed_steps < 0.5 * seconds);
      fmt::print("{} {} {} {:.3f} {:.4e} {:.2f} {:.1f}\n", horizon_shift ? "horizon" : "plain", n,
                 evals, elapsed, rate, 1e9 / rate, steps / elapsed_steps);
    }
}
