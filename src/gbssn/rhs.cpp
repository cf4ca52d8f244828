#include "gbssn/rhs.hpp"

#include "fd/stencils.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>

namespace gbssn1d {

namespace {

/// An AdvectionStencil as 0/1 weights of the three stencils (branch-free, so that the point
/// loop vectorises).
struct StencilWeights {
  double centred = 0.0, upwind_gd = 0.0, upwind_full = 0.0;
  explicit StencilWeights(AdvectionStencil s)
      : centred(s == AdvectionStencil::centred ? 1.0 : 0.0),
        upwind_gd(s == AdvectionStencil::upwind_gd ? 1.0 : 0.0),
        upwind_full(s == AdvectionStencil::upwind_full ? 1.0 : 0.0) {}
};

/// d_x Delta^r (times dx) by the weighted stencil; `beta_gd`, `beta_full` give the upwind
/// directions; `ko6` is fd::ko6(f).
[[gnu::always_inline]] inline double delta_derivative(const StencilWeights& w, const double* f,
                                                      double beta_gd, double beta_full,
                                                      double ko6) {
  const double half_sum = 0.5 * fd::lopsided_sum(f), half_diff = (1.0 / 24.0) * ko6;
  const double sign_gd = beta_gd > 0.0 ? 1.0 : -1.0, sign_full = beta_full > 0.0 ? 1.0 : -1.0;
  return w.centred * fd::d1_centred(f) + w.upwind_gd * (half_sum + sign_gd * half_diff)
         + w.upwind_full * (half_sum + sign_full * half_diff);
}

/// Pointers to the start of each variable's array, by name (passed by value, so that the
/// compiler keeps them in registers in the point loop).
struct Rows {
  const double *alpha, *beta, *B, *chi, *a, *b, *K, *A_a, *Delta_r;
  Rows(const State& u, const Grid& grid) {
    auto row = [&](Var v) { return u.data() + index(v) * grid.n_total(); };
    alpha = row(Var::alpha);
    beta = row(Var::beta);
    B = row(Var::B);
    chi = row(Var::chi);
    a = row(Var::a);
    b = row(Var::b);
    K = row(Var::K);
    A_a = row(Var::A_a);
    Delta_r = row(Var::Delta_r);
  }
};

/// The 6th differences of the fields at one point (fd::ko6), in registry order: shared by the
/// upwind stencils (fd::advect_from) and the dissipation.
using Ko6 = std::array<double, n_vars>;

/// All of point_data, with the per-point grid factors passed in (the hot loop); `ko` receives
/// the 6th differences.
[[gnu::always_inline]] inline PointData gather(const Rows u, std::size_t i, double r, double inv_r,
                                               double inv_dx, double inv_rx, double d2_fx,
                                               Ko6& ko) {
  const double d1_scale = inv_dx * inv_rx;
  const double d2_scale = inv_dx * inv_dx * inv_rx * inv_rx;
  const double* alpha = u.alpha + i;
  const double* beta = u.beta + i;
  const double* B = u.B + i;
  const double* chi = u.chi + i;
  const double* a = u.a + i;
  const double* b = u.b + i;
  const double* K = u.K + i;
  const double* A_a = u.A_a + i;
  const double* Delta_r = u.Delta_r + i;

  // f_r = f_x / r_x;  f_rr = f_xx / r_x^2 - f_x r_xx / r_x^3
  auto first = [&](const double* f) { return fd::d1_centred(f) * d1_scale; };
  auto second = [&](const double* f) {
    return fd::d2_centred(f) * d2_scale + fd::d1_centred(f) * inv_dx * d2_fx;
  };

  PointData p;
  p.r = r;
  p.inv_r = inv_r;
  p.alpha = alpha[0];
  p.beta = beta[0];
  p.B = B[0];
  p.chi = chi[0];
  p.a = a[0];
  p.b = b[0];
  p.K = K[0];
  p.A_a = A_a[0];
  p.Delta_r = Delta_r[0];

  p.d_alpha = first(alpha);
  p.d_beta = first(beta);
  p.d_B = first(B);
  p.d_chi = first(chi);
  p.d_a = first(a);
  p.d_b = first(b);
  p.d_K = first(K);
  p.d_A_a = first(A_a);
  p.d_Delta_r = first(Delta_r);

  p.dd_alpha = second(alpha);
  p.dd_beta = second(beta);
  p.dd_chi = second(chi);
  p.dd_a = second(a);
  p.dd_b = second(b);

  // beta d_r f, lopsided upwind; the map factor 1/r_x is positive, so the direction is that of
  // the shift in x as well. Each upwind stencil is the lopsided sum and the 6th difference.
  const double beta_r = p.beta * d1_scale;
  auto advect = [&](Var v, const double* f) {
    ko[index(v)] = fd::ko6(f);
    return fd::advect_from(beta_r, fd::lopsided_sum(f), ko[index(v)]);
  };
  p.adv_alpha = advect(Var::alpha, alpha);
  p.adv_beta = advect(Var::beta, beta);
  p.adv_B = advect(Var::B, B);
  p.adv_chi = advect(Var::chi, chi);
  p.adv_a = advect(Var::a, a);
  p.adv_b = advect(Var::b, b);
  p.adv_K = advect(Var::K, K);
  p.adv_A_a = advect(Var::A_a, A_a);
  p.adv_Delta_r = advect(Var::Delta_r, Delta_r);
  return p;
}

} // namespace

PointData point_data(const State& u, const Grid& grid, std::size_t i) {
  Ko6 ko;
  return gather(Rows(u, grid), i, grid.r()[i], grid.inv_r()[i], 1.0 / grid.dx(),
                grid.inv_dr_dx()[i], grid.d2_fx_coeff()[i], ko);
}

namespace {

/// f(r_i / w) on every point.
std::vector<double> profile_on(const Grid& grid, const HorizonShiftParams& params) {
  std::vector<double> f(grid.n_total());
  for (std::size_t i = 0; i < f.size(); ++i)
    f[i] = shift_profile(params.profile, grid.r()[i] / params.width); // odd
  return f;
}

/// beta_H = f amplitude s^r (H3) on n points, and beta_full = beta_GD + beta_H if given; one
/// loop per normal, so that each vectorises.
template <ShiftNormal normal>
void fill_horizon_shift(std::size_t n, const double* f, const double* chi, const double* a,
                        double amplitude, double chi_smooth, double* beta_H,
                        const double* beta_GD = nullptr, double* beta_full = nullptr) {
  for (std::size_t i = 0; i < n; ++i) {
    beta_H[i] = f[i] * amplitude * shift_normal(normal, chi[i], a[i], chi_smooth); // s^r even
    if (beta_full)
      beta_full[i] = beta_GD[i] + beta_H[i];
  }
}

void fill_horizon_shift(ShiftNormal normal, std::size_t n, const double* f, const double* chi,
                        const double* a, double amplitude, double chi_smooth, double* beta_H,
                        const double* beta_GD = nullptr, double* beta_full = nullptr) {
  switch (normal) { // dispatched once per call
  case ShiftNormal::conformal:
    return fill_horizon_shift<ShiftNormal::conformal>(n, f, chi, a, amplitude, chi_smooth, beta_H,
                                                      beta_GD, beta_full);
  case ShiftNormal::smooth:
    return fill_horizon_shift<ShiftNormal::smooth>(n, f, chi, a, amplitude, chi_smooth, beta_H,
                                                   beta_GD, beta_full);
  case ShiftNormal::unit:
  default:
    return fill_horizon_shift<ShiftNormal::unit>(n, f, chi, a, amplitude, chi_smooth, beta_H,
                                                 beta_GD, beta_full);
  }
}

} // namespace

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

void horizon_shift_profile(const State& u, const Grid& grid, const HorizonShiftParams& params,
                           std::optional<double> h_AH, std::vector<double>& beta_H, double t) {
  beta_H.assign(grid.n_total(), 0.0);
  if (!h_AH || params.A == 0.0)
    return;
  const double amplitude = params.strength(t) * (*h_AH - params.h);
  fill_horizon_shift(params.normal, grid.n_total(), profile_on(grid, params).data(),
                     field(u, grid, Var::chi).data(), field(u, grid, Var::a).data(), amplitude,
                     params.chi_smooth, beta_H.data());
}

void GbssnRhs::split_shift(const State& u, double t) {
  const HorizonShiftParams& hs = params_.horizon_shift;
  const std::size_t n = grid_->n_total();
  beta_H_.resize(n);
  beta_full_.resize(n);
  const auto beta_GD = field(u, *grid_, Var::beta);
  // without a horizon beta_H = 0 (amplitude 0 keeps the same loop)
  const double amplitude = h_AH_ ? hs.strength(t) * (*h_AH_ - hs.h) : 0.0;
  fill_horizon_shift(hs.normal, n, profile_.data(), field(u, *grid_, Var::chi).data(),
                     field(u, *grid_, Var::a).data(), amplitude, hs.chi_smooth, beta_H_.data(),
                     beta_GD.data(), beta_full_.data());
}

void GbssnRhs::operator()(const State& u, State& dudt, double t) {
  dudt.resize(u.size());
  const HorizonShiftParams& hs = params_.horizon_shift;
  if (!hs.active()) {
    interior<false>(u, dudt);
  } else {
    const bool in_window = t >= hs.t_min && (hs.t_max < 0.0 || t <= hs.t_max);
    const bool midstep_search =
        hs.variant == HorizonShiftParams::Variant::midstep_update
        && evaluations_ % static_cast<std::uint64_t>(4 * hs.midstep_every) == 1;
    if (hs.prescribed()) {
      h_AH_ = hs.prescribed_h_AH(t); // open loop: the same h_AH(t) at every resolution
    } else if ((hs.search_every_substage || midstep_search) && in_window) {
      h_AH_ = hs.locate ? hs.locate(u, *grid_, h_AH_.value_or(hs.h), t) : std::nullopt;
    }
    split_shift(u, t);
    using V = HorizonShiftParams::Variant;
    switch (hs.variant) { // dispatched once per call, not per point
    case V::consistent:
    case V::midstep_update: // differs only in when h_AH is searched
      interior<true, V::consistent>(u, dudt);
      break;
    case V::no_shift_derivatives:
      interior<true, V::no_shift_derivatives>(u, dudt);
      break;
    case V::no_shift_second_derivatives:
      interior<true, V::no_shift_second_derivatives>(u, dudt);
      break;
    case V::delta_rhs_from_gd:
      interior<true, V::delta_rhs_from_gd>(u, dudt);
      break;
    case V::driver_full_shift:
      interior<true, V::driver_full_shift>(u, dudt);
      break;
    }
  }
  outer_boundary(u, dudt);
  origin_ghosts(dudt);
  ++evaluations_;
}

template <bool with_horizon_shift, HorizonShiftParams::Variant variant>
void GbssnRhs::interior(const State& u, State& dudt) const {
  const Grid& g = *grid_;
  const std::size_t nt = g.n_total();
  // With the horizon shift every term sees the full shift beta_GD + beta_H ...
  Rows in_full(u, g);
  const double* const beta_GD_full = in_full.beta;
  if constexpr (with_horizon_shift)
    in_full.beta = beta_full_.data();
  const double inv_dx = 1.0 / g.dx();
  const double ko_scale = params_.ko_sigma / 64.0 * inv_dx;
  const GaugeParams gauge = params_.gauge;
  const StencilWeights driver_w(params_.advection.driver), delta_w(params_.advection.delta);
  // The points are taken in blocks of B. Each block's input rows (the fields, with the full
  // shift in place of beta when the horizon shift is on, and beta_GD; each with the stencils'
  // halo of 3 on each side) and its grid factors are first copied into one scratch array at
  // compile-time offsets, so that the point loop addresses them all from one base register:
  // with 10 input and 4 grid rows as separate pointers (and the 9 output rows) the loop spent
  // about 17% of its time reloading pointers (profile). Results are unchanged bit for bit.
  constexpr std::size_t B = block_size, W = B + 6; // block, and block with the halo
  constexpr std::size_t rows_in = n_vars + 1, rows_grid = 4;
  thread_local std::vector<double> scratch(rows_in * W); // one per thread
  double* const buf = scratch.data();
  const double* full_rows[rows_in] = {in_full.alpha,   in_full.beta, in_full.B, in_full.chi,
                                      in_full.a,       in_full.b,    in_full.K, in_full.A_a,
                                      in_full.Delta_r, beta_GD_full};
  for (std::size_t i0 = g.first_interior(); i0 < g.end_interior(); i0 += B) {
    const std::size_t n = std::min(B, g.end_interior() - i0);
    for (std::size_t v = 0; v < rows_in; ++v)
      std::copy(full_rows[v] + i0 - 3, full_rows[v] + i0 + n + 3, buf + v * W);
    Rows in = in_full;
    in.alpha = buf + 0 * W + 3;
    in.beta = buf + 1 * W + 3;
    in.B = buf + 2 * W + 3;
    in.chi = buf + 3 * W + 3;
    in.a = buf + 4 * W + 3;
    in.b = buf + 5 * W + 3;
    in.K = buf + 6 * W + 3;
    in.A_a = buf + 7 * W + 3;
    in.Delta_r = buf + 8 * W + 3;
    const double* const beta_GD = buf + 9 * W + 3;
    // the grid factors of this block, laid out once per grid (grid_blocks_)
    const double* const grid = grid_blocks_.data() + (i0 - g.first_interior()) / B * rows_grid * B;
    const double* const r = grid + 0 * B;
    const double* const inv_r = grid + 1 * B;
    const double* const inv_rx = grid + 2 * B;
    const double* const d2_fx = grid + 3 * B;
    double* const out0 = dudt.data() + i0;
    double* const out_alpha = out0 + 0 * nt;
    double* const out_beta = out0 + 1 * nt;
    double* const out_B = out0 + 2 * nt;
    double* const out_chi = out0 + 3 * nt;
    double* const out_a = out0 + 4 * nt;
    double* const out_b = out0 + 5 * nt;
    double* const out_K = out0 + 6 * nt;
    double* const out_A_a = out0 + 7 * nt;
    double* const out_Delta_r = out0 + 8 * nt;
    const std::size_t begin = 0, end = n;
    // The output never aliases the input, which `ivdep` asserts: the loop vectorises across
    // points.
#pragma GCC ivdep
    for (std::size_t i = begin; i < end; ++i) {
      Ko6 k6;
      PointData p = gather(in, i, r[i], inv_r[i], inv_dx, inv_rx[i], d2_fx[i], k6);
      const double d1_scale = inv_dx * inv_rx[i];
      // The shift whose d_t Delta^r drives B: the full shift for the plain Gamma-driver,
      // beta_GD alone with the horizon shift (H2).
      Shift gd = full_shift(p);
      const double* f = beta_GD + i;
      if constexpr (with_horizon_shift) {
        gd.beta = f[0];
        gd.d_beta = fd::d1_centred(f) * d1_scale;
        gd.dd_beta =
            fd::d2_centred(f) * d1_scale * d1_scale + fd::d1_centred(f) * inv_dx * d2_fx[i];
      }
      // The two beta d_r Delta^r terms, each with its stencil (AdvectionParams).
      const double* Delta = in.Delta_r + i;
      const double ko_Delta = k6[index(Var::Delta_r)];
      gd.adv_Delta_r =
          gd.beta * d1_scale * delta_derivative(driver_w, Delta, gd.beta, p.beta, ko_Delta);
      p.adv_Delta_r =
          p.beta * d1_scale * delta_derivative(delta_w, Delta, gd.beta, p.beta, ko_Delta);
      Rhs rhs;
      if constexpr (with_horizon_shift) {
        using Variant = HorizonShiftParams::Variant;
        if constexpr (variant == Variant::no_shift_derivatives) {
          p.d_beta = gd.d_beta; // the full shift's value, but beta_GD's derivatives
          p.dd_beta = gd.dd_beta;
        } else if constexpr (variant == Variant::no_shift_second_derivatives) {
          p.dd_beta = gd.dd_beta;
        } else if constexpr (variant == Variant::driver_full_shift) {
          gd = full_shift(p);
        }
        // beta_GD is the evolved field: (G2) advects it, and it is what dissipation damps
        k6[index(Var::beta)] = fd::ko6(f);
        p.adv_beta = fd::advect_from(p.beta * d1_scale, fd::lopsided_sum(f), k6[index(Var::beta)]);
        rhs = gbssn_rhs(p, gauge, gd);
        if constexpr (variant == Variant::delta_rhs_from_gd)
          rhs.Delta_r = rhs_Delta_r(p, metric_pieces(p), gd);
      } else {
        rhs = gbssn_rhs(p, gauge, gd);
      }
      const double ko = ko_scale * inv_rx[i];
      out_alpha[i] = rhs.alpha + ko * k6[index(Var::alpha)];
      out_beta[i] = rhs.beta + ko * k6[index(Var::beta)];
      out_B[i] = rhs.B + ko * k6[index(Var::B)];
      out_chi[i] = rhs.chi + ko * k6[index(Var::chi)];
      out_a[i] = rhs.a + ko * k6[index(Var::a)];
      out_b[i] = rhs.b + ko * k6[index(Var::b)];
      out_K[i] = rhs.K + ko * k6[index(Var::K)];
      out_A_a[i] = rhs.A_a + ko * k6[index(Var::A_a)];
      out_Delta_r[i] = rhs.Delta_r + ko * k6[index(Var::Delta_r)];
    }
  }
}

void GbssnRhs::outer_boundary(const State& u, State& dudt) const {
  // Sec. 8: d_t f = -v [ d_r f + n (f - f_inf) / r ], one-sided derivatives, on the ghost cells.
  const Grid& g = *grid_;
  const std::size_t nt = g.n_total();
  const double inv_dx = 1.0 / g.dx();
  for (const auto& entry : registry) {
    const double* f = u.data() + index(entry.var) * nt;
    double* out = dudt.data() + index(entry.var) * nt;
    for (std::size_t i = g.end_interior(); i < nt; ++i) {
      const double d_r_f = fd::d1_backward(f + i) * inv_dx * g.inv_dr_dx()[i];
      out[i] = -entry.speed * (d_r_f + entry.falloff * (f[i] - entry.asymptotic) * g.inv_r()[i]);
    }
  }
}

void GbssnRhs::origin_ghosts(State& dudt) const {
  fill_origin_ghosts(dudt, *grid_);
}

} // namespace gbssn1d
