// The BSSN point loop's instances with the lopsided upwind pair (the default), the study's
// horizon-shift variants among them (gbssn/rhs_interior.hpp); the biased pair's are in
// rhs_biased.cpp.
#include "gbssn/rhs_bssn_equations.hpp" // IWYU pragma: keep (PointEquations<bssn>, for the instances)
#include "gbssn/rhs_interior.hpp"

namespace gbssn1d {

GBSSN1D_INTERIOR_INSTANCES(Formulation::bssn, fd::Upwind::lopsided);

} // namespace gbssn1d
