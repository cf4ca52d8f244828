// The right-hand side on the whole grid (method of lines):
//  - interior points: centred derivatives of the grid's order p = 2, 4, 6 or 8 (chain rule
//    through the radial map), upwind derivatives for the beta d_r advection terms (lopsided of
//    order p, or biased of order p + 1: fd::Upwind),
//    the point-wise equations of gbssn/equations.hpp, plus Kreiss-Oliger dissipation of the
//    (p+2)-th difference (fd/stencils.hpp);
//  - outer ghost cells: Sommerfeld condition (Sec. 8) with one-sided derivatives, toward each
//    variable's asymptotic value from the registry, at the speed the gauge gives its wave
//    family (Gauge::speed);
//  - ghost cells at the origin: the mirror's right-hand side times the parity, so that every
//    Runge-Kutta stage stays parity-consistent.
#pragma once

#include "fd/stencils.hpp"
#include "gbssn/point_data.hpp"
#include "gbssn/rhs_params.hpp"
#include "gbssn/state.hpp"
#include "grid/grid.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace gbssn1d {

/// The point-wise equations of formulation f as the point loop takes them (a policy type such as
/// Bssn, gbssn/equations.hpp, or Z4c, gbssn/z4c.hpp): specialised beside each, with `type`,
/// `make(const RhsParams&)`, whether the horizon shift's study variants exist for it, and the
/// orders and upwind pairs whose point loops are compiled for it (`offers(p, upwind)`).
template <Formulation f>
struct PointEquations;

/// Fields, derivatives and advection terms at grid point i, at the grid's finite-difference
/// order p (needs i - p/2 - 1 ... i + p/2 + 1), advection with the upwind pair `upwind`.
PointData point_data(const State& u, const Grid& grid, std::size_t i,
                     fd::Upwind upwind = fd::Upwind::lopsided);

/// point_data with the ADM trace K in K's place (Z1): K-hat + 2 Theta for a Z4c state, K itself
/// for BSSN's (whose Theta reads 0). What the constraints, the expansion and the areal radius
/// read.
PointData adm_point_data(const State& u, const Grid& grid, std::size_t i);

/// Rows of values of interior points: out[k - k_begin] for point k (grid point
/// first_interior() + k).
struct DiagnosticRows {
  double *H, *M_r, *G_r;  ///< the constraints (Sec. 5); all three null: not computed
  double* R_areal;        ///< (T2) the areal radius
  double* Theta_plus;     ///< (T1) the outgoing expansion
  double* m_ms = nullptr; ///< (T4) the Misner-Sharp mass; computed with the constraints
  /// (S7) the energy flux through the sphere of fixed areal radius; with the constraints, of a
  /// state with matter only (null otherwise)
  double* flux = nullptr;
};
/// The constraints, areal radius and expansion at the interior points [k_begin, k_end), from
/// adm_point_data's values at the grid's order: one vectorised loop (diagnostic_rows.cpp)
/// instead of a call per point, the same expressions.
void diagnostic_rows(const State& u, const Grid& grid, const DiagnosticRows& out,
                     std::size_t k_begin, std::size_t k_end);
/// The same at every interior point.
void diagnostic_rows(const State& u, const Grid& grid, const DiagnosticRows& out);

class GbssnRhs {
public:
  GbssnRhs(const Grid& grid, RhsParams params);

  /// d u / dt at time t; the signature Boost.Odeint expects of a system.
  void operator()(const State& u, State& dudt, double t);

  const Grid& grid() const { return *grid_; }
  const RhsParams& params() const { return params_; }
  std::uint64_t evaluations() const { return evaluations_; }
  void set_evaluations(std::uint64_t n) { evaluations_ = n; } ///< for a resumed run

  /// The horizon radius h_AH used by the horizon shift: set between searches (held mode), or
  /// given by the source at the last evaluation. nullopt: no horizon, beta_H = 0.
  std::optional<double> horizon_radius() const { return h_AH_; }
  void set_horizon_radius(std::optional<double> h_AH) { h_AH_ = h_AH; }

