// The point loop's Z4c instances (gbssn/z4c.hpp), compiled apart from BSSN's (rhs.cpp,
// rhs_biased.cpp) so that the three build in parallel and a change to BSSN's loop alone does
// not rebuild them: every order, both upwind pairs, with and without the horizon shift.
#include "gbssn/rhs_loop.hpp" // IWYU pragma: keep (Z4c's instances of its templates)
#include "gbssn/z4c.hpp"

namespace gbssn1d {

template <int p, fd::Upwind upwind>
void GbssnRhs::interior_z4c(const State& u, State& dudt) const {
  const Z4c z4c(params_.z4c);
  if (!params_.horizon_shift.active())
    interior<Z4c, p, upwind, false>(z4c, u, dudt);
  else
    interior<Z4c, p, upwind, true, HorizonShiftParams::Variant::consistent>(z4c, u, dudt);
}

template void GbssnRhs::interior_z4c<2, fd::Upwind::lopsided>(const State&, State&) const;
template void GbssnRhs::interior_z4c<4, fd::Upwind::lopsided>(const State&, State&) const;
template void GbssnRhs::interior_z4c<6, fd::Upwind::lopsided>(const State&, State&) const;
template void GbssnRhs::interior_z4c<8, fd::Upwind::lopsided>(const State&, State&) const;
template void GbssnRhs::interior_z4c<2, fd::Upwind::biased>(const State&, State&) const;
template void GbssnRhs::interior_z4c<4, fd::Upwind::biased>(const State&, State&) const;
template void GbssnRhs::interior_z4c<6, fd::Upwind::biased>(const State&, State&) const;
template void GbssnRhs::interior_z4c<8, fd::Upwind::biased>(const State&, State&) const;

} // namespace gbssn1d
