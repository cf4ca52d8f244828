// BSSN's equations as the point loop takes them (GbssnRhs::interior_of), for the two files
// that compile its instances (rhs_bssn.cpp, rhs_biased.cpp).
#pragma once

#include "gbssn/equations.hpp"
#include "gbssn/rhs.hpp"

namespace gbssn1d {

template <>
struct PointEquations<Formulation::bssn> {
  using type = Bssn;
  static Bssn make(const RhsParams&) { return {}; }
  static constexpr bool study_variants = true; ///< the published study's formulation
  static constexpr bool offers(int, fd::Upwind) { return true; }
};

} // namespace gbssn1d
