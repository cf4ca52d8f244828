#include "mesh/hierarchy.hpp"
#include "mesh/time_interpolation.hpp"

#include "fd/stencils.hpp"
#include "mesh/transfer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace gbssn1d::mesh {

std::vector<long> level_steps(const MeshLayout& layout, const StepperOptions& options) {
  // Level l's step is dt_finest x 2^k_l, the largest such step within cfl dr_l and dt_max; its
  // parent's is the same or twice it (refinement factor 1 or 2 in time).
  const std::size_t n_levels = layout.levels();
  const double dt_finest = options.cfl * layout.spacing(n_levels - 1);
  std::vector<long> steps(n_levels, 1);
  if (options.subcycling) {
    std::vector<int> k(n_levels, 0);
    for (std::size_t l = n_levels - 1; l-- > 0;) {
      k[l] = k[l + 1];
      const double twice = std::ldexp(dt_finest, k[l] + 1);
      if (twice <= options.cfl * layout.spacing(l) * (1.0 + 1e-12) && twice <= options.dt_max)
        ++k[l];
    }
    for (std::size_t l = 0; l < n_levels; ++l)
      steps[l] = 1L << (k[0] - k[l]);
  }
  return steps;
}

double hierarchy_dt(const MeshLayout& layout, const StepperOptions& options) {
  const std::size_t finest = layout.levels() - 1;
  return static_cast<double>(level_steps(layout, options)[finest]) * options.cfl
         * layout.spacing(finest);
}

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

namespace {

/// s = sum_m w[m] a[m] (m = 0 ... M - 1, in that order) on the cells [lo, hi) of each of `rows`
/// rows of nt points (interior cell i at g + i): the loop over the cells vectorises, each sum
/// in a register (summing one array at a time through memory waited on store forwarding).
template <std::size_t M>
void combine_rows(const State* const* a, const double* w, State& s, std::size_t rows,
                  std::size_t nt, std::size_t g, long lo, long hi) {
  for (std::size_t v = 0; v < rows; ++v) {
    const std::size_t row = v * nt + g;
    std::array<const double*, M> f{};
    for (std::size_t m = 0; m < M; ++m)
      f[m] = a[m]->data() + row;
    double* const out = s.data() + row;
    for (long i = lo; i < hi; ++i) {
      double sum = 0.0;
#pragma GCC unroll 8
      for (std::size_t m = 0; m < M; ++m)
        sum = combination_term(sum, w[m], f[m][i]);
      out[i] = sum;
    }
  }
}

/// The coarse cells a fused fill (fill_rows) holds per row, at most.
constexpr long fused_cells = 64;

/// fine[j] for the interior cells j in [j_begin, j_end) of each of `rows` rows (at most
/// n_vars): the parent's arrays combined as combine_rows does on the coarse cells [lo, hi)
/// (0 <= lo, hi - lo <= fused_cells) into a local array, every row first, then prolonged from
/// it as prolong_field does. The same sums in the same order, so the same bits; gone are the
/// round trip through the parent's scratch rows and the mirror's branch (the fill of each stage
/// of every box, a tenth of a box run). All rows are combined before any is prolonged: a
/// prolongation reading a row just stored waits on store forwarding.
template <std::size_t M>
void fill_rows(const State* const* a, const double* w, std::size_t rows, std::size_t nt_c,
               State& fine, std::size_t nt_f, long lo, long hi, long j_begin, long j_end) {
  const std::size_t g = Grid::n_ghost, cells = static_cast<std::size_t>(hi - lo);
  std::array<double, n_vars * fused_cells> combined; // row v, coarse cell i: v * cells + i - lo
  for (std::size_t v = 0; v < rows; ++v) {
    std::array<const double*, M> f{};
    for (std::size_t m = 0; m < M; ++m)
      f[m] = a[m]->data() + v * nt_c + g + lo;
    double* const c = combined.data() + v * cells;
    for (std::size_t i = 0; i < cells; ++i) {
      double sum = 0.0;
#pragma GCC unroll 8
      for (std::size_t m = 0; m < M; ++m)
        sum = combination_term(sum, w[m], f[m][i]);
      c[i] = sum;
    }
  }
  for (std::size_t v = 0; v < rows; ++v) {
    const double* const c = combined.data() + v * cells; // c[i - lo]: coarse cell i
    double* const out = fine.data() + v * nt_f + g;
    // fine cell 2i at -1/4 from coarse centre i reads cells i-3 ... i+2, fine cell 2i+1 at
    // +1/4 reads i-2 ... i+3 (prolong_field): a pair's m-th terms are neighbours in c
    auto one = [&](long j, const std::array<double, 6>& wj, long first) {
      double sum = 0.0;
      for (std::size_t m = 0; m < 6; ++m)
        sum += wj[m] * c[first - lo + static_cast<long>(m)];
      out[j] = sum;
    };
    long j = j_begin;
    if ((j & 1) == 1) {
      one(j, prolong_weights_plus, j / 2 - 2);
      ++j;
    }
    for (; j + 1 < j_end; j += 2) {
      const double* const cm = c + (j / 2 - 3 - lo);
      double minus = 0.0, plus = 0.0;
      for (std::size_t m = 0; m < 6; ++m) {
        minus += prolong_weights_minus[m] * cm[m];
        plus += prolong_weights_plus[m] * cm[m + 1];
      }
      out[j] = minus;
      out[j + 1] = plus;
    }
    if (j < j_end)
      one(j, prolong_weights_minus, j / 2 - 3);
  }
}

} // namespace

