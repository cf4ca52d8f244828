// The point loop of GbssnRhs (gbssn/rhs.hpp): gathering a point's data, the blocks of the loop
// and its instances, one per formulation, finite-difference order and upwind pair, with and
// without the horizon shift (the study's variants are formulations of their own:
// gbssn/rhs_study.cpp).
// Internal to src/gbssn: included by rhs.cpp (the lopsided pair) and rhs_biased.cpp (the biased
// pair's instances, compiled on their own so that the two build in parallel).
#pragma once

#include "fd/stencils.hpp"
#include "gbssn/dispatch.hpp"
#include "gbssn/full_shift.hpp"
#include "gbssn/rhs.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace gbssn1d {

namespace point_loop {

/// An AdvectionStencil as 0/1 weights of the three stencils (branch-free, so that the point
/// loop vectorises).
struct StencilWeights {
  double centred = 0.0, upwind_gd = 0.0, upwind_full = 0.0, matched = 0.0;
  explicit StencilWeights(AdvectionStencil s)
      : centred(s == AdvectionStencil::centred ? 1.0 : 0.0),
        upwind_gd(s == AdvectionStencil::upwind_gd ? 1.0 : 0.0),
        upwind_full(s == AdvectionStencil::upwind_full ? 1.0 : 0.0),
        matched(s == AdvectionStencil::matched ? 1.0 : 0.0) {}
};

/// d_x Delta^r (times dx) by the weighted stencil of order p, upwind pair u; `beta_gd`,
/// `beta_full` give the upwind directions; `diff` is fd::difference<p>(f).
template <int p, fd::Upwind u>
[[gnu::always_inline]] inline double delta_derivative(const StencilWeights& w, const double* f,
                                                      double beta_gd, double beta_full,
                                                      double diff) {
  const double half_sum = 0.5 * fd::upwind_sum<p, u>(f),
               half_diff = (0.5 * fd::Order<p>::template upwind_ratio_of<u>)*diff;
  const double sign_gd = beta_gd > 0.0 ? 1.0 : -1.0, sign_full = beta_full > 0.0 ? 1.0 : -1.0;
  return w.centred * fd::d1_centred<p>(f) + w.upwind_gd * (half_sum + sign_gd * half_diff)
         + w.upwind_full * (half_sum + sign_full * half_diff);
}

/// Pointers to the start of each variable's array, in registry order (passed by value, so that
/// the compiler keeps them in registers in the point loop); null for a variable the state's
/// formulation does not evolve.
struct Rows {
  std::array<const double*, n_vars> row{};
  Rows(const State& u, const Grid& grid) {
    for (const auto& entry : u.vars())
      row[index(entry.var)] = field(u, grid, entry.var).data();
  }
  const double*& operator[](Var v) { return row[index(v)]; }
  const double* operator[](Var v) const { return row[index(v)]; }
};

/// The (p+2)-th differences of the fields at one point (fd::difference): shared by the upwind
/// stencils (fd::advect_from) and the dissipation.
using Differences = PerVar;

/// All of point_data at order p with the upwind pair `upwind` for the rows of `fields` (a
/// formulation's, with its matter's), with the per-point grid factors passed in (the hot loop);
/// `ko` receives the (p+2)-th differences.
template <int p, fd::Upwind upwind, Fields fields>
[[gnu::always_inline]] inline PointData gather(const Rows u, std::size_t i, double r, double inv_r,
                                               double inv_dx, double inv_rx, double d2_fx,
                                               Differences& ko) {
  const double d1_scale = inv_dx * inv_rx;
  const double d2_scale = inv_dx * inv_dx * inv_rx * inv_rx;
  PointData pd;
  pd.r = r;
  pd.inv_r = inv_r;
  pd.inv_dr = d1_scale;
  // beta d_r f, upwinded by the pair `upwind`; the map factor 1/r_x is positive, so the direction
  // is that of the shift in x as well. Each upwind stencil is the pair's sum and the (p+2)-th
  // difference.
  const double beta_r = u[Var::beta][i] * d1_scale;
  constexpr std::size_t n_fields = fields.size();
#pragma GCC unroll 16 // unrolled, so that the point loop around it vectorises
  for (std::size_t k = 0; k < n_fields; ++k) {
    const Var v = fields.rows()[k].var;
    const double* f = u[v] + i;
    pd.f[v] = f[0];
    // f_r = f_x / r_x;  f_rr = f_xx / r_x^2 - f_x r_xx / r_x^3
    pd.d[v] = fd::d1_centred<p>(f) * d1_scale;
    pd.dd[v] = fd::d2_centred<p>(f) * d2_scale + fd::d1_centred<p>(f) * inv_dx * d2_fx;
    ko[v] = fd::difference<p>(f);
    pd.adv[v] = fd::advect_from<p, upwind>(beta_r, fd::upwind_sum<p, upwind>(f), ko[v]);
  }
  return pd;
}

} // namespace point_loop

