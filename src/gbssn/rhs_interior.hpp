// GbssnRhs::interior_of: the point loop of one formulation, order and upwind pair, with the
// horizon shift's forms. Included only by the files that compile a formulation's instances
// (rhs_bssn.cpp, rhs_biased.cpp, rhs_z4c.cpp), each with its formulation's PointEquations;
// everything else sees the declaration in gbssn/rhs.hpp.
#pragma once

#include "gbssn/matter.hpp"
#include "gbssn/rhs_loop.hpp" // IWYU pragma: keep (GbssnRhs::interior, the point loop)

#include <stdexcept>

namespace gbssn1d {

template <Formulation f, int p, fd::Upwind upwind>
void GbssnRhs::interior_of(const State& u, State& dudt) const {
  if constexpr (!PointEquations<f>::offers(p, upwind)) {
    // no point loop compiled: validate() refuses the combination
    static_cast<void>(u);
    static_cast<void>(dudt);
    throw std::logic_error("a formulation at an --fd-order or --upwind it is not offered with "
                           "(rejected by validate)");
  } else {
    interior_offered<f, p, upwind>(u, dudt);
  }
}

template <Formulation f, int p, fd::Upwind upwind>
void GbssnRhs::interior_offered(const State& u, State& dudt) const {
  using Equations = typename PointEquations<f>::type;
  const Equations equations = PointEquations<f>::make(params_);
  const HorizonShiftParams& hs = params_.horizon_shift;
  using V = HorizonShiftParams::Variant;
  if (params_.matter == Matter::scalar) {
    // the scalar field at the default stencil (4th order, the lopsided pair), with or without
    // the horizon shift, no study variant (validate() refuses the rest)
    if constexpr (p == 4 && upwind == fd::Upwind::lopsided) {
      if (!hs.active())
        interior<Equations, ScalarField, p, upwind, false>(equations, u, dudt);
      else if (hs.variant == V::consistent)
        interior<Equations, ScalarField, p, upwind, true>(equations, u, dudt);
      else
        throw std::logic_error("a study --rah-variant with --matter scalar (rejected by "
                               "validate)");
    } else {
      throw std::logic_error("--matter scalar at an --fd-order or --upwind other than 4 and "
                             "lopsided (rejected by validate)");
    }
  } else if (!hs.active()) {
    interior<Equations, Vacuum, p, upwind, false>(equations, u, dudt);
  } else if (hs.variant == V::consistent) {
    interior<Equations, Vacuum, p, upwind, true>(equations, u, dudt);
  } else if constexpr (PointEquations<f>::study_variants && upwind == fd::Upwind::lopsided
                       && p == 4) {
    // the published study's formulation, order and stencil only (validate() rejects the rest)
    interior_study_variant(u, dudt);
  } else {
    throw std::logic_error("a study --rah-variant with another formulation, --upwind or "
                           "--fd-order than BSSN's lopsided 4th order (rejected by validate)");
  }
}

/// The explicit instances of formulation F with the upwind pair U at every order, for a
/// formulation's source file.
#define GBSSN1D_INTERIOR_INSTANCES(F, U)                                                           \
  template void GbssnRhs::interior_of<F, 2, U>(const State&, State&) const;                        \
  template void GbssnRhs::interior_of<F, 4, U>(const State&, State&) const;                        \
  template void GbssnRhs::interior_of<F, 6, U>(const State&, State&) const;                        \
  template void GbssnRhs::interior_of<F, 8, U>(const State&, State&) const

} // namespace gbssn1d
