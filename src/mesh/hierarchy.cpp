#include "mesh/hierarchy.hpp"
#include "mesh/level_steps.hpp"
#include "mesh/prolong_rows.hpp"
#include "mesh/time_interpolation.hpp"

#include "fd/stencils.hpp"
#include "mesh/transfer.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
#include <utility>

namespace gbssn1d::mesh {

MeshStepper::MeshStepper(const MeshLayout& layout, std::vector<LevelRhs> rhs,
                         StepperOptions options)
    : layout_(&layout), rhs_(std::move(rhs)), options_(options), levels_(layout.levels()),
      evaluations_(layout.levels(), 0), first_cell_(layout.levels(), 0) {
  if (rhs_.size() != layout.levels())
    throw std::invalid_argument("the mesh stepper needs one right-hand side per level ("
                                + std::to_string(layout.levels()) + "), got "
                                + std::to_string(rhs_.size()));
  if (!(options_.cfl > 0.0 && options_.cfl <= 1.0))
    throw std::invalid_argument("--cfl = " + std::to_string(options_.cfl)
                                + " is invalid: outside (0, 1]");
  if (!(options_.dt_max > 0.0))
    throw std::invalid_argument("the mesh stepper's largest step must be positive");
  steps_ = level_steps(layout, options_);
}

void MeshStepper::fit_scratch(const std::vector<State>& u) {
  // shaped by the states themselves, which carry their formulation (gbssn/state.hpp)
  for (std::size_t l = 0; l < layout_->levels(); ++l) {
    Level& L = levels_[l];
    L.tmp.fit(u[l]);
    for (auto& k : L.k)
      k.fit(u[l]);
    if (l + 1 < layout_->levels()) {
      L.u0.fit(u[l]);
      L.scratch.fit(u[l]);
    }
  }
}

double MeshStepper::dt() const {
  return hierarchy_dt(*layout_, options_);
}

double MeshStepper::level_dt(std::size_t level, double dt) const {
  return dt / static_cast<double>(steps_.at(level));
}

long MeshStepper::restricted_cells() const {
  // coarse cell i reads fine cells up to 2i + 3, which must lie below N - buffer
  const long n = static_cast<long>(layout_->n_cells()), b = static_cast<long>(buffer());
  return (n - b - 4) / 2 + 1;
}

std::size_t MeshStepper::first_needed_cell(std::size_t l) const {
  if (l + 1 >= layout_->levels())
    return 0;
  const long n = static_cast<long>(layout_->n_cells()), b = static_cast<long>(buffer());
  const long R = static_cast<long>(fd::stencil_radius(layout_->fd_order()));
  // The lowest cell read: the child's fills (every stage, or once per step over its buffer)
  // prolong from coarse cell (N - buffer) / 2 - 3 on; the diagnostics of the parent's own cells
  // from N / 2 on (on dense output between steps, before restriction) reach 3 cells further
  // down with the horizon finder's and the radius interpolation's 6-point stencils, and R below
  // those with the derivatives. The taper and the ghosts' last fill read the parent after
  // restriction, which leaves every cell below restricted_cells() exact.
  const long lowest = std::min({(n - b) / 2 - 3, n / 2 - 3 - R, restricted_cells()});
  return static_cast<std::size_t>(std::max(0L, lowest - 3 * R));
}

void MeshStepper::set_first_cell(std::size_t l, std::size_t cell) {
  if (cell > first_needed_cell(l))
    throw std::logic_error("a level's stage sums may skip the cells below first_needed_cell only");
  first_cell_.at(l) = cell;
}

void MeshStepper::restrict_level(std::vector<State>& u, std::size_t fine_level) const {
  restrict_to(u[fine_level], layout_->grid(fine_level), u[fine_level - 1],
              layout_->grid(fine_level - 1), 0, restricted_cells());
}

void MeshStepper::fill_ghosts(std::vector<State>& u) const {
  const long end = static_cast<long>(layout_->n_cells() + Grid::n_ghost);
  const long begin = static_cast<long>(layout_->n_cells() - buffer());
  for (std::size_t l = 1; l < layout_->levels(); ++l)
    prolong(u[l - 1], layout_->grid(l - 1), u[l], layout_->grid(l), begin, end);
}

void MeshStepper::taper_from_parent(std::vector<State>& u, std::size_t l) {
  const long n = static_cast<long>(layout_->n_cells());
  const long k = std::min(static_cast<long>(options_.taper_cells), n / 2);
  if (l == 0 || k <= 0 || layout_->extent(l) <= options_.taper_min_extent)
    return;
  const long j0 = n - k;
  State& parent = levels_[l].tmp; // free between steps
  parent.fit(u[l]);
  fill_from_parent(l, parent, {&u[l - 1]}, {1.0}, j0);
  const Grid& g = layout_->grid(l);
  for (const auto& entry : u[l].vars()) {
    const auto p = field(parent, g, entry.var);
    const auto f = field(u[l], g, entry.var);
    for (long j = j0; j < n; ++j) {
      const double s = static_cast<double>(j - j0 + 1) / static_cast<double>(k);
      const double w = s * s * (3.0 - 2.0 * s);
      const std::size_t i = Grid::n_ghost + static_cast<std::size_t>(j);
      f[i] += w * (p[i] - f[i]);
    }
  }
}

void MeshStepper::initialise(std::vector<State>& u, double t) {
  if (u.size() != layout_->levels())
    throw std::invalid_argument("the mesh stepper needs one state per level");
  fit_scratch(u);
  for (std::size_t l = 0; l < layout_->levels(); ++l)
    fill_origin_ghosts(u[l], layout_->grid(l));
  for (std::size_t l = layout_->levels() - 1; l >= 1; --l)
    restrict_level(u, l);
  fill_ghosts(u);
  for (auto& L : levels_) {
    L.history.clear();
    L.t0 = t;
    L.dt = 0.0;
  }
  // Quadratic interpolation in time needs three time levels from the first step on: the level
  // before t is made by one RK4 step backwards, as Carpet's init_3_timelevels (Scott Hawley's
  // algorithm) evolves to fill past time levels. Without it the first coarse step would
  // interpolate linearly, an O(dt^2) error at the fine boundary that does not converge where it
  // focuses at r = 0 (measured: the 3-level gauge pulse's self-convergence stalls). The
  // backward step of a level > 0 keeps its ghosts from t; what that spoils stays within
  // stages x stencil radius points of its outer ghosts, away from the cells its child reads.
  if (options_.time == TimeInterpolation::quadratic)
    for (std::size_t l = 0; l + 1 < layout_->levels(); ++l) {
      const double dt_l = level_dt(l, dt());
      State back = u[l];
      rk4(l, back, t, -dt_l, nullptr);
      levels_[l].history.push_back({t - dt_l, std::move(back)});
    }
}

void MeshStepper::fill_from_parent(std::size_t l, State& fine,
                                   std::initializer_list<const State*> arrays,
                                   std::initializer_list<double> weights, long j_begin) const {
  // one call per stage of every box: the scratch is the parent's, allocated once
  prolong_combination({std::data(arrays), arrays.size()}, {std::data(weights), weights.size()},
                      layout_->grid(l - 1), fine, layout_->grid(l), j_begin,
                      levels_[l - 1].scratch);
}

void MeshStepper::advance(std::vector<State>& u, std::size_t l, double t, double dt,
                          const State* k1) {
  const bool quadratic = options_.time == TimeInterpolation::quadratic;
  const bool has_child = l + 1 < layout_->levels();
  Level& L = levels_[l];
  if (l > 0 && quadratic)
    fill_quadratic(u, l, t);
  if (has_child && quadratic) {
    if (L.history.size() == 2)
      L.history.erase(L.history.begin());
    L.history.push_back({t, u[l]});
  }
  L.t0 = t;
  L.dt = dt;
  std::function<void(int, State&)> fill;
  if (l > 0 && !quadratic) {
    const Level& P = levels_[l - 1];
    const double theta = (t - P.t0) / P.dt, ratio = dt / P.dt;
    const long j_begin = static_cast<long>(layout_->n_cells());
    // each stage's weights, once per step, or as made for the same theta, ratio and dt
    auto* memo = &L.weights_memo[0];
    if (!(memo->theta == theta && memo->ratio == ratio && memo->dt == P.dt)) {
      memo = &L.weights_memo[1];
      if (!(memo->theta == theta && memo->ratio == ratio && memo->dt == P.dt)) {
        memo = &L.weights_memo[L.weights_memo_next];
        L.weights_memo_next = 1 - L.weights_memo_next;
        *memo = {theta, ratio, P.dt, {}};
        if (options_.time == TimeInterpolation::rk_stages)
          memo->weights = rk_stage_weights_all(theta, ratio, P.dt);
        else
          for (std::size_t s = 0; s < 4; ++s)
            memo->weights[s] = dense_output_weights(theta + rk4_stage_times[s] * ratio, P.dt);
      }
    }
    const std::array<StageWeights, 4> weights = memo->weights;
    fill = [this, &P, l, weights, j_begin](int s, State& x) {
      const StageWeights& w = weights[static_cast<std::size_t>(s)];
      // Trailing zero weights add +-0 to a sum that is never -0 (it starts at +0): the same
      // bits without them. At theta = 0 the first stage reads u0 alone, the second u0 and k1.
      if (w[2] == 0.0 && w[3] == 0.0 && w[4] == 0.0) {
        if (w[1] == 0.0)
          fill_from_parent(l, x, {&P.u0}, {w[0]}, j_begin);
        else
          fill_from_parent(l, x, {&P.u0, &P.k[0]}, {w[0], w[1]}, j_begin);
        return;
      }
      fill_from_parent(l, x, {&P.u0, &P.k[0], &P.k[1], &P.k[2], &P.k[3]},
                       {w[0], w[1], w[2], w[3], w[4]}, j_begin);
    };
  }
  // the children's boundaries interpolate between the step's start (L.u0) and its stages
  rk4(l, u[l], t, dt, fill, k1, has_child && !quadratic ? &L.u0 : nullptr);
  if (after_step)
    after_step(l, u[l]);
  if (has_child) {
    if (steps_[l + 1] != steps_[l]) { // two child steps
      advance(u, l + 1, t, 0.5 * dt);
      advance(u, l + 1, t + 0.5 * dt, 0.5 * dt);
    } else {
      advance(u, l + 1, t, dt);
    }
    restrict_level(u, l + 1);
    taper_from_parent(u, l + 1);
  }
}

void MeshStepper::step(std::vector<State>& u, double t, double dt) {
  step(u, t, dt, nullptr);
}

void MeshStepper::step(std::vector<State>& u, double t, double dt, const State& k1) {
  step(u, t, dt, &k1);
}

void MeshStepper::step(std::vector<State>& u, double t, double dt, const State* k1) {
  if (u.size() != layout_->levels())
    throw std::invalid_argument("the mesh stepper needs one state per level");
  fit_scratch(u);
  advance(u, 0, t, dt, k1);
  // Every level is at t + dt now: its outer ghosts (and buffer) by prolongation, so that each
  // state is complete for output. This changes nothing in the evolution: the next step's first
  // fill at t + dt selects the same parent state with weights exactly 1 and 0.
  fill_ghosts(u);
}

} // namespace gbssn1d::mesh
