// The horizon shift's study variants (--rah-variant no-shift-derivatives,
// no-shift-second-derivatives, delta-rhs-from-gd, driver-full-shift; docs/horizon-shift-study.md
// Sec. 2): deliberately inconsistent discretisations of BSSN with the horizon shift, each a
// formulation policy wrapping Bssn's equations, compiled here alone and only for the published
// study's order and stencil (4th order, lopsided pair), so that the production loop carries no
// variant and a change to it compiles these four instances only here.
#include "gbssn/rhs_bssn_equations.hpp" // IWYU pragma: keep (Bssn's equations)
#include "gbssn/rhs_loop.hpp"           // IWYU pragma: keep (GbssnRhs::interior, the point loop)

#include <stdexcept>

namespace gbssn1d {

namespace {

using Variant = HorizonShiftParams::Variant;

/// Bssn's right-hand side with the variant's inconsistency: the shift's derivatives or B's
/// driver taken from the wrong part of the shift (beta_GD for the full shift or the reverse).
template <Variant variant>
struct BssnStudyVariant {
  static constexpr Formulation formulation = Formulation::bssn;
  template <class M>
  [[gnu::always_inline]] Rhs rhs(PointData p, const Gauge& gauge, Shift gd) const {
    static_assert(M::matter == Matter::none, "the study's variants are of vacuum BSSN");
    if constexpr (variant == Variant::no_shift_derivatives) {
      p.d[Var::beta] = gd.d_beta; // the full shift's value, but beta_GD's derivatives
      p.dd[Var::beta] = gd.dd_beta;
    } else if constexpr (variant == Variant::no_shift_second_derivatives) {
      p.dd[Var::beta] = gd.dd_beta;
    } else if constexpr (variant == Variant::driver_full_shift) {
      gd = full_shift(p);
    }
    Rhs rhs = gbssn_rhs(p, gauge, gd);
    if constexpr (variant == Variant::delta_rhs_from_gd)
      rhs[Var::Delta_r] = gbssn1d::rhs_Delta_r(p, metric_pieces(p), gd);
    return rhs;
  }
};

} // namespace

void GbssnRhs::interior_study_variant(const State& u, State& dudt) const {
  constexpr fd::Upwind lopsided = fd::Upwind::lopsided;
  switch (params_.horizon_shift.variant) { // dispatched once per call, not per point
  case Variant::no_shift_derivatives:
    return interior<BssnStudyVariant<Variant::no_shift_derivatives>, Vacuum, 4, lopsided, true>(
        {}, u, dudt);
  case Variant::no_shift_second_derivatives:
    return interior<BssnStudyVariant<Variant::no_shift_second_derivatives>, Vacuum, 4, lopsided,
                    true>({}, u, dudt);
  case Variant::delta_rhs_from_gd:
    return interior<BssnStudyVariant<Variant::delta_rhs_from_gd>, Vacuum, 4, lopsided, true>({}, u,
                                                                                             dudt);
  case Variant::driver_full_shift:
    return interior<BssnStudyVariant<Variant::driver_full_shift>, Vacuum, 4, lopsided, true>({}, u,
                                                                                             dudt);
  case Variant::consistent:
    break;
  }
  throw std::logic_error("the consistent horizon shift is no study variant");
}

} // namespace gbssn1d