template <fd::Upwind upwind>
void GbssnRhs::evaluate_with(const State& u, State& dudt, double t) {
  with_order(grid_->fd_order(), [&]<int p>() { evaluate<p, upwind>(u, dudt, t); });
}

template <int p, fd::Upwind upwind>
void GbssnRhs::evaluate(const State& u, State& dudt, double t) {
  dudt.fit(u);
  const HorizonShiftParams& hs = params_.horizon_shift;
  if (hs.active()) {
    if (source_)
      h_AH_ = source_(u, *grid_, t, evaluations_, h_AH_);
    shift_amplitude_ = shift_amplitude(t);
  }
  if (u.fields() != Fields(params_.formulation, params_.matter))
    throw std::logic_error("a right-hand side given a state of other fields");
  // compiled in the formulation's own source file (gbssn/rhs_interior.hpp)
  with_formulation(params_.formulation,
                   [&]<Formulation f>() { interior_of<f, p, upwind>(u, dudt); });
  const std::size_t n_fields = u.vars().size();
  if (outer_from_parent_) // n_ghost zeros a row, stored in place (a call of memset each cost more)
    for (std::size_t v = 0; v < n_fields; ++v) {
      double* const ghosts = dudt.data() + v * grid_->n_total() + grid_->end_interior();
      for (std::size_t i = 0; i < Grid::n_ghost; ++i)
        ghosts[i] = 0.0;
    }
  else
    outer_boundary(u, dudt);
  origin_ghosts(dudt);
  ++evaluations_;
}

