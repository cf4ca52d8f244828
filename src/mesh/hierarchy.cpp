#include "mesh/hierarchy.hpp"

#include "core/registry.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace gbssn1d {

namespace {

/// Coarse nodes of the prolongation stencil, relative to the coarse cell holding the fine cell:
/// three either side of the fine centre, which is a quarter cell left (even fine index) or right
/// (odd) of the coarse centre.
constexpr int stencil_left[6] = {-3, -2, -1, 0, 1, 2}; // fine centre at -1/4
constexpr int stencil_right[6] = {-2, -1, 0, 1, 2, 3}; // fine centre at +1/4

std::vector<double> weights_at(const int (&nodes)[6], double x) {
  return lagrange_weights({double(nodes[0]), double(nodes[1]), double(nodes[2]), double(nodes[3]),
                           double(nodes[4]), double(nodes[5])},
                          x);
}

} // namespace

std::vector<double> lagrange_weights(const std::vector<double>& nodes, double x) {
  std::vector<double> w(nodes.size(), 1.0);
  for (std::size_t k = 0; k < nodes.size(); ++k)
    for (std::size_t m = 0; m < nodes.size(); ++m)
      if (m != k)
        w[k] *= (x - nodes[m]) / (nodes[k] - nodes[m]);
  return w;
}

std::vector<Grid> make_levels(const HierarchySpec& spec) {
  if (spec.levels < 1)
    throw std::invalid_argument("a hierarchy needs at least one level");
  if (spec.levels > 1) {
    if (spec.N % 2 != 0)
      throw std::invalid_argument(fmt::format(
          "N = {} is odd: a fine level's outer edge would lie inside a coarse cell", spec.N));
    if (restricted_cells(spec.N) < 1)
      throw std::invalid_argument(fmt::format(
          "N = {} leaves no coarse cell to restrict: a fine level needs more than {} cells "
          "(its buffer of {} and the 6-point stencil)",
          spec.N, buffer_cells + 4, buffer_cells));
  }
  std::vector<Grid> grids;
  for (std::size_t l = 0; l < spec.levels; ++l)
    grids.emplace_back(RadialMap::uniform(spec.rmax / std::ldexp(1.0, static_cast<int>(l))),
                       spec.N);
  return grids;
}

void prolongate(const Grid& coarse, const State& u_coarse, const Grid& fine, State& u_fine,
                std::size_t i_begin, std::size_t i_end) {
  if (i_begin < Grid::n_ghost || i_end > fine.n_total())
    throw std::invalid_argument("prolongation fills interior and outer ghost cells only (the "
                                "origin ghosts hold parity images)");
  static const std::vector<double> w_left = weights_at(stencil_left, -0.25);
  static const std::vector<double> w_right = weights_at(stencil_right, 0.25);
  const std::size_t g = Grid::n_ghost;
  for (const auto& entry : registry) {
    const auto c = field(u_coarse, coarse, entry.var);
    const auto f = field(u_fine, fine, entry.var);
    for (std::size_t i = i_begin; i < i_end; ++i) {
      // fine interior index (may be negative for origin ghosts) and its coarse cell
      const auto fi = static_cast<std::ptrdiff_t>(i) - static_cast<std::ptrdiff_t>(g);
      const std::ptrdiff_t j = fi >= 0 ? fi / 2 : (fi - 1) / 2;
      const bool right = (fi - 2 * j) == 1;
      const auto& nodes = right ? stencil_right : stencil_left;
      const auto& w = right ? w_right : w_left;
      double sum = 0.0;
      for (int k = 0; k < 6; ++k)
        sum += w[k] * c[static_cast<std::size_t>(j + nodes[k] + static_cast<std::ptrdiff_t>(g))];
      f[i] = sum;
    }
  }
}

std::size_t restricted_cells(std::size_t N) {
  // coarse cell j takes fine cells 2j - 2 ... 2j + 3, which must lie below the buffer
  const std::ptrdiff_t exact = static_cast<std::ptrdiff_t>(N) - std::ptrdiff_t{buffer_cells};
  if (exact < 4)
    return 0;
  return static_cast<std::size_t>((exact - 4) / 2 + 1); // 2j + 3 <= exact - 1
}

void restrict_to_coarse(const Grid& fine, const State& u_fine, const Grid& coarse,
                        State& u_coarse) {
  // the value midway between two fine centres, 6-point Lagrange: (3, -25, 150, 150, -25, 3)/256
  constexpr double w[6] = {3.0 / 256,   -25.0 / 256, 150.0 / 256,
                           150.0 / 256, -25.0 / 256, 3.0 / 256};
  const std::size_t g = Grid::n_ghost, cells = restricted_cells(fine.n_interior());
  for (const auto& entry : registry) {
    const auto f = field(u_fine, fine, entry.var);
    const auto c = field(u_coarse, coarse, entry.var);
    for (std::size_t j = 0; j < cells; ++j) {
      double sum = 0.0;
      for (std::size_t k = 0; k < 6; ++k)
        sum += w[k] * f[g + 2 * j + k - 2];
      c[g + j] = sum;
    }
  }
  fill_origin_ghosts(u_coarse, coarse);
}

BergerOliger::BergerOliger(HierarchySpec spec, double cfl, std::vector<State> u,
                           std::vector<LevelRhs> rhs)
    : spec_(spec), cfl_(cfl), grids_(make_levels(spec)), levels_(grids_.size()),
      rhs_(std::move(rhs)) {
  if (u.size() != grids_.size() || rhs_.size() != grids_.size())
    throw std::invalid_argument("one state and one right-hand side per level");
  for (std::size_t l = 0; l < grids_.size(); ++l) {
    if (u[l].size() != n_vars * grids_[l].n_total())
      throw std::invalid_argument(fmt::format("level {}: the state has the wrong size", l));
    levels_[l].u = std::move(u[l]);
  }
}

