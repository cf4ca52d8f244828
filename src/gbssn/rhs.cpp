#include "gbssn/rhs.hpp"

#include "gbssn/dispatch.hpp"
#include "gbssn/horizon_shift.hpp"
#include "gbssn/rhs_loop.hpp"
#include "gbssn/z4c.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace gbssn1d {

namespace {

/// The state's rows gathered at point i (Theta zero where the formulation evolves none), and,
/// with `adm`, as the diagnostics read them (diagnosed: K the ADM K).
template <int p, fd::Upwind upwind, Formulation f>
PointData point_data_as(const State& u, const Grid& grid, std::size_t i, bool adm) {
  point_loop::Differences ko;
  const point_loop::Rows rows(u, grid);
  const double r = grid.r()[i], inv_r = grid.inv_r()[i], inv_dx = 1.0 / grid.dx(),
               inv_rx = grid.inv_dr_dx()[i], d2_fx = grid.d2_fx_coeff()[i];
  PointData pd =
      point_loop::gather<p, upwind, Fields(f)>(rows, i, r, inv_r, inv_dx, inv_rx, d2_fx, ko);
  if constexpr (!traits(f).evolves(Var::Theta))
    pd.f[Var::Theta] = pd.d[Var::Theta] = pd.dd[Var::Theta] = pd.adv[Var::Theta] = 0.0;
  return adm ? diagnosed<f>(pd) : pd;
}

PointData point_data_of(const State& u, const Grid& grid, std::size_t i, fd::Upwind upwind,
                        bool adm) {
  return with_upwind(upwind, [&]<fd::Upwind w>() {
    return with_order(grid.fd_order(), [&]<int p>() {
      return with_formulation(u.formulation(), [&]<Formulation f>() {
        return point_data_as<p, w, f>(u, grid, i, adm);
      });
    });
  });
}

} // namespace

PointData point_data(const State& u, const Grid& grid, std::size_t i, fd::Upwind upwind) {
  return point_data_of(u, grid, i, upwind, false);
}

PointData adm_point_data(const State& u, const Grid& grid, std::size_t i) {
  return point_data_of(u, grid, i, fd::Upwind::lopsided, true);
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

void GbssnRhs::operator()(const State& u, State& dudt, double t) {
  // dispatched once per call: each order's and upwind pair's loop is its own instance
  with_upwind(params_.upwind, [&]<fd::Upwind w>() { evaluate_with<w>(u, dudt, t); });
}

void GbssnRhs::outer_boundary(const State& u, State& dudt) const {
  // Sec. 8: d_t f = -v [ d_r f + n (f - f_inf) / r ], one-sided derivatives, on the ghost cells.
  const Grid& g = *grid_;
  const std::size_t nt = g.n_total();
  const double inv_dx = 1.0 / g.dx();
  for (std::size_t k = 0; k < u.vars().size(); ++k) {
    const VarInfo& entry = u.vars()[k];
    const double* f = u.data() + k * nt;
    double* out = dudt.data() + k * nt;
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
