// The point loop's instances with the biased upwind pair (--upwind biased), compiled apart from
// rhs.cpp's lopsided ones so that the two build in parallel (each instance is a copy of the
// point loop; under the sanitizers one such file took 3 minutes to compile).
#include "gbssn/rhs_loop.hpp" // IWYU pragma: keep (the biased pair's instances of its templates)

namespace gbssn1d {

template void GbssnRhs::evaluate_with<fd::Upwind::biased>(const State&, State&, double);

} // namespace gbssn1d
