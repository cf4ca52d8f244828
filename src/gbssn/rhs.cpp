#include "gbssn/rhs.hpp"

#include "gbssn/horizon_shift.hpp"
#include "gbssn/rhs_loop.hpp"
#include "gbssn/z4c.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace gbssn1d {

namespace {

template <int p, fd::Upwind upwind>
PointData point_data_at(const State& u, const Grid& grid, std::size_t i) {
  point_loop::Differences ko;
  const point_loop::Rows rows(u, grid);
  const double r = grid.r()[i], inv_r = grid.inv_r()[i], inv_dx = 1.0 / grid.dx(),
               inv_rx = grid.inv_dr_dx()[i], d2_fx = grid.d2_fx_coeff()[i];
  if (formulation_of(u, grid) == Formulation::z4c) {
    constexpr std::size_t n = n_evolved(Formulation::z4c);
    return point_loop::gather<p, upwind, n>(rows, i, r, inv_r, inv_dx, inv_rx, d2_fx, ko);
  }
  constexpr std::size_t n = n_evolved(Formulation::bssn);
  PointData pd = point_loop::gather<p, upwind, n>(rows, i, r, inv_r, inv_dx, inv_rx, d2_fx, ko);
  pd.f[Var::Theta] = pd.d[Var::Theta] = pd.dd[Var::Theta] = pd.adv[Var::Theta] = 0.0;
  return pd;
}

template <fd::Upwind upwind>
PointData point_data_with(const State& u, const Grid& grid, std::size_t i) {
  switch (grid.fd_order()) {
  case 2:
    return point_data_at<2, upwind>(u, grid, i);
  case 6:
    return point_data_at<6, upwind>(u, grid, i);
  case 8:
    return point_data_at<8, upwind>(u, grid, i);
  default:
    return point_data_at<4, upwind>(u, grid, i);
  }
}

} // namespace

PointData point_data(const State& u, const Grid& grid, std::size_t i, fd::Upwind upwind) {
  return upwind == fd::Upwind::biased ? point_data_with<fd::Upwind::biased>(u, grid, i)
                                      : point_data_with<fd::Upwind::lopsided>(u, grid, i);
}

PointData adm_point_data(const State& u, const Grid& grid, std::size_t i) {
  const PointData p = point_data(u, grid, i);
  return formulation_of(u, grid) == Formulation::z4c ? adm_trace(p) : p;
}

GbssnRhs::GbssnRhs(const Grid& grid, RhsParams params) : grid_(&grid), params_(params) {
  // r, 1/r, 1/r_x and the f_rr coefficient, block by block (interior)
  const std::size_t n = grid.n_interior(), blocks = (n + block_size - 1) / block_size;
  grid_blocks_.assign(blocks * 4 * block_size, 0.0);
  const std::vector<double>* rows[4] = {&grid.r(), &grid.inv_r(), &grid.inv_dr_dx(),
                                        &grid.d2_fx_coeff()};
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t v = 0; v < 4; ++v)
      grid_blocks_[(k / block_size * 4 + v) * block_size + k % block_size] =
          (*rows[v])[grid.first_interior() + k];
  if (params_.horizon_shift.active())
    profile_ = profile_on(grid, params_.horizon_shift);
}

void GbssnRhs::set_first_cell(std::size_t cell) {
  if (cell > grid_->n_interior())
    throw std::invalid_argument("the point loop's first cell lies beyond the grid");
  first_cell_ = cell / vector_points * vector_points;
}

double GbssnRhs::shift_amplitude(double t) const {
  const HorizonShiftParams& hs = params_.horizon_shift;
  // without a horizon beta_H = 0 (amplitude 0 keeps the same loop)
  return h_AH_ ? hs.strength(t) * (*h_AH_ - hs.h) : 0.0;
}

// compiled in rhs_biased.cpp
extern template void GbssnRhs::evaluate_with<fd::Upwind::biased>(const State&, State&, double);

void GbssnRhs::operator()(const State& u, State& dudt, double t) {
  // dispatched once per call: each order's and upwind pair's loop is its own instance
  if (params_.upwind == fd::Upwind::biased)
    evaluate_with<fd::Upwind::biased>(u, dudt, t);
  else
    evaluate_with<fd::Upwind::lopsided>(u, dudt, t);
}

void GbssnRhs::outer_boundary(const State& u, State& dudt) const {
  // Sec. 8: d_t f = -v [ d_r f + n (f - f_inf) / r ], one-sided derivatives, on the ghost cells.
  const Grid& g = *grid_;
  const std::size_t nt = g.n_total();
  const double inv_dx = 1.0 / g.dx();
  for (const auto& entry : state_vars(u, g)) {
    const double* f = u.data() + index(entry.var) * nt;
    double* out = dudt.data() + index(entry.var) * nt;
    const double speed = params_.gauge.speed(entry.wave);
    for (std::size_t i = g.end_interior(); i < nt; ++i) {
      const double d_r_f = fd::d1_backward(f + i) * inv_dx * g.inv_dr_dx()[i];
      out[i] = -speed * (d_r_f + entry.falloff * (f[i] - entry.asymptotic) * g.inv_r()[i]);
    }
  }
}

void GbssnRhs::origin_ghosts(State& dudt) const {
  fill_origin_ghosts(dudt, *grid_);
}

} // namespace gbssn1d
