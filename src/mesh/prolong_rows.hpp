// The row kernels of box-in-box refinement: a fine box's cells filled with the prolongation of
// a weighted combination of its parent's arrays (RK stage values, time interpolation), row by
// row and fused, bit for bit the combination prolonged (mesh/hierarchy.hpp steps with them).
#pragma once

#include "gbssn/state.hpp"
#include "grid/grid.hpp"

#include <cmath>
#include <span>

namespace gbssn1d::mesh {

/// One term of prolong_combination's sums, sum + w x: fused, one rounding, where the target has
/// FMA, written out so that the sums do not depend on whether the compiler contracts them (GCC
/// contracts a * b + c only from -O2: the optimised and the -O1 sanitizer builds rounded
/// differently, and a test's own loop could not follow both); sum + w x elsewhere.
inline double combination_term(double sum, double w, double x) {
#ifdef __FP_FAST_FMA
  return std::fma(w, x, sum);
#else
  return sum + w * x;
#endif
}

/// The fine level's interior cells [j_begin, N + n_ghost) (its outer ghosts included), every
/// row: the prolongation (transfer.hpp's prolong) of the parent's sum_m weights[m] arrays[m]
/// (1, 2, 3 or 5 arrays, summed in the order m = 0, 1, ..., each term by combination_term). Away
/// from the origin the sums stay in a local array; near it (a coarse cell read below 0) they go
/// through `scratch` and prolong_field's mirror. The same bits either way.
void prolong_combination(std::span<const State* const> arrays, std::span<const double> weights,
                         const Grid& coarse_grid, State& fine, const Grid& fine_grid, long j_begin,
                         State& scratch);

} // namespace gbssn1d::mesh
