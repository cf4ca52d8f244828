// A user's own experiment in a few lines, on the library gbssn1d_core (docs/design.md): how fast
// does the horizon-adjusting shift move a 1+log trumpet's horizon from r = 0.83 M to h = 1.2 M,
// for three strengths A? The parameters are set as the command line sets them (defaults
// resolved, then validated), the run is stepped without output files, and the horizon is read
// at every series time. Built as gbssn1d_example; run: build/gbssn1d_example [tmax].
#include "config/params.hpp"
#include "evolution/simulation.hpp"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <limits>

int main(int argc, char** argv) {
  using namespace gbssn1d;
  const double tmax = argc > 1 ? std::atof(argv[1]) : 20.0;
  std::printf("# A t r_AH M_AH\n");
  try {
    for (const double A : {0.25, 0.5, 1.0}) {
      Params p; // every default of `gbssn1d evolve`
      p.id = InitialDataKind::onelog_trumpet;
      p.grid = RadialGrid::sinh;
      p.N = 400;
      p.rmax = 64.0;
      p.tmax = tmax;
      p.dt_series = 1.0;
      p.rahA = A;
      p.rah0 = 1.2;
      const ResolvedParams run = resolve(p); // the defaults that are rules (eta = 2/M, ...)
      validate(run); // throws ParamError naming the flag, as the command line would
      Simulation sim(evolution_config(run));
      sim.on_series = [A](Simulation& s) { // at t = 0 and every dt_series
        const auto horizon = s.horizons().horizon();
        const double none = std::numeric_limits<double>::quiet_NaN();
        std::printf("%g %g %.10g %.10g\n", A, s.time(), horizon ? horizon->r : none,
                    horizon ? horizon->mass : none);
      };
      sim.run(nullptr);    // no files: the numbers above are the experiment's output
      std::printf("\n\n"); // a gnuplot block per strength
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "own_experiment: %s\n", e.what());
    return 1;
  }
  return 0;
}