namespace point_loop {

/// One block of the point loop. Its input rows (the fields, with the full shift in place of
/// beta when the horizon shift is on, and beta_GD; each with the stencils' halo of R points on
/// each side) are copied into one scratch array `buf` at compile-time offsets, so that the point
/// loop addresses them all from one base register: with 10 input and 4 grid rows as separate
/// pointers (and the 9 output rows) the loop spent about 17% of its time reloading pointers
/// (profile). Its grid factors are laid out once per grid (`grid`, GbssnRhs::grid_blocks_).
/// Results are unchanged bit for bit.
struct Block {
  Rows in;
  const double *beta_GD, *r, *inv_r, *inv_rx, *d2_fx;
};
/// What the full shift beta_GD + beta_H is formed from, on the whole grid (full_shift_on).
struct FullShift {
  ShiftNormal normal;
  const double *profile, *chi, *a;
  double amplitude, chi_smooth;
};
template <std::size_t R, std::size_t B, Fields fields, bool with_beta_GD>
[[gnu::always_inline]] inline Block stage_block(const Rows& in_full, const FullShift& shift,
                                                double* buf, std::size_t i0, std::size_t n,
                                                const double* grid) {
  constexpr std::size_t W = B + 2 * R; // block with the halo
  constexpr std::size_t n_fields = fields.size();
  Block b{in_full, buf + n_fields * W + R, grid, grid + B, grid + 2 * B, grid + 3 * B};
  constexpr std::size_t beta = index(Var::beta);
  static_assert(fields.slot(Var::beta) == beta);
  // the rows at their slots in buf
  for (std::size_t k = 0; k < n_fields; ++k) {
    const std::size_t v = index(fields.rows()[k].var);
    if (!with_beta_GD || v != beta)
      std::copy(in_full.row[v] + i0 - R, in_full.row[v] + i0 + n + R, buf + k * W);
  }
#pragma GCC unroll 16 // compile-time offsets from buf, one base register in the point loop
  for (std::size_t k = 0; k < n_fields; ++k)
    b.in.row[index(fields.rows()[k].var)] = buf + k * W + R;
  if constexpr (with_beta_GD) { // the horizon shift's evolved part; otherwise beta itself
    const std::size_t from = i0 - R, count = n + 2 * R;
    std::copy(in_full.row[beta] + from, in_full.row[beta] + from + count, buf + n_fields * W);
    // the full shift, formed here: no pass over the grid before the loop, no row to copy
    full_shift_on(shift.normal, count, shift.profile + from, shift.chi + from, shift.a + from,
                  shift.amplitude, shift.chi_smooth, in_full.row[beta] + from, buf + beta * W);
  }
  return b;
}

/// d_t u = 0 on the first `cells` interior cells of each of the n_fields rows from `out` (a
/// multiple of `vector` cells: whole 64-byte stores; the count and the row in locals, which a
/// store through double* would otherwise make the loop reload after every store).
template <std::size_t n_fields, std::size_t vector>
inline void zero_below(double* const out, const std::size_t nt, const std::size_t cells) {
  for (std::size_t v = 0; v < n_fields; ++v)
    for (std::size_t i = 0; i < cells; i += vector)
      std::memset(out + v * nt + i, 0, vector * sizeof(double));
}

/// The two beta d_r Delta^r terms, each with its stencil (AdvectionParams): (E6)'s into
/// p.adv[Delta_r], and B's driver term gd.adv_Delta_r, with the `matched` stencil (E6)'s own
/// term minus beta_H d_r Delta^r centred, so that B - Delta^r sees no lopsided stencil
/// (AdvectionStencil::matched).
template <int order, fd::Upwind upwind>
[[gnu::always_inline]] inline void
advect_Delta(PointData& p, Shift& gd, const double* Delta, double ko_Delta, double d1_scale,
             const StencilWeights& delta_w, const StencilWeights& driver_w) {
  p.adv[Var::Delta_r] =
      p.f[Var::beta] * d1_scale
      * delta_derivative<order, upwind>(delta_w, Delta, gd.beta, p.f[Var::beta], ko_Delta);
  const double beta_H = p.f[Var::beta] - gd.beta;
  gd.adv_Delta_r =
      gd.beta * d1_scale
          * delta_derivative<order, upwind>(driver_w, Delta, gd.beta, p.f[Var::beta], ko_Delta)
      + driver_w.matched * (p.adv[Var::Delta_r] - beta_H * d1_scale * fd::d1_centred<order>(Delta));
}

} // namespace point_loop

