// The point loop's instances of BSSN with the Eulerian volume choice (gbssn/bssn_eulerian.hpp):
// every order, both upwind pairs, with and without the horizon shift.
#include "gbssn/bssn_eulerian.hpp" // IWYU pragma: keep (PointEquations<bssn_eulerian>)
#include "gbssn/rhs_interior.hpp"

namespace gbssn1d {

GBSSN1D_INTERIOR_INSTANCES(Formulation::bssn_eulerian, fd::Upwind::lopsided);
GBSSN1D_INTERIOR_INSTANCES(Formulation::bssn_eulerian, fd::Upwind::biased);

} // namespace gbssn1d
