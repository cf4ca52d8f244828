// Simulations in tests, configured as the command line configures them: parameters with their
// defaults resolved and validated, converted into the evolution's typed configuration.
#pragma once

#include "config/params.hpp"
#include "evolution/simulation.hpp"

namespace gbssn1d::testing {

/// A small, fast 1+log trumpet: `n` cells of a uniform grid out to r = `rmax` (M = 1; every
/// other parameter its default, tmax and dt_series among them). A test sets what else it needs.
inline Params small_trumpet_params(int n, double rmax) {
  Params p;
  p.id = InitialDataKind::onelog_trumpet;
  p.grid = RadialGrid::uniform;
  p.N = n;
  p.rmax = rmax;
  return p;
}

/// `p` with its defaults resolved; throws ParamError as the command line would.
inline ResolvedParams validated(const Params& p) {
  ResolvedParams r = resolve(p);
  validate(r);
  return r;
}

/// The simulation of the parameters `p` (validated first).
inline Simulation simulation(const Params& p) {
  return Simulation(evolution_config(validated(p)));
}

} // namespace gbssn1d::testing
