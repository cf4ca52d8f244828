// Schwarzschild trumpet slices in isotropic radius (equations document, Sec. 9 item 5 and
// Sec. 13). Both solutions are computed in units of M and scaled on output.
#include "initial_data/trumpet_solutions.hpp"

#include "initial_data/trumpet_support.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <boost/math/tools/roots.hpp>
// GCC (12) reports the copy of the steppers' not-yet-used scratch arrays inside Odeint as
// use of uninitialised memory; silence that for the library headers only.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <boost/numeric/odeint.hpp>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

namespace gbssn1d {

namespace {

namespace odeint = boost::numeric::odeint;
using trumpet::require_valid_mass;
using trumpet::require_valid_radius;
using trumpet::solve_bracketed;

// ---------------------------------------------------------------------------------------------
// Stationary 1+log trumpet (Sec. 13), units M = 1:
//   (S1)  F(alpha, R) = alpha^2 - 1 + 2/R - C^2 e^alpha / R^4 = 0,
// with C^2 e^{alpha_c} = R_c^3 / 2 and alpha_c = 1/(4 R_c) at the critical point. Writing
// C^2 e^alpha / R^4 = 2 alpha_c e^{dalpha} (R_c/R)^4 (dalpha = alpha - alpha_c) gives
//   F_R     = (2/R^2) expm1(dalpha - 3 ln(R/R_c)),
//   F_alpha = 2 dalpha - 2 alpha_c expm1(dalpha - 4 ln(R/R_c)),
// free of the cancellation of the plain formulas near the critical point, where both vanish.

/// d alpha / d R = -F_R / F_alpha on a level set of F.
template <class Real>
Real onelog_slope(Real alpha, Real R, Real Rc, Real alpha_c) {
  using std::expm1;
  using std::log1p;
  const Real dalpha = alpha - alpha_c;
  const Real ln_R_Rc = log1p((R - Rc) / Rc);
  const Real F_R = Real(2) / (R * R) * expm1(dalpha - Real(3) * ln_R_Rc);
  const Real F_alpha = Real(2) * dalpha - Real(2) * alpha_c * expm1(dalpha - Real(4) * ln_R_Rc);
  return -F_R / F_alpha;
}

/// Truncated power series sum_k c_k v^k.
using Series = std::vector<double>;

Series series_mul(const Series& a, const Series& b) {
  Series c(a.size(), 0.0);
  for (std::size_t k = 0; k < c.size(); ++k)
    for (std::size_t j = 0; j <= k; ++j)
      c[k] += a[j] * b[k - j];
  return c;
}

/// exp(a(v) - a_0), from f' = a' f.
Series series_exp_shifted(const Series& a) {
  Series f(a.size(), 0.0);
  f[0] = 1.0;
  for (std::size_t k = 1; k < f.size(); ++k) {
    double sum = 0.0;
    for (std::size_t j = 1; j <= k; ++j)
      sum += static_cast<double>(j) * a[j] * f[k - j];
    f[k] = sum / static_cast<double>(k);
  }
  return f;
}

/// 1 / a(v), a_0 != 0.
Series series_reciprocal(const Series& a) {
  Series g(a.size(), 0.0);
  g[0] = 1.0 / a[0];
  for (std::size_t k = 1; k < g.size(); ++k) {
    double sum = 0.0;
    for (std::size_t j = 1; j <= k; ++j)
      sum += a[j] * g[k - j];
    g[k] = -sum / a[0];
  }
  return g;
}

double series_value(const Series& c, double v) {
  double sum = 0.0;
  for (auto it = c.rbegin(); it != c.rend(); ++it)
    sum = sum * v + *it;
  return sum;
}

double series_derivative(const Series& c, double v) {
  double sum = 0.0;
  for (std::size_t k = c.size() - 1; k >= 1; --k)
    sum = sum * v + static_cast<double>(k) * c[k];
  return sum;
}

/// Series of F(alpha(R_c + v), R_c + v) from (S1), for the alpha series a.
Series onelog_residual_series(const Series& a, double Rc) {
  const std::size_t n = a.size();
  Series q(n); // 1/R = 1/(R_c + v)
  for (std::size_t k = 0; k < n; ++k)
    q[k] = (k % 2 == 0 ? 1.0 : -1.0) / std::pow(Rc, static_cast<double>(k + 1));
  const Series q2 = series_mul(q, q);
  const Series exp_term = series_mul(series_exp_shifted(a), series_mul(q2, q2));
  const Series a2 = series_mul(a, a);
  Series F(n);
  for (std::size_t k = 0; k < n; ++k)
    F[k] = a2[k] + 2.0 * q[k] - 0.5 * Rc * Rc * Rc * exp_term[k];
  F[0] -= 1.0;
  return F;
}

/// Taylor coefficients of the physical branch alpha(R_c + v) of (S1), to order `order`.
/// The first-order coefficient s solves F_aa s^2 + 2 F_aR s + F_RR = 0 (the positive root:
/// alpha increases through R_c); a_n (n >= 2) enters the v^{n+1} coefficient of
/// F(alpha(R_c + v), R_c + v) linearly, with factor F_aa s + F_aR.
Series onelog_alpha_series(double Rc, double alpha_c, std::size_t order) {
  const double F_aa = 2.0 - 2.0 * alpha_c;
  const double F_aR = 2.0 / (Rc * Rc);
  const double F_RR = -6.0 / (Rc * Rc * Rc);
  const double b = 2.0 * F_aR;
  const double s = -2.0 * F_RR / (b + std::sqrt(b * b - 4.0 * F_aa * F_RR));
  const double D = F_aa * s + F_aR;
  Series a(order + 2, 0.0);
  a[0] = alpha_c;
  a[1] = s;
  for (std::size_t n = 2; n <= order; ++n) {
    Series trial(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(n + 2));
    trial[n] = 0.0;
    a[n] = -onelog_residual_series(trial, Rc)[n + 1] / D;
  }
  a.resize(order + 1);
  return a;
}

// Order of the Taylor series and half-width of the region where they are used (units of M).
// The series of ln r converges for |v| < R_c - R_0 = 0.228 (1/alpha has a pole at R_0), that of
// alpha for |v| < ~1.5; at |v| <= 0.02 the truncation error at order 24 is far below rounding.
// Outside the region, the slope -F_R/F_alpha loses at most ~1e-15/|v| to rounding.
constexpr std::size_t taylor_order = 24;
constexpr double taylor_delta = 0.02;
// Relative tolerance and first step of the Runge-Kutta-Fehlberg 7(8) integration of (S2) in
// ln r, and the tolerance of the (long double) Bulirsch-Stoer normalisation integral.
constexpr double ode_rel_tol = 5e-16;
constexpr double ode_initial_step = 1e-2;
constexpr long double norm_rel_tol =
    std::max(1e-18L, 16.0L * std::numeric_limits<long double>::epsilon());
// Outer end of the normalisation integral and the tail of ln(r/R) beyond it.
constexpr long double norm_R_end = 1e6L;

/// z(infinity) - z(R) for z = ln(r/R) = int (1/alpha - 1) d ln R, from (S1):
/// 1/alpha - 1 = (1 - 2x)^{-1/2} - 1 + O(x^4) = x + (3/2) x^2 + (5/2) x^3 + O(x^4), x = 1/R.
/// The neglected O(x^4) is ~1e-24 at R = 1e6.
long double onelog_z_tail(long double R) {
  const long double x = 1.0L / R;
  return x * (1.0L + x * (0.75L + x * (5.0L / 6.0L)));
}

using State2 = std::array<double, 2>;

/// (S2) with ln r as the independent variable: d R / d ln r = alpha R,
/// d alpha / d ln r = alpha R d alpha / d R. State {R, alpha}.
struct IsotropicSystem {
  double Rc, alpha_c;
  void operator()(const State2& x, State2& dxds, double /*s*/) const {
    const double aR = x[1] * x[0];
    dxds[0] = aR;
    dxds[1] = aR * onelog_slope(x[1], x[0], Rc, alpha_c);
  }
};

/// Integrates (S2) in s = ln r from (s, x) through the targets (sorted along `direction`),
/// handing each target's state to emit(k, state). The main trajectory takes the step-size
/// controller's own steps; every target gets one extra step from the last main point, no
/// longer than the controller's current step. Dense targets therefore neither shorten the main
/// steps nor accumulate rounding error along them.
template <class Emit>
void integrate_isotropic(const IsotropicSystem& system, State2 x, double s, double direction,
                         const std::vector<double>& targets, Emit emit) {
  using Stepper = odeint::runge_kutta_fehlberg78<State2>;
  using Checker =
      odeint::default_error_checker<double, odeint::array_algebra, odeint::default_operations>;
  odeint::controlled_runge_kutta<Stepper> controlled(
      Checker(std::numeric_limits<double>::min(), ode_rel_tol));
  Stepper single;
  double h = direction * ode_initial_step;
  State2 y;
  for (std::size_t k = 0; k < targets.size(); ++k) {
    int failures = 0;
    while (direction * (targets[k] - s) > direction * h) {
      if (controlled.try_step(system, x, s, h) == odeint::success)
        failures = 0;
      else if (++failures > 200)
        throw std::runtime_error("OneLogTrumpet: step size control failed in (S2)");
    }
    single.do_step(system, x, s, y, targets[k] - s);
    emit(k, y);
  }
}

} // namespace

// ---------------------------------------------------------------------------------------------

// ---------------------------------------------------------------------------------------------

OneLogTrumpet::OneLogTrumpet(double M) : M_(M), C_(0.0), Rc_(0.0), alpha_c_(0.0), R0_(0.0) {
  require_valid_mass(M, "OneLogTrumpet");

  // Critical point of (S1), units M = 1: x = M/R_c = sqrt(160) - 12 (written without the
  // cancellation), alpha_c = x/4, C^2 = (R_c^3/2) e^{-alpha_c}.
  const double x = 16.0 / (12.0 + std::sqrt(160.0));
  const double Rc = 1.0 / x;
  const double alpha_c = 0.25 * x;
  const double C2 = 0.5 * Rc * Rc * Rc * std::exp(-alpha_c);

  // Cylinder: F(0, R) = 0 <=> R^4 - 2R^3 + C^2 = 0, smaller root (the other is > 3/2).
  const auto cyl = [C2](double R) { return R * R * R * (R - 2.0) + C2; };
  const double R0 = solve_bracketed(cyl, 1.0, 1.5, cyl(1.0), cyl(1.5));

  // Taylor region around the critical point: alpha(R) and ln(r/r_c) = int dR / (alpha R).
  delta_ = taylor_delta;
  alpha_series_ = onelog_alpha_series(Rc, alpha_c, taylor_order);
  Series alpha_R = alpha_series_; // alpha (R_c + v)
  for (std::size_t k = alpha_R.size() - 1; k >= 1; --k)
    alpha_R[k] = Rc * alpha_series_[k] + alpha_series_[k - 1];
  alpha_R[0] = Rc * alpha_series_[0];
  const Series inv = series_reciprocal(alpha_R);
  lnr_series_.assign(taylor_order + 1, 0.0);
  for (std::size_t k = 0; k < taylor_order; ++k)
    lnr_series_[k + 1] = inv[k] / static_cast<double>(k + 1);

  // Normalisation (S2), r/R -> 1: z = ln(r/R) obeys dz/d ln R = 1/alpha - 1. Integrate
  // alpha and z outward from R_+ = R_c + delta (in long double, once) and use the tail of z
  // beyond the end.
  {
    using LState = std::array<long double, 2>; // {alpha, int (1/alpha - 1) d ln R}
    const long double Rc_l = Rc, alpha_c_l = alpha_c;
    const auto system = [Rc_l, alpha_c_l](const LState& y, LState& dydt, long double t) {
      const long double R = std::exp(t);
      dydt[0] = R * onelog_slope(y[0], R, Rc_l, alpha_c_l);
      dydt[1] = 1.0L / y[0] - 1.0L;
    };
    LState y = {static_cast<long double>(series_value(alpha_series_, delta_)), 0.0L};
    const long double t0 = std::log(static_cast<long double>(Rc + delta_));
    const long double t1 = std::log(norm_R_end);
    odeint::bulirsch_stoer<LState, long double> stepper(norm_rel_tol, norm_rel_tol);
    odeint::integrate_adaptive(std::ref(stepper), system, y, t0, t1, 1e-3L);
    const long double z_plus = -onelog_z_tail(norm_R_end) - y[1];
    ln_r_plus_ = static_cast<double>(t0 + z_plus);
  }
  ln_rc_ = ln_r_plus_ - series_value(lnr_series_, delta_);
  ln_r_minus_ = ln_rc_ + series_value(lnr_series_, -delta_);

  C_ = M * M * std::sqrt(C2);
  Rc_ = M * Rc;
  alpha_c_ = alpha_c;
  R0_ = M * R0;
}

TrumpetSample OneLogTrumpet::taylor_sample(double r, double ln_rho) const {
  // Newton iteration for ln(r/r_c) = L(v); L' = 1/(alpha R) > 0 and L'' is small.
  const double target = ln_rho - ln_rc_;
  double v = target / lnr_series_[1];
  for (int it = 0; it < 20; ++it) {
    v = std::clamp(v, -delta_, delta_);
    const double step = (series_value(lnr_series_, v) - target) / series_derivative(lnr_series_, v);
    v -= step;
    if (std::abs(step) <= 1e-17)
      break;
  }
  v = std::clamp(v, -delta_, delta_);
  TrumpetSample t;
  t.r = r;
  t.R = M_ * (Rc_ / M_ + v);
  t.alpha = series_value(alpha_series_, v);
  t.dalpha_dR = series_derivative(alpha_series_, v) / M_;
  return t;
}

std::vector<TrumpetSample> OneLogTrumpet::at(std::span<const double> r) const {
  for (const double ri : r)
    require_valid_radius(ri, "OneLogTrumpet::at");

  const double Rc = Rc_ / M_;
  std::vector<TrumpetSample> out(r.size());
  std::vector<double> ln_rho(r.size());
  std::vector<std::size_t> inner, outer;
  for (std::size_t i = 0; i < r.size(); ++i) {
    ln_rho[i] = std::log(r[i] / M_);
    if (ln_rho[i] < ln_r_minus_)
      inner.push_back(i);
    else if (ln_rho[i] > ln_r_plus_)
      outer.push_back(i);
    else
      out[i] = taylor_sample(r[i], ln_rho[i]);
  }

  // Integrate (S2) in ln r away from the Taylor region: outward through the sorted outer
  // radii, inward through the sorted inner ones.
  const IsotropicSystem system{Rc, alpha_c_};
  const auto sweep = [&](std::vector<std::size_t>& idx, double v_start, double s_start,
                         double direction) {
    if (idx.empty())
      return;
    std::sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) {
      return direction * ln_rho[a] < direction * ln_rho[b];
    });
    std::vector<double> targets(idx.size());
    for (std::size_t k = 0; k < idx.size(); ++k)
      targets[k] = ln_rho[idx[k]];
    const State2 x = {Rc + v_start, series_value(alpha_series_, v_start)};
    integrate_isotropic(
        system, x, s_start, direction, targets, [&](std::size_t k, const State2& y) {
          const std::size_t i = idx[k];
          out[i] = {r[i], M_ * y[0], y[1], onelog_slope(y[1], y[0], Rc, alpha_c_) / M_};
        });
  };
  sweep(outer, delta_, ln_r_plus_, 1.0);
  sweep(inner, -delta_, ln_r_minus_, -1.0);
  return out;
}

} // namespace gbssn1d
