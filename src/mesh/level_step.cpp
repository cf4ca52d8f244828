// One level's RK4 step (MeshStepper::rk4), its boundary from its parent at each stage time (the
// parent's RK4 stage values, dense output, or three of its time levels, quadratic in time, as
// Carpet and BAM: fill_quadratic).
#include "mesh/hierarchy.hpp"
#include "mesh/time_interpolation.hpp"

#include "grid/grid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gbssn1d::mesh {

void MeshStepper::fill_quadratic(std::vector<State>& u, std::size_t l, double t) const {
  const Level& P = levels_[l - 1];
  const double t_now = P.t0 + P.dt; // the parent's current state u[l - 1]
  const long j_begin = static_cast<long>(layout_->n_cells() - buffer());
  const auto& h = P.history;
  if (h.size() >= 2) {
    const auto w = quadratic_weights(h[h.size() - 2].t, h.back().t, t_now, t);
    fill_from_parent(l, u[l], {&h[h.size() - 2].u, &h.back().u, &u[l - 1]}, {w[0], w[1], w[2]},
                     j_begin);
  } else if (h.size() == 1) {
    const auto w = linear_weights(h.back().t, t_now, t);
    fill_from_parent(l, u[l], {&h.back().u, &u[l - 1]}, {w[0], w[1]}, j_begin);
  } else {
    fill_from_parent(l, u[l], {&u[l - 1]}, {1.0}, j_begin);
  }
}

void MeshStepper::rk4(std::size_t l, State& u, double t, double dt,
                      const std::function<void(int, State&)>& fill, const State* given_k1,
                      State* start) {
  // Classical RK4 with the arithmetic of Boost.Odeint's runge_kutta4 (explicit_generic_rk:
  // stage sums 1 x u + (a_ij dt) k_j in the same order, stage times t + c_i dt), so that one
  // level reproduces it bit for bit; `fill` sets the outer ghosts of each stage's input.
  Level& L = levels_[l];
  LevelRhs& f = rhs_[l];
  State &k2 = L.k[1], &k3 = L.k[2], &k4 = L.k[3], &x = L.tmp;
  // a given first stage is read in place, and copied only where a finer level's boundary
  // needs the coarse stages
  const bool copy_k1 = given_k1 && l + 1 < layout_->levels();
  if (copy_k1)
    L.k[0] = *given_k1;
  const State& k1 = given_k1 && !copy_k1 ? *given_k1 : L.k[0];
  const std::size_t n = u.size();
  x.fit(u);
  const double a21 = 0.5 * dt, a32 = 0.5 * dt, a43 = 1.0 * dt;
  const double b1 = (1.0 / 6.0) * dt, b2 = (1.0 / 3.0) * dt, b3 = (1.0 / 3.0) * dt,
               b4 = (1.0 / 6.0) * dt;
  // The stage sums, each row from the level's first cell on (set_first_cell; every cell by
  // default). Odeint's tableau also has a31 = a41 = a42 = 0: its terms 0 x k add +-0, which
  // leaves every finite sum as it is, so they are left out (three loads in 14 per point and
  // variable).
  const std::size_t nt = layout_->grid(l).n_total(), rows = n / nt;
  const std::size_t skip = first_cell_[l] == 0 ? 0 : Grid::n_ghost + first_cell_[l];
  auto each_cell = [&](auto&& sum) {
    if (skip == 0) {
      for (std::size_t i = 0; i < n; ++i)
        sum(i);
      return;
    }
    for (std::size_t v = 0; v < rows; ++v)
      for (std::size_t i = v * nt + skip; i < (v + 1) * nt; ++i)
        sum(i);
  };
  if (fill)
    fill(0, u);
  if (!given_k1)
    f(u, L.k[0], t);
  each_cell([&](std::size_t i) { x[i] = 1.0 * u[i] + a21 * k1[i]; });
  if (fill)
    fill(1, x);
  f(x, k2, t + 0.5 * dt);
  each_cell([&](std::size_t i) { x[i] = 1.0 * u[i] + a32 * k2[i]; });
  if (fill)
    fill(2, x);
  f(x, k3, t + 0.5 * dt);
  each_cell([&](std::size_t i) { x[i] = 1.0 * u[i] + a43 * k3[i]; });
  if (fill)
    fill(3, x);
  f(x, k4, t + 1.0 * dt);
  if (on_level_step && dt > 0.0)
    on_level_step(l, t, dt, u, {&k1, &k2, &k3, &k4});
  if (start) { // u -> start, the new state -> u, through x: no copy
    each_cell([&](std::size_t i) {
      x[i] = 1.0 * u[i] + b1 * k1[i] + b2 * k2[i] + b3 * k3[i] + b4 * k4[i];
    });
    if (skip > 0) // the cells below the first: the state before the step
      for (std::size_t v = 0; v < rows; ++v)
        std::copy_n(u.begin() + static_cast<std::ptrdiff_t>(v * nt), skip,
                    x.begin() + static_cast<std::ptrdiff_t>(v * nt));
    std::swap(*start, u);
    std::swap(u, x);
  } else {
    each_cell([&](std::size_t i) {
      u[i] = 1.0 * u[i] + b1 * k1[i] + b2 * k2[i] + b3 * k3[i] + b4 * k4[i];
    });
  }
  evaluations_[l] += given_k1 ? 3 : 4;
}

} // namespace gbssn1d::mesh
