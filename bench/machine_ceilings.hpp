// The core's ceilings for the roofline of the right-hand side (machine_ceilings.cpp,
// docs/roofline.md): printed by `gbssn1d_bench --sections peak`.
#pragma once

/// Prints the clock (a dependent FMA chain of `fma_latency` cycles per FMA), FMA, multiply and
/// division throughput at 1, 4 and 8 lanes, and read and triad bandwidth for arrays that fit
/// L1, L2, L3 and none of them (about `seconds` each), best of 15 repetitions, on one core.
void print_machine_ceilings(double seconds, double fma_latency);
