#include "initial_data/initial_data.hpp"

#include "initial_data/trumpet_solutions.hpp"

#include <cmath>
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

} // namespace

State initial_data(const Grid& grid, const InitialDataParams& params, Formulation formulation) {
  // Z4c: Theta = 0 (its value at infinity, flat()), so that K-hat = K (Sec. 17)
  State u = make_state(grid, formulation);
  const auto& r = grid.r();
  const std::size_t n = grid.n_total();

  switch (params.kind) {
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
