// Time interpolation of the data that fills a fine level's outer ghosts (and buffer) from the
// coarser level (mesh/hierarchy.hpp has the design note). Each is a linear combination of
// stored coarse arrays; these functions give its weights.
#pragma once

#include <array>

namespace gbssn1d::mesh {

/// Weights (of u0, k1, k2, k3, k4) of a coarse RK4 step u0 -> u0 + dt (k1 + 2 k2 + 2 k3 + k4)/6
/// with stage derivatives k_i = f(Y_i). The coarse step's solution as a cubic in
/// theta = (t - t0) / dt (the RK4 continuous extension, Hairer, Norsett & Wanner I, II.6):
///   u(theta) = u0 + theta K1 + theta^2 / 2 D2 + theta^3 / 6 D3, with K_i = dt k_i,
///   D2 = -3 K1 + 2 K2 + 2 K3 - K4 ~ dt^2 u'',  D3 = 4 (K1 - K2 - K3 + K4) ~ dt^3 u''',
/// and J = 4 (K3 - K2) ~ dt^3 f_u u'' (McCorquodale & Colella 2011, Sec. 3).
using StageWeights = std::array<double, 5>;

namespace detail {
inline constexpr StageWeights u0{1, 0, 0, 0, 0}, K1{0, 1, 0, 0, 0}, D2{0, -3, 2, 2, -1},
    D3{0, 4, -4, -4, 4}, J{0, 0, -4, 4, 0};
constexpr StageWeights axpy(StageWeights y, double a, const StageWeights& x) {
  for (std::size_t m = 0; m < 5; ++m)
    y[m] += a * x[m];
  return y;
}
/// From weights of (u0, K1..K4) to weights of (u0, k1..k4).
constexpr StageWeights times_dt(StageWeights w, double dt) {
  for (std::size_t m = 1; m < 5; ++m)
    w[m] *= dt;
  return w;
}
/// dt^n times the n-th derivative of the cubic at theta, in (u0, K) weights.
constexpr StageWeights taylor(double theta, int n) {
  switch (n) {
  case 0:
    return axpy(axpy(axpy(u0, theta, K1), theta * theta / 2, D2), theta * theta * theta / 6, D3);
  case 1:
    return axpy(axpy(K1, theta, D2), theta * theta / 2, D3);
  case 2:
    return axpy(D2, theta, D3);
  default:
    return D3;
  }
}
} // namespace detail

/// The coarse step's dense output at theta (exact for solutions that are cubics in t).
constexpr StageWeights dense_output_weights(double theta, double dt) {
  return detail::times_dt(detail::taylor(theta, 0), dt);
}

/// The input Y_s (s = 0 ... 3) of stage s + 1 of a fine RK4 step of size ratio x dt starting at
/// theta, Taylor-expanded to dt^3 (McCorquodale & Colella 2011, Sec. 3; Mongwane 2015;
/// derived again in tests/mesh/test_time_interpolation.cpp's comment):
///   Y1 = U,  Y2 = U + h/2 U',  Y3 = U + h/2 U' + h^2/4 U'' + h^3/16 (U''' - f_u U''),
///   Y4 = U + h U' + h^2/2 U'' + h^3/8 (U''' + f_u U''),
/// with h = ratio dt and U, U', ... the cubic's values at theta.
namespace detail {
/// Stage s's weights from the cubic's Taylor terms U, A1, A2, A3 at theta (rk_stage_weights).
constexpr StageWeights stage_weights(const std::array<StageWeights, 4>& taylor_terms, double ratio,
                                     int stage, double dt) {
  const auto& [U, A1, A2, A3] = taylor_terms;
  const double r = ratio, r2 = r * r, r3 = r2 * r;
  StageWeights w = U;
  switch (stage) {
  case 0:
    break;
  case 1:
    w = axpy(U, r / 2, A1);
    break;
  case 2:
    w = axpy(axpy(axpy(axpy(U, r / 2, A1), r2 / 4, A2), r3 / 16, A3), -r3 / 16, J);
    break;
  default:
    w = axpy(axpy(axpy(axpy(U, r, A1), r2 / 2, A2), r3 / 8, A3), r3 / 8, J);
    break;
  }
  return times_dt(w, dt);
}
constexpr std::array<StageWeights, 4> taylor_terms(double theta) {
  return {taylor(theta, 0), taylor(theta, 1), taylor(theta, 2), taylor(theta, 3)};
}
} // namespace detail

constexpr StageWeights rk_stage_weights(double theta, double ratio, int stage, double dt) {
  return detail::stage_weights(detail::taylor_terms(theta), ratio, stage, dt);
}

/// rk_stage_weights of the four stages of one fine step at once (the Taylor terms once).
constexpr std::array<StageWeights, 4> rk_stage_weights_all(double theta, double ratio, double dt) {
  const auto terms = detail::taylor_terms(theta);
  return {detail::stage_weights(terms, ratio, 0, dt), detail::stage_weights(terms, ratio, 1, dt),
          detail::stage_weights(terms, ratio, 2, dt), detail::stage_weights(terms, ratio, 3, dt)};
}

/// The times of a classical RK4 stage s = 0 ... 3, in units of the step.
inline constexpr std::array<double, 4> rk4_stage_times{0.0, 0.5, 0.5, 1.0};

/// Lagrange weights at t of the time levels t0 < t1 < t2 (quadratic; exact for quadratics in
/// t). At a level the weights are exactly (0, .., 1, .., 0).
constexpr std::array<double, 3> quadratic_weights(double t0, double t1, double t2, double t) {
  return {(t - t1) * (t - t2) / ((t0 - t1) * (t0 - t2)),
          (t - t0) * (t - t2) / ((t1 - t0) * (t1 - t2)),
          (t - t0) * (t - t1) / ((t2 - t0) * (t2 - t1))};
}

/// Linear weights at t of the levels t0 < t1 (while only two exist).
constexpr std::array<double, 2> linear_weights(double t0, double t1, double t) {
  return {(t1 - t) / (t1 - t0), (t - t0) / (t1 - t0)};
}

} // namespace gbssn1d::mesh
