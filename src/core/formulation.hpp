// Which evolution equations: a parameter that configurations name without the table of
// variables (core/registry.hpp says which variables each formulation evolves).
#pragma once

namespace gbssn1d {

/// BSSN (equations document, Sec. 2-3; Brown's Lagrangian volume choice), Z4c with constraint
/// damping (Sec. 17), which evolves Theta besides, and K-hat = K - 2 Theta in K's place, or
/// BSSN with Brown's Eulerian volume choice (Sec. 18; --gbssn-volume eulerian).
enum class Formulation { bssn, z4c, bssn_eulerian };

/// Brown's volume choice (Brown 2009), sigma in d_t gbar_ij = L_beta gbar_ij - (2/3) sigma
/// gbar_ij Dbar_k beta^k - 2 alpha Abar_ij: Lagrangian (sigma = 1, d_t det(gbar) = 0 along the
/// normal and the shift; Sec. 2.2) or Eulerian (sigma = 0, Sec. 18). The terms sigma weights
/// are (C1)'s and (E2)-(E3)'s -(2/3) Dbar.beta parts and (E6)'s (2/3) Delta_gamma^r Dbar.beta +
/// (1/(3a)) (Dbar.beta)'; the Eulerian choice leaves them out (gbssn/equations.hpp).
enum class Volume { eulerian, lagrangian };

/// The matter a run evolves besides the geometry: none (vacuum), or a massless scalar field
/// (equations document, Sec. 19; --matter scalar).
enum class Matter { none, scalar };

} // namespace gbssn1d
