// The BSSN point loop's instances with the biased upwind pair (--upwind biased), compiled apart
// from the lopsided ones (rhs_bssn.cpp) so that the two build in parallel (each instance is a
// copy of the point loop; under the sanitizers one such file took 3 minutes to compile).
#include "gbssn/rhs_bssn_equations.hpp" // IWYU pragma: keep (PointEquations<bssn>, for the instances)
#include "gbssn/rhs_interior.hpp"

namespace gbssn1d {

GBSSN1D_INTERIOR_INSTANCES(Formulation::bssn, fd::Upwind::biased);

} // namespace gbssn1d
