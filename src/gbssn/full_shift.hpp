// The full shift beta_GD + beta_H (H3) on a row of points, as the right-hand side's point loop
// stages it block by block (gbssn/rhs_loop.hpp). Declared apart from gbssn/horizon_shift.hpp,
// whose profiles, normals and taper the point loop's files then do not depend on.
#pragma once

#include "gbssn/horizon_shift_params.hpp"

#include <cstddef>

namespace gbssn1d {

/// beta_full = beta_GD + beta_H on n points, beta_H = f amplitude s^r as horizon_shift_on's
/// (gbssn/horizon_shift.hpp), in one pass.
void full_shift_on(ShiftNormal normal, std::size_t n, const double* f, const double* chi,
                   const double* a, double amplitude, double chi_smooth, const double* beta_GD,
                   double* beta_full);

} // namespace gbssn1d