template <class Equations, class M, int order, fd::Upwind upwind, bool with_horizon_shift>
void GbssnRhs::interior(const Equations& equations, const State& u, State& dudt) const {
  using namespace point_loop;
  const Grid& g = *grid_;
  const std::size_t nt = g.n_total();
  // With the horizon shift every term sees the full shift beta_GD + beta_H ... (formed block
  // by block as the blocks are staged: stage_block)
  const Rows in_full(u, g);
  const HorizonShiftParams& hs = params_.horizon_shift;
  const FullShift full_shift_rows{hs.normal,       profile_.data(),  in_full[Var::chi],
                                  in_full[Var::a], shift_amplitude_, hs.chi_smooth};
  const double inv_dx = 1.0 / g.dx();
  // Kreiss-Oliger dissipation: sigma/dx x the (p+2)-th difference, signed and normalised so
  // that the highest grid mode decays at the rate sigma/dx (fd::Order)
  const double ko_scale = params_.ko_sigma * fd::Order<order>::dissipation_sign
                          * fd::Order<order>::dissipation_norm * inv_dx;
  const Gauge gauge = params_.gauge;
  const StencilWeights driver_w(params_.advection.driver), delta_w(params_.advection.delta);
  constexpr std::size_t R = fd::Order<order>::radius;
  static_assert(R <= Grid::n_ghost, "the stencils reach beyond the ghosts");
  // blocks of B points, each with the stencils' halo: W points of each input row (stage_block)
  constexpr std::size_t B = block_size, W = B + 2 * R;
  constexpr Fields fields(Equations::formulation, M::matter);
  constexpr std::size_t n_fields = fields.size(), rows_in = n_fields + 1, rows_grid = 4;
  thread_local std::vector<double> scratch(rows_in * W); // one per thread
  double* const buf = scratch.data();
  // Cells below the first cell (under a child box, set_first_cell): d_t u = 0. The first block
  // starts at the first cell, inside its block of grid factors, so that the loop itself starts
  // at 0 (a loop from a run-time start held 3.6 times the spilled registers: 8% slower on a
  // single grid, which never skips).
  zero_below<n_fields, vector_points>(dudt.data() + g.first_interior(), nt, first_cell_);
  for (std::size_t i0 = g.first_interior() + first_cell_, n = 0; i0 < g.end_interior(); i0 += n) {
    const std::size_t k = i0 - g.first_interior(), offset = k % B; // 0 but in the first block
    n = std::min(B - offset, g.end_interior() - i0);
    const Block blk = stage_block<R, B, fields, with_horizon_shift>(
        in_full, full_shift_rows, buf, i0, n, grid_blocks_.data() + k / B * rows_grid * B + offset);
    const Rows in = blk.in;
    const double *const beta_GD = blk.beta_GD, *const r = blk.r, *const inv_r = blk.inv_r,
                        *const inv_rx = blk.inv_rx, *const d2_fx = blk.d2_fx;
    double* const out0 = dudt.data() + i0; // the output row of slot k: out0 + k nt
    const std::size_t begin = 0, end = n;
    // The output never aliases the input, which `ivdep` asserts: the loop vectorises across
    // points.
#pragma GCC ivdep
    for (std::size_t i = begin; i < end; ++i) {
      Differences k6;
      PointData p =
          gather<order, upwind, fields>(in, i, r[i], inv_r[i], inv_dx, inv_rx[i], d2_fx[i], k6);
      const double d1_scale = inv_dx * inv_rx[i];
      // The shift whose d_t Delta^r drives B: the full shift for the plain Gamma-driver,
      // beta_GD alone with the horizon shift (H2).
      Shift gd = full_shift(p);
      const double* f = beta_GD + i;
      if constexpr (with_horizon_shift) {
        gd.beta = f[0];
        gd.d_beta = fd::d1_centred<order>(f) * d1_scale;
        gd.dd_beta = fd::d2_centred<order>(f) * d1_scale * d1_scale
                     + fd::d1_centred<order>(f) * inv_dx * d2_fx[i];
      }
      advect_Delta<order, upwind>(p, gd, in[Var::Delta_r] + i, k6[Var::Delta_r], d1_scale, delta_w,
                                  driver_w);
      if constexpr (with_horizon_shift) {
        // beta_GD is the evolved field: (G2) advects it, and it is what dissipation damps
        k6[Var::beta] = fd::difference<order>(f);
        p.adv[Var::beta] = fd::advect_from<order, upwind>(
            p.f[Var::beta] * d1_scale, fd::upwind_sum<order, upwind>(f), k6[Var::beta]);
      }
      const Rhs rhs = equations.template rhs<M>(p, gauge, gd);
      const double ko = ko_scale * inv_rx[i];
#pragma GCC unroll 16
      for (std::size_t k = 0; k < n_fields; ++k) {
        const std::size_t v = index(fields.rows()[k].var);
        out0[k * nt + i] = rhs.values[v] + ko * k6.values[v];
      }
    }
  }
}

} // namespace gbssn1d