void prolong_combination(std::span<const State* const> arrays, std::span<const double> weights,
                         const Grid& gc, State& fine, const Grid& gf, long j_begin,
                         State& scratch) {
  if (arrays.empty() || arrays.size() != weights.size())
    throw std::logic_error("prolong_combination needs one weight per array");
  const long j_end = static_cast<long>(gf.n_interior() + Grid::n_ghost);
  // the coarse cells the prolongation reads: floor(j/2) - 3 ... floor(j/2) + 3, mirrored below 0
  long lo = j_begin / 2 - 3;
  long hi = (j_end - 1) / 2 + 4;
  // The parent's arrays need not be of one formulation's count: the rows are those of the
  // state (size / nt).
  const std::size_t nt = gc.n_total(), g = Grid::n_ghost;
  const std::size_t size = arrays.front()->size();
  const std::size_t rows = size / nt;
  const State* const* const a = arrays.data();
  const double* const w = weights.data();
  if (lo >= 0 && hi - lo <= fused_cells && rows <= n_vars) { // away from the origin's mirror
    const std::size_t nt_f = gf.n_total();
    switch (arrays.size()) { // the counts the callers pass: each sum's terms in registers
    case 1:
      return fill_rows<1>(a, w, rows, nt, fine, nt_f, lo, hi, j_begin, j_end);
    case 2:
      return fill_rows<2>(a, w, rows, nt, fine, nt_f, lo, hi, j_begin, j_end);
    case 3:
      return fill_rows<3>(a, w, rows, nt, fine, nt_f, lo, hi, j_begin, j_end);
    case 5:
      return fill_rows<5>(a, w, rows, nt, fine, nt_f, lo, hi, j_begin, j_end);
    default:
      throw std::logic_error("prolong_combination combines 1, 2, 3 or 5 arrays");
    }
  }
  if (lo < 0) {
    hi = std::max(hi, -lo);
    lo = 0;
  }
  // near the origin: scratch = sum_m w[m] arrays[m] on the cells [lo, hi) of every variable,
  // then prolong_field with the mirror
  scratch.fit(*arrays.front());
  switch (arrays.size()) {
  case 1:
    combine_rows<1>(a, w, scratch, rows, nt, g, lo, hi);
    break;
  case 2:
    combine_rows<2>(a, w, scratch, rows, nt, g, lo, hi);
    break;
  case 3:
    combine_rows<3>(a, w, scratch, rows, nt, g, lo, hi);
    break;
  case 5:
    combine_rows<5>(a, w, scratch, rows, nt, g, lo, hi);
    break;
  default:
    throw std::logic_error("prolong_combination combines 1, 2, 3 or 5 arrays");
  }
  prolong(scratch, gc, fine, gf, j_begin, j_end);
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