double BergerOliger::dt(std::size_t l) const {
  const std::size_t finest = grids_.size() - 1;
  return cfl_ * grids_[spec_.subcycling ? l : finest].min_spacing();
}

void BergerOliger::evaluate(std::size_t l, const State& u, State& dudt, double t) {
  rhs_[l](u, dudt, t);
  ++levels_[l].evaluations;
}

void BergerOliger::rk4(std::size_t l, double dt) {
  // Boost.Odeint's runge_kutta4 (classic), operation for operation, with k1 = f_start.
  Level& L = levels_[l];
  State& u = L.u;
  const State& k1 = L.f_start;
  const std::size_t n = u.size();
  const double t = L.t, dh = dt / 2.0, th = t + dh;
  L.tmp.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    L.tmp[i] = 1.0 * u[i] + dh * k1[i];
  evaluate(l, L.tmp, L.k2, th);
  for (std::size_t i = 0; i < n; ++i)
    L.tmp[i] = 1.0 * u[i] + dh * L.k2[i];
  evaluate(l, L.tmp, L.k3, th);
  for (std::size_t i = 0; i < n; ++i)
    L.tmp[i] = 1.0 * u[i] + dt * L.k3[i];
  evaluate(l, L.tmp, L.k4, t + dt);
  const double dt6 = dt / 6.0, dt3 = dt / 3.0;
  for (std::size_t i = 0; i < n; ++i)
    u[i] = 1.0 * u[i] + dt6 * k1[i] + dt3 * L.k2[i] + dt3 * L.k3[i] + dt6 * L.k4[i];
}

void BergerOliger::advance(std::size_t l) {
  Level& L = levels_[l];
  const bool coarse_of_another = l + 1 < levels();
  const double dt_l = dt(l);
  if (coarse_of_another) { // what the finer level's boundary zone is interpolated from
    if (spec_.time_interpolation == TimeInterpolation::quadratic && L.stepped)
      L.u_earlier = L.u_start;
    L.u_start = L.u;
  }
  L.t_start = L.t;
  evaluate(l, L.u, L.f_start, L.t);
  rk4(l, dt_l);
  L.t = L.t_start + dt_l;
  if (l > 0) { // end the step exactly where the coarser level's step ends
    const Level& P = levels_[l - 1];
    if (std::abs(L.t - P.t) <= 1e-12 * dt_l)
      L.t = P.t;
    fill_boundary_zone(l, L.t);
  }
  if (after_step)
    after_step(l, L.u);
  L.stepped = true;
  if (!coarse_of_another)
    return;
  if (spec_.time_interpolation == TimeInterpolation::dense)
    evaluate(l, L.u, L.u_end_rhs, L.t);
  const int substeps = spec_.subcycling ? 2 : 1;
  for (int s = 0; s < substeps; ++s)
    advance(l + 1);
  restrict_to_coarse(grids_[l + 1], levels_[l + 1].u, grids_[l], L.u);
  if (after_step)
    after_step(l, L.u);
}

void BergerOliger::coarse_at(std::size_t l, double t, State& out) const {
  const Level& P = levels_[l];
  const double dt = P.t - P.t_start, theta = (t - P.t_start) / dt;
  if (std::abs(theta - 1.0) <= 1e-12) {
    out = P.u; // the end of the coarse step: no interpolation
    return;
  }
  if (spec_.time_interpolation == TimeInterpolation::dense) {
    hermite_interpolate(P.u_start, P.f_start, P.u, P.u_end_rhs, dt, theta, out);
    return;
  }
  out.resize(P.u.size());
  if (!P.u_earlier) { // the first step: only two time levels yet
    for (std::size_t i = 0; i < out.size(); ++i)
      out[i] = (1.0 - theta) * P.u_start[i] + theta * P.u[i];
    return;
  }
  // the parabola through t_start - dt, t_start and t_start + dt
  const double w_earlier = 0.5 * theta * (theta - 1.0), w_start = (1.0 - theta) * (1.0 + theta),
               w_end = 0.5 * theta * (theta + 1.0);
  const State& e = *P.u_earlier;
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = w_earlier * e[i] + w_start * P.u_start[i] + w_end * P.u[i];
}

void BergerOliger::fill_boundary_zone(std::size_t l, double t) {
  coarse_at(l - 1, t, scratch_);
  const Grid& fine = grids_[l];
  prolongate(grids_[l - 1], scratch_, fine, levels_[l].u, fine.end_interior() - buffer_cells,
             fine.n_total());
}

void BergerOliger::step() {
  advance(0);
  t_ = levels_[0].t;
}

void hermite_interpolate(const State& u0, const State& f0, const State& u1, const State& f1,
                         double dt, double theta, State& out) {
  const double s = theta, s2 = s * s, s3 = s2 * s;
  const double h00 = 2.0 * s3 - 3.0 * s2 + 1.0, h01 = -2.0 * s3 + 3.0 * s2;
  const double h10 = (s3 - 2.0 * s2 + s) * dt, h11 = (s3 - s2) * dt;
  out.resize(u0.size());
  for (std::size_t i = 0; i < u0.size(); ++i)
    out[i] = h00 * u0[i] + h10 * f0[i] + h01 * u1[i] + h11 * f1[i];
}

} // namespace gbssn1d
