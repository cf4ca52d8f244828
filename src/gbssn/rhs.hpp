// The right-hand side on the whole grid (method of lines):
//  - interior points: 4th-order centred derivatives (chain rule through the radial map),
//    4th-order lopsided derivatives for the beta d_r advection terms, the point-wise equations
//    of gbssn/equations.hpp, plus Kreiss-Oliger dissipation;
//  - outer ghost cells: Sommerfeld condition (Sec. 8) with one-sided derivatives, toward each
//    variable's asymptotic value from the registry;
//  - ghost cells at the origin: the mirror's right-hand side times the parity, so that every
//    Runge-Kutta stage stays parity-consistent.
#pragma once

#include "gbssn/equations.hpp"
#include "gbssn/state.hpp"
#include "grid/grid.hpp"

#include <cstdint>

namespace gbssn1d {

struct RhsParams {
  GaugeParams gauge;
  double ko_sigma = 0.1; ///< Kreiss-Oliger strength (0 switches dissipation off)
};

/// Fields, derivatives and advection terms at grid point i (needs i - 3 ... i + 3).
PointData point_data(const State& u, const Grid& grid, std::size_t i);

class GbssnRhs {
public:
  GbssnRhs(const Grid& grid, RhsParams params);

  /// d u / dt at time t; the signature Boost.Odeint expects of a system.
  void operator()(const State& u, State& dudt, double t);

  const Grid& grid() const { return *grid_; }
  const RhsParams& params() const { return params_; }
  std::uint64_t evaluations() const { return evaluations_; }

private:
  void interior(const State& u, State& dudt) const;
  void outer_boundary(const State& u, State& dudt) const;
  void origin_ghosts(State& dudt) const;

  const Grid* grid_;
  RhsParams params_;
  std::uint64_t evaluations_ = 0;
};

} // namespace gbssn1d
