// An experiment for the roofline of the right-hand side (docs/roofline.md, Sec. 3): the point
// loop's stencils alone, as GCC vectorises them from the point-wise code, against explicit SIMD
// windows. Printed by `gbssn1d_bench --sections stencils`.
#pragma once

/// Times, in alternating chunks for about `seconds`, the stencils of the 4th-order point loop's
/// gather (gbssn/rhs_loop.hpp: d1, d2, the 6th difference, the lopsided upwind sum and the
/// advection and dissipation terms built from them) for 9 fields on staged blocks of 256 points:
/// once as the point loop computes them (a scalar loop GCC vectorises, each neighbour a load of
/// its own), and once with explicit vectors of 4 and of 8 doubles, each field's neighbours
/// formed in registers from three aligned loads; also from the pairs f[k] +/- f[-k], and with
/// each stencil in two partial sums (shorter dependent chains: docs/roofline.md, Sec. 7). Prints
/// ns per point of each, their paired ratios, and the largest difference between the versions'
/// results.
void print_stencil_windows(double seconds);