  /// Where an evaluation with the horizon shift on takes h_AH from: called with the stage's
  /// state, the grid, t, the count of evaluations before this one and the radius held so far;
  /// returns the radius to use (a search, a prescribed or an extrapolated value, or the held
  /// one). The schedule lives with the evolution (evolution/horizon_tracker.hpp), so that the
  /// equations depend on neither the finder nor the schedule. Without a source h_AH is held.
  using HorizonSource =
      std::function<std::optional<double>(const State& u, const Grid& grid, double t,
                                          std::uint64_t evaluation, std::optional<double> held)>;
  void set_horizon_source(HorizonSource source) { source_ = std::move(source); }

  /// A box whose outer ghosts are set from its parent before every stage (mesh::MeshStepper
  /// with stage values or dense output) needs no d_t there: the Sommerfeld condition is then
  /// skipped and d_t = 0 is written on those ghosts.
  void set_outer_ghosts_from_parent(bool from_parent) { outer_from_parent_ = from_parent; }

  /// The point loop starts at interior cell `cell` rounded down to a multiple of 8 (0: every
  /// cell) and writes d_t u = 0 below it. For a parent box whose cells below it lie under its
  /// child: restriction overwrites them after every step, and no result reads them before
  /// (mesh::MeshStepper::first_needed_cell). The rounding keeps every point in the part of the
  /// loop that computes it without a first cell (the vectors of 8 points from the first
  /// interior cell, then a remainder): the two parts contract their sums into FMAs differently,
  /// so the same point from the other part may differ in its last bit (measured).
  void set_first_cell(std::size_t cell);
  std::size_t first_cell() const { return first_cell_; }

private:
  /// The point loop; the formulation (a policy type such as Bssn), the matter (Vacuum or
  /// ScalarField, gbssn/matter.hpp), the differencing order, the upwind pair and the horizon
  /// shift are template parameters, so that each instance is branch-free and vectorises (a
  /// run-time switch inside the loop stops it).
  template <class Equations, class M, int order, fd::Upwind upwind, bool with_horizon_shift>
  void interior(const Equations& equations, const State& u, State& dudt) const;
  /// The horizon shift's study variants (--rah-variant no-shift-derivatives, ...): BSSN's loop
  /// at 4th order with the lopsided pair, its equations wrapped (gbssn/rhs_study.cpp, the only
  /// file that compiles them).
  void interior_study_variant(const State& u, State& dudt) const;
  /// The point loop of formulation f at order p with the upwind pair `upwind`, with or without
  /// the horizon shift (and its study variants where f has them). Defined in
  /// gbssn/rhs_interior.hpp and compiled in each formulation's own source file (rhs_bssn.cpp
  /// and rhs_biased.cpp, rhs_z4c.cpp), which build in parallel; evaluate() only declares it.
  template <Formulation f, int p, fd::Upwind upwind>
  void interior_of(const State& u, State& dudt) const;
  /// interior_of where f is offered at order p with the pair `upwind` (PointEquations::offers).
  template <Formulation f, int p, fd::Upwind upwind>
  void interior_offered(const State& u, State& dudt) const;
  /// operator() with the upwind pair `upwind`, at the grid's finite-difference order.
  template <fd::Upwind upwind>
  void evaluate_with(const State& u, State& dudt, double t);
  /// operator() at the grid's finite-difference order p and the upwind pair `upwind`.
  template <int p, fd::Upwind upwind>
  void evaluate(const State& u, State& dudt, double t);
  void outer_boundary(const State& u, State& dudt) const;
  void origin_ghosts(State& dudt) const;
  /// A(t) (h_AH - h) of beta_H for the current h_AH_ (H3), or 0 without a horizon.
  double shift_amplitude(double t) const;

  const Grid* grid_;
  RhsParams params_;
  std::uint64_t evaluations_ = 0;
  std::optional<double> h_AH_;
  HorizonSource source_;
  bool outer_from_parent_ = false;
  std::size_t first_cell_ = 0;  ///< the point loop's first interior cell (set_first_cell)
  std::vector<double> profile_; ///< f(r_i / w) on every point (fixed by the grid)
  static constexpr std::size_t block_size = 256;  ///< points per block of the point loop
  static constexpr std::size_t vector_points = 8; ///< of a vector (AVX-512)
  static_assert(block_size % vector_points == 0);
  std::vector<double> grid_blocks_; ///< grid factors laid out per block (rhs_loop.hpp)
  double shift_amplitude_ = 0.0;    ///< shift_amplitude(t) of the evaluation under way
};

} // namespace gbssn1d
