// Run-time choices made compile-time constants, each in one place: the finite-difference order
// (--fd-order), the upwind pair (--upwind) and the formulation (the state's tag). Each helper
// calls fn.template operator()<value>() with the value chosen, once per call of a loop over
// points, so that every combination is its own instance and no point sees a switch.
#pragma once

#include "core/formulation.hpp"
#include "fd/stencils.hpp"

namespace gbssn1d {

/// fn<order>() for --fd-order 2, 4, 6 or 8 (4 for anything else: validate() refuses it first).
template <class Fn>
decltype(auto) with_order(int order, Fn&& fn) {
  switch (order) {
  case 2:
    return fn.template operator()<2>();
  case 6:
    return fn.template operator()<6>();
  case 8:
    return fn.template operator()<8>();
  default:
    return fn.template operator()<4>();
  }
}

/// fn<upwind>() for the upwind pair.
template <class Fn>
decltype(auto) with_upwind(fd::Upwind upwind, Fn&& fn) {
  if (upwind == fd::Upwind::biased)
    return fn.template operator()<fd::Upwind::biased>();
  return fn.template operator()<fd::Upwind::lopsided>();
}

/// fn<matter>() for each matter model of core/formulation.hpp.
template <class Fn>
decltype(auto) with_matter(Matter matter, Fn&& fn) {
  if (matter == Matter::scalar)
    return fn.template operator()<Matter::scalar>();
  return fn.template operator()<Matter::none>();
}

/// fn<formulation>() for each formulation of core/formulation.hpp.
template <class Fn>
decltype(auto) with_formulation(Formulation formulation, Fn&& fn) {
  switch (formulation) {
  case Formulation::z4c:
    return fn.template operator()<Formulation::z4c>();
  case Formulation::bssn_eulerian:
    return fn.template operator()<Formulation::bssn_eulerian>();
  case Formulation::bssn:
    break;
  }
  return fn.template operator()<Formulation::bssn>();
}

} // namespace gbssn1d
