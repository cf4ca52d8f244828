// The point loop's Z4c instances (gbssn/z4c.hpp), compiled apart from BSSN's (rhs_bssn.cpp,
// rhs_biased.cpp) so that they build in parallel and a change to BSSN's loop alone does not
// rebuild them: every order, both upwind pairs, with and without the horizon shift.
#include "gbssn/rhs_interior.hpp"
#include "gbssn/z4c.hpp"

namespace gbssn1d {

template <>
struct PointEquations<Formulation::z4c> {
  using type = Z4c;
  static Z4c make(const RhsParams& params) { return Z4c(params.z4c); }
  static constexpr bool study_variants = false; ///< the study's variants are BSSN's
  static constexpr bool offers(int, fd::Upwind) { return true; }
};

GBSSN1D_INTERIOR_INSTANCES(Formulation::z4c, fd::Upwind::lopsided);
GBSSN1D_INTERIOR_INSTANCES(Formulation::z4c, fd::Upwind::biased);

} // namespace gbssn1d
