// Time interpolation of fine-level boundary data: quadratic Lagrange weights exact for
// quadratics in t; the RK4 dense output exact for cubics; the RK4 stage method reproducing the
// stages of a fine RK4 step exactly when the solution is a cubic in t, and to O(dt^4) for a
// nonlinear equation.
//
// The stage method, derived for u' = f(u): with a fine step h from U = u(t*), the RK4 stage
// inputs are Y1 = U, Y2 = U + h/2 f(U), Y3 = U + h/2 f(Y2), Y4 = U + h f(Y3); expanding f about U
// (u'' = f_u u', u''' = f_u f_u u' + f_uu(u', u')) gives
//   Y3 = U + h/2 U' + h^2/4 U'' + h^3/16 (U''' - f_u U''),
//   Y4 = U + h U' + h^2/2 U'' + h^3/8 (U''' + f_u U''),
// and the coarse step's stages give dt^3 f_u u'' = 4 (K3 - K2) + O(dt^4).
#include "mesh/time_interpolation.hpp"

#include "../test_support.hpp"

#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <functional>
#include <vector>

using namespace gbssn1d::mesh;
using gbssn1d::testing::fit_order;

namespace {

/// A coarse RK4 step of u' = f(t, u) from (t0, u0): u0 and the stage derivatives k1 ... k4.
std::array<double, 5> coarse_step(const std::function<double(double, double)>& f, double t0,
                                  double u0, double dt) {
  const double k1 = f(t0, u0), k2 = f(t0 + dt / 2, u0 + dt / 2 * k1),
               k3 = f(t0 + dt / 2, u0 + dt / 2 * k2), k4 = f(t0 + dt, u0 + dt * k3);
  return {u0, k1, k2, k3, k4};
}

double combine(const StageWeights& w, const std::array<double, 5>& x) {
  double s = 0.0;
  for (std::size_t m = 0; m < 5; ++m)
    s += w[m] * x[m];
  return s;
}

/// The four stage inputs of an RK4 step of size h from (t, U).
std::array<double, 4> fine_stages(const std::function<double(double, double)>& f, double t,
                                  double U, double h) {
  const double y2 = U + h / 2 * f(t, U);
  const double y3 = U + h / 2 * f(t + h / 2, y2);
  const double y4 = U + h * f(t + h / 2, y3);
  return {U, y2, y3, y4};
}

} // namespace

TEST_CASE("quadratic time interpolation is exact for quadratics, linear for lines") {
  const auto q = [](double t) { return 1.0 + 2.0 * t - 3.0 * t * t; };
  const double t0 = 0.1, t1 = 0.35, t2 = 0.6;
  for (double t : {0.1, 0.2, 0.35, 0.475, 0.6}) {
    const auto w = quadratic_weights(t0, t1, t2, t);
    CHECK(w[0] * q(t0) + w[1] * q(t1) + w[2] * q(t2) == doctest::Approx(q(t)).epsilon(1e-14));
    const auto v = linear_weights(t1, t2, t);
    CHECK(v[0] * (3 - t1) + v[1] * (3 - t2) == doctest::Approx(3 - t).epsilon(1e-14));
  }
  // at a time level the weights select it exactly
  const auto w = quadratic_weights(t0, t1, t2, t1);
  CHECK(w[0] == 0.0);
  CHECK(w[1] == 1.0);
  CHECK(w[2] == 0.0);
}

TEST_CASE("dense output and RK4 stage values are exact when the solution is a cubic in t") {
  // u' = p(t), p quadratic: u is a cubic, and RK4's stages are polynomials in t
  const auto p = [](double t, double) { return 0.5 - 1.2 * t + 2.1 * t * t; };
  const auto u = [](double t) { return 0.3 + 0.5 * t - 0.6 * t * t + 0.7 * t * t * t; };
  const double t0 = 0.4, dt = 0.3;
  const auto x = coarse_step(p, t0, u(t0), dt);
  for (double theta : {0.0, 0.25, 0.5, 1.0})
    CHECK(combine(dense_output_weights(theta, dt), x)
          == doctest::Approx(u(t0 + theta * dt)).epsilon(1e-14));
  for (double theta : {0.0, 0.5})
    for (double ratio : {0.5, 1.0}) {
      if (theta + ratio > 1.0)
        continue;
      const double ts = t0 + theta * dt;
      const auto y = fine_stages(p, ts, u(ts), ratio * dt);
      for (int s = 0; s < 4; ++s)
        CHECK(combine(rk_stage_weights(theta, ratio, s, dt), x)
              == doctest::Approx(y[static_cast<std::size_t>(s)]).epsilon(1e-14));
    }
}

TEST_CASE("the four stages' weights at once are each stage's, bit for bit") {
  for (double theta : {0.0, 0.25, 0.5})
    for (double ratio : {0.5, 1.0}) {
      const auto all = rk_stage_weights_all(theta, ratio, 0.3);
      for (int s = 0; s < 4; ++s) {
        const auto one = rk_stage_weights(theta, ratio, s, 0.3);
        for (std::size_t m = 0; m < 5; ++m)
          CHECK(all[static_cast<std::size_t>(s)][m] == one[m]);
      }
    }
}

TEST_CASE("RK4 stage values of a nonlinear equation: local error O(dt^4)") {
  // u' = u^2 + t, from an exact solution: the stage inputs of the fine steps from the coarse
  // stages differ from the true fine RK4 stages (started from the dense output) by O(dt^4) --
  // the (f_u U'') term matters: without it Y3 and Y4 would be off at O(dt^3)
  const auto f = [](double t, double u) { return u * u + t; };
  for (double theta : {0.0, 0.5}) {
    std::vector<double> h;
    std::array<std::vector<double>, 4> err;
    for (double dt : {0.08, 0.04, 0.02, 0.01}) {
      const auto x = coarse_step(f, 0.0, 0.6, dt);
      const double ts = theta * dt, U = combine(dense_output_weights(theta, dt), x);
      const auto y = fine_stages(f, ts, U, 0.5 * dt);
      h.push_back(dt);
      for (int s = 0; s < 4; ++s)
        err[static_cast<std::size_t>(s)].push_back(std::abs(
            combine(rk_stage_weights(theta, 0.5, s, dt), x) - y[static_cast<std::size_t>(s)]));
    }
    // from the step's start the second stage input is exact: U' = k1
    if (theta == 0.0)
      for (double e : err[1])
        CHECK(e < 1e-15);
    for (int s = theta == 0.0 ? 2 : 1; s < 4; ++s) {
      const double order = fit_order(h, err[static_cast<std::size_t>(s)]);
      MESSAGE("theta " << theta << " stage " << s + 1 << ": local order " << order);
      CHECK(order > 3.8);
    }
  }
}
