#include "initial_data/initial_data.hpp"

#include "initial_data/scalar_pulse.hpp"
#include "initial_data/trumpet_solutions.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <vector>

namespace gbssn1d {

namespace {

/// The fields of one point of a spherically symmetric slice, for r > 0, by registry variable.
using SliceValues = PerVar;

/// Flat space in the registry's variables: each at its value at infinity.
SliceValues flat() {
  SliceValues s;
  for (const auto& entry : registry)
    s[entry.var] = entry.asymptotic;
  return s;
}

void store(State& u, const Grid& grid, std::size_t i, const SliceValues& s, double sign) {
  // sign = -1 for points at r < 0 (origin ghosts): odd variables flip.
  for (const auto& entry : u.vars())
    field(u, grid, entry.var)[i] = (entry.parity < 0 ? sign : 1.0) * s[entry.var];
}

SliceValues wormhole(double r, const InitialDataParams& p) {
  const double psi = 1.0 + p.M / (2.0 * r);
  SliceValues s = flat();
  s[Var::chi] = 1.0 / (psi * psi * psi * psi);
  s[Var::alpha] = p.lapse0 == InitialLapse::precollapsed ? 1.0 / (psi * psi) : 1.0;
  return s;
}

/// Sec. 9 item 5: phi = ln(R/r)/2, a = b = 1, alpha = sqrt(f), beta = C r / R^3, K = 0,
/// A_a = -2C/R^3, Delta^r = 0.
SliceValues maximal_trumpet(double r, const MaximalTrumpet& trumpet) {
  const TrumpetSample t = trumpet.at(r);
  const double R3 = t.R * t.R * t.R;
  SliceValues s = flat();
  s[Var::chi] = (r / t.R) * (r / t.R);
  s[Var::alpha] = t.alpha;
  s[Var::beta] = trumpet.C() * r / R3;
  s[Var::K] = 0.0;
  s[Var::A_a] = -2.0 * trumpet.C() / R3;
  return s;
}

/// (S2), (S3): chi = (r/R)^2, u = C e^{alpha/2}, beta = u r / R^3, K^theta_theta = u / R^3,
/// K = u alpha_R / (2 R^2), A_a = (2/3) K - 2 K^theta_theta, Delta^r = B = 0.
SliceValues onelog_trumpet(const TrumpetSample& t, double C) {
  const double R3 = t.R * t.R * t.R;
  const double u = C * std::exp(0.5 * t.alpha);
  const double K_thth = u / R3;
  SliceValues s = flat();
  s[Var::chi] = (t.r / t.R) * (t.r / t.R);
  s[Var::alpha] = t.alpha;
  s[Var::beta] = u * t.r / R3;
  s[Var::K] = u * t.dalpha_dR / (2.0 * t.R * t.R);
  s[Var::A_a] = (2.0 / 3.0) * s[Var::K] - 2.0 * K_thth;
  return s;
}

/// Time-symmetric data of the scalar field's pulse (Sec. 19) on flat space or a puncture: chi
/// from the conformal factor the Hamiltonian constraint gives, Phi, Pi = 0; the lapse as the
/// wormhole's (psi^-2 precollapsed, with the whole psi), 1 on flat data.
void scalar_pulse(State& u, const Grid& grid, const InitialDataParams& params) {
  const bool puncture = params.kind == InitialDataKind::wormhole;
  if (!puncture && params.kind != InitialDataKind::flat)
    throw std::invalid_argument("the scalar field's data are flat or a puncture's");
  const ScalarPulseData data(params.scalar, puncture ? params.M : 0.0);
  const auto& r = grid.r();
  const std::size_t n = grid.n_total();
  std::vector<std::size_t> order(n); // the points by |r|: the ghosts at the origin mirror
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t i, std::size_t j) { return std::abs(r[i]) < std::abs(r[j]); });
  std::vector<double> radii(n);
  for (std::size_t k = 0; k < n; ++k)
    radii[k] = std::abs(r[order[k]]);
  const std::vector<double> psi = data.psi(radii);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = order[k];
    SliceValues s = flat();
    const double psi2 = psi[k] * psi[k];
    s[Var::chi] = 1.0 / (psi2 * psi2);
    if (puncture && params.lapse0 == InitialLapse::precollapsed)
      s[Var::alpha] = 1.0 / psi2;
    s[Var::Phi] = data.Phi(radii[k]);
    s[Var::Pi] = 0.0;
    store(u, grid, i, s, r[i] < 0 ? -1.0 : 1.0);
  }
}

} // namespace

double adm_mass(const InitialDataParams& params, Fields fields) {
  const double hole = params.kind == InitialDataKind::flat ? 0.0 : params.M;
  if (fields.matter != Matter::scalar)
    return hole;
  return ScalarPulseData(params.scalar, hole).adm_mass();
}

State initial_data(const Grid& grid, const InitialDataParams& params, Fields fields) {
  // Z4c: Theta = 0 (its value at infinity, flat()), so that K-hat = K (Sec. 17)
  State u = make_state(grid, fields);
  const auto& r = grid.r();
  const std::size_t n = grid.n_total();
  if (fields.matter == Matter::scalar) {
    scalar_pulse(u, grid, params);
    return u;
  }

  switch (params.kind) {
  case InitialDataKind::flat:
    for (std::size_t i = 0; i < n; ++i)
      store(u, grid, i, flat(), r[i] < 0 ? -1.0 : 1.0);
    break;
  case InitialDataKind::wormhole:
    for (std::size_t i = 0; i < n; ++i)
      store(u, grid, i, wormhole(std::abs(r[i]), params), r[i] < 0 ? -1.0 : 1.0);
    break;
  case InitialDataKind::maximal_trumpet: {
    const MaximalTrumpet trumpet(params.M);
    for (std::size_t i = 0; i < n; ++i)
      store(u, grid, i, maximal_trumpet(std::abs(r[i]), trumpet), r[i] < 0 ? -1.0 : 1.0);
    break;
  }
  case InitialDataKind::onelog_trumpet: {
    const OneLogTrumpet trumpet(params.M);
    std::vector<double> radii(n);
    for (std::size_t i = 0; i < n; ++i)
      radii[i] = std::abs(r[i]);
    const auto samples = trumpet.at(radii);
    for (std::size_t i = 0; i < n; ++i)
      store(u, grid, i, onelog_trumpet(samples[i], trumpet.C()), r[i] < 0 ? -1.0 : 1.0);
    break;
  }
  }
  return u;
}

} // namespace gbssn1d
