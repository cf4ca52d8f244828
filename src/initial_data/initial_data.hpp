// Initial data for one Schwarzschild black hole of mass M (equations document, Sec. 9, 13).
#pragma once

#include "gbssn/state.hpp"
#include "grid/grid.hpp"
#include "initial_data/initial_data_params.hpp"

namespace gbssn1d {

/// The state on every point of the grid (ghosts included).
///  wormhole:        isotropic puncture psi = 1 + M/(2r), chi = psi^-4, a = b = 1,
///                   K = A_a = Delta^r = beta = B = 0, alpha = 1 or psi^-2;
///  maximal-trumpet: Baumgarte-Naculich analytic trumpet with its lapse and shift (Sec. 9.5);
///  1log-trumpet:    stationary 1+log trumpet with its lapse and shift, B = 0 (Sec. 13);
///  flat:            Minkowski space, alpha = 1, every other field at its value at infinity;
/// with the variables of `fields` (Z4c: Theta = 0, K-hat = K). With the scalar field (flat or
/// wormhole data): its time-symmetric pulse, params.scalar, with the conformal factor the
/// Hamiltonian constraint gives (initial_data/scalar_pulse.hpp).
State initial_data(const Grid& grid, const InitialDataParams& params, Fields fields);

/// The ADM mass of those data: M for a black hole's, 0 for flat space's, and with the scalar
/// field M (0 on flat space) plus the field's, -2 lim r^2 psi' of the conformal factor solved
/// from the Hamiltonian constraint.
double adm_mass(const InitialDataParams& params, Fields fields);

} // namespace gbssn1d
