#include "initial_data/scalar_pulse.hpp"

#include <boost/numeric/odeint.hpp>

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace gbssn1d {

namespace {

namespace odeint = boost::numeric::odeint;
using Ode = std::array<double, 2>; ///< u and u'

/// Where the integration starts: u' = 0 there, a relative error of order (r/w)^2 (at 1e-8 w,
/// far below the grid's).
constexpr double start_over_width = 1e-8;
constexpr double tolerance = 1e-13;

} // namespace

ScalarPulseData::ScalarPulseData(const ScalarPulse& pulse, double puncture_mass)
    : pulse_(pulse), M_(puncture_mass) {
  if (!(pulse.width > 0.0) || !(pulse.r0 >= 0.0) || !std::isfinite(pulse.amplitude))
    throw std::invalid_argument("a scalar pulse needs a width > 0, r0 >= 0 and a finite amplitude");
  // exp(-(10)^2) ~ 4e-44: beyond r0 + 10 w the pulse is zero in double precision
  r_far_ = pulse.r0 + 10.0 * pulse.width;
  const double r_start = start_over_width * pulse.width;
  // u at r_far from u(r_start) = u_c: c = u + r u' is the constant u tends to (u = c + d/r
  // outside the pulse); linear in u_c, so two integrations give the u_c with c = 0
  const auto far_constant = [&](double u_c) {
    Ode y{u_c, 0.0};
    odeint::integrate_adaptive(
        odeint::make_controlled(tolerance, tolerance, odeint::runge_kutta_dopri5<Ode>()),
        [this](const Ode& x, Ode& dx, double r) { constraint(x, dx, r); }, y, r_start, r_far_,
        1e-3 * pulse.width);
    return std::array<double, 2>{y[0] + r_far_ * y[1], -r_far_ * r_far_ * y[1]};
  };
  const auto at0 = far_constant(0.0), at1 = far_constant(1.0);
  u0_ = -at0[0] / (at1[0] - at0[0]);
  d_far_ = at0[1] + u0_ * (at1[1] - at0[1]);
  adm_mass_ = M_ + 2.0 * d_far_;
}

void ScalarPulseData::constraint(const std::array<double, 2>& x, std::array<double, 2>& dx,
                                 double r) const {
  const double psi0 = 1.0 + 0.5 * M_ / r, dphi = dPhi(r);
  dx[0] = x[1];
  dx[1] = -2.0 * x[1] / r - std::numbers::pi * dphi * dphi * (psi0 + x[0]);
}

double ScalarPulseData::Phi(double r) const {
  const double x = (r - pulse_.r0) / pulse_.width;
  return pulse_.amplitude * std::exp(-x * x);
}

double ScalarPulseData::dPhi(double r) const {
  const double x = (r - pulse_.r0) / pulse_.width;
  return -2.0 * pulse_.amplitude * x / pulse_.width * std::exp(-x * x);
}

std::vector<double> ScalarPulseData::psi(const std::vector<double>& radii) const {
  std::vector<double> out;
  out.reserve(radii.size());
  const double r_start = start_over_width * pulse_.width;
  std::vector<double> times{r_start};
  for (const double r : radii)
    if (r > r_start && r < r_far_)
      times.push_back(r);
  std::vector<double> u_at; // u at times[1...]
  Ode y{u0_, 0.0};
  odeint::integrate_times(
      odeint::make_dense_output(tolerance, tolerance, odeint::runge_kutta_dopri5<Ode>()),
      [this](const Ode& x, Ode& dx, double r) { constraint(x, dx, r); }, y, times.begin(),
      times.end(), 1e-3 * pulse_.width, [&](const Ode& x, double) { u_at.push_back(x[0]); });
  std::size_t k = 1; // u_at[0] is at r_start
  for (const double r : radii) {
    const double psi0 = 1.0 + 0.5 * M_ / r;
    if (r <= r_start)
      out.push_back(psi0 + u0_);
    else if (r < r_far_)
      out.push_back(psi0 + u_at.at(k++));
    else
      out.push_back(psi0 + d_far_ / r);
  }
  return out;
}

} // namespace gbssn1d
