// A run's end as evolve and resume report it (cli/evolve_command.cpp, cli/resume_command.cpp).
#pragma once

#include "config/params.hpp"
#include "evolution/simulation.hpp"
#include "io/output.hpp"

namespace gbssn1d {

/// Runs `sim` into `out`; says how it ended on stderr and in timeseries.dat; returns the exit
/// status (0, 3 stopped, 128 + n interrupted by signal n, 1 a failed write).
int run_and_report(Simulation& sim, Output& out, const Params& p);

} // namespace gbssn1d
