// The massless scalar field (docs/gbssn1d-equations.md Sec. 19) against solutions nobody here
// wrote: a weak pulse on flat space is the flat spherical wave, r Phi = (u0(r - t) + u0(r + t))/2
// with u0(x) = x A exp(-((|x| - r0)/w)^2) (d'Alembert, Pi = 0 at t = 0); the conformal factor of
// time-symmetric data solves the Hamiltonian constraint, so H at t = 0 converges at the
// differences' order.

#include "../cli/cli_support.hpp"
#include "../simulation_support.hpp"

#include "config/params.hpp"
#include "diagnostics/constraints.hpp"
#include "evolution/simulation.hpp"
#include "gbssn/state.hpp"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

using namespace gbssn1d;
using gbssn1d::testing::scratch;

namespace {

/// The flat spherical wave of a Gaussian pulse of amplitude A at r0 with width w, time-symmetric.
double flat_wave(double r, double t, double A, double r0, double w) {
  const auto u0 = [&](double x) {
    const double q = (std::abs(x) - r0) / w;
    return x * A * std::exp(-q * q);
  };
  return 0.5 * (u0(r - t) + u0(r + t)) / r;
}

/// The flags of the pulse on flat space, uniform rmax 40, N cells, BSSN or Z4c.
Params flat_pulse(int N, double amplitude, Formulation formulation) {
  Params p;
  p.id = InitialDataKind::flat;
  p.matter = Matter::scalar;
  p.formulation = formulation;
  p.scalar_amp = amplitude;
  p.scalar_r0 = 10.0;
  p.scalar_width = 2.0;
  p.grid = RadialGrid::uniform;
  p.rmax = 40.0;
  p.N = N;
  p.tmax = 8.0;
  return p;
}

/// The largest |Phi - flat_wave| / A over the interior at t = 8.
double wave_error(int N, double amplitude, Formulation formulation) {
  Simulation sim = gbssn1d::testing::simulation(flat_pulse(N, amplitude, formulation));
  sim.run(nullptr);
  REQUIRE(sim.time() == doctest::Approx(8.0));
  const Grid& g = sim.grid();
  const auto Phi = field(sim.state(), g, Var::Phi);
  double worst = 0.0;
  for (std::size_t i = g.first_interior(); i < g.end_interior(); ++i)
    worst = std::max(worst, std::abs(Phi[i] - flat_wave(g.r()[i], 8.0, amplitude, 10.0, 2.0)));
  return worst / amplitude;
}

} // namespace

TEST_CASE("the scalar field on flat space: a weak pulse is the flat spherical wave at t = 8, "
          "within 1e-3 A at N = 800 and converging at order 3.5 or more, in BSSN and Z4c") {
  for (const Formulation f : {Formulation::bssn, Formulation::z4c}) {
    std::vector<double> e;
    for (const int N : {200, 400, 800})
      e.push_back(wave_error(N, 1e-6, f));
    const double order_1 = std::log2(e[0] / e[1]), order_2 = std::log2(e[1] / e[2]);
    INFO(fmt::format("formulation {}: max |Phi - exact|/A at N = 200, 400, 800: {:.3e} {:.3e} "
                     "{:.3e}, orders {:.2f} {:.2f}",
                     static_cast<int>(f), e[0], e[1], e[2], order_1, order_2));
    CHECK(e[2] < 1e-3);
    CHECK(order_1 >= 3.5);
    CHECK(order_2 >= 3.5);
  }
}

TEST_CASE("timeseries.dat's Phi_center follows the flat wave at the centre, A (f(t) + t f'(t)) "
          "for the time-symmetric pulse f, within 1e-3 A at N = 400, and vacuum runs have no such "
          "column") {
  const std::filesystem::path dir = scratch("phi_center");
  std::filesystem::remove_all(dir);
  const auto result = gbssn1d::testing::run(
      "evolve --id flat --matter scalar --scalar-amp 1e-6 --grid uniform --rmax 40 --N 400 "
      "--tmax 16 --dt-series 0.5 --out "
      + dir.string());
  REQUIRE(result.status == 0);
  const auto series = gbssn1d::testing::read_table((dir / "timeseries.dat").string());
  const double A = 1e-6, r0 = 10.0, w = 2.0;
  double worst = 0.0, largest = 0.0;
  for (std::size_t k = 0; k < series.rows.size(); ++k) {
    // r Phi = (u0(r - t) + u0(r + t))/2 at r -> 0: Phi(t, 0) = f(t) + t f'(t), f(x) = A
    // exp(-((x - r0)/w)^2)
    const double t = series.at(k, "t"), q = (t - r0) / w;
    const double f = A * std::exp(-q * q), f_prime = -2.0 * q / w * f;
    const double exact = f + t * f_prime;
    largest = std::max(largest, std::abs(exact));
    worst = std::max(worst, std::abs(series.at(k, "Phi_center") - exact));
    CHECK(std::isfinite(series.at(k, "Pi_center")));
  }
  INFO("max |Phi_center - exact| / A = " << worst / A << ", max |exact| / A = " << largest / A);
  CHECK(largest > 0.5 * A); // the pulse reached the centre within the run
  CHECK(worst < 1e-3 * A);
  std::filesystem::remove_all(dir);
  const auto vacuum = gbssn1d::testing::run("evolve --N 64 --tmax 0.5 --out " + dir.string());
  REQUIRE(vacuum.status == 0);
  const auto plain = gbssn1d::testing::read_table((dir / "timeseries.dat").string());
  CHECK(std::find(plain.columns.begin(), plain.columns.end(), "Phi_center") == plain.columns.end());
  std::filesystem::remove_all(dir);
}

TEST_CASE("the scalar field's data: the Hamiltonian constraint with its source converges at 4th "
          "order at t = 0 (the conformal factor from the constraint), far below 16 pi rho") {
  // A = 0.1: rho and the conformal factor's departure from 1 are far above round-off
  std::vector<double> h;
  for (const int N : {200, 400, 800}) {
    const Simulation sim = gbssn1d::testing::simulation(flat_pulse(N, 0.1, Formulation::bssn));
    const DerivedProfiles d = derived_profiles(sim.state(), sim.grid());
    double worst = 0.0;
    for (const double v : d.H)
      worst = std::max(worst, std::abs(v));
    h.push_back(worst);
  }
  INFO(fmt::format("max |H| at t = 0, N = 200, 400, 800: {:.3e} {:.3e} {:.3e}", h[0], h[1], h[2]));
  CHECK(std::log2(h[0] / h[1]) >= 3.5);
  CHECK(std::log2(h[1] / h[2]) >= 3.5);
  // without its source H would be R alone, the pulse's 16 pi rho: far from small
  const Simulation sim = gbssn1d::testing::simulation(flat_pulse(800, 0.1, Formulation::bssn));
  const Grid& g = sim.grid();
  const auto Phi = field(sim.state(), g, Var::Phi);
  double rho_max = 0.0;
  for (std::size_t i = g.first_interior() + 1; i + 1 < g.end_interior(); ++i) {
    const double dPhi = (Phi[i + 1] - Phi[i - 1]) / (g.r()[i + 1] - g.r()[i - 1]);
    rho_max = std::max(rho_max, 0.5 * dPhi * dPhi); // chi/a ~ 1
  }
  CHECK(16.0 * std::numbers::pi * rho_max > 1e4 * h[2]);
}

namespace {

/// A hole of M = 1 (wormhole data, the default sinh grid at N = 400) with a shell of the scalar
/// field, A = 0.04 at r0 = 10 with w = 2, to t = 80; `rahA` != 0: the horizon held at 1.0 M.
struct Accreted {
  double M_AH_start = 0.0, M_AH_end = 0.0, r_AH_end = 0.0;
};
Accreted accretion(double rahA) {
  Params p;
  p.id = InitialDataKind::wormhole;
  p.matter = Matter::scalar;
  p.scalar_amp = 0.04;
  p.N = 400;
  p.tmax = 80.0;
  p.dt_series = 10.0;
  p.rahA = rahA;
  p.rah0 = 1.0;
  Simulation sim = gbssn1d::testing::simulation(p);
  Accreted a;
  const auto start = sim.horizons().horizon();
  REQUIRE(start);
  a.M_AH_start = start->mass;
  sim.run(nullptr);
  const auto end = sim.horizons().horizon();
  REQUIRE(end);
  a.M_AH_end = end->mass;
  a.r_AH_end = end->r;
  return a;
}

} // namespace

TEST_CASE("the scalar field's shell falls into the hole: M_AH grows by more than 10% by t = 80, "
          "and with the horizon-adjusting shift r_AH ends at 1.0 +- 0.02 with the same M_AH") {
  const Accreted left = accretion(0.0), held = accretion(0.5);
  INFO(fmt::format("M_AH {:.9f} -> {:.9f}; held at h = 1: r_AH {:.5f}, M_AH {:.9f}",
                   left.M_AH_start, left.M_AH_end, held.r_AH_end, held.M_AH_end));
  CHECK(left.M_AH_end > 1.1 * left.M_AH_start);
  CHECK(left.r_AH_end > 2.0); // left to grow, the horizon moves out
  CHECK(std::abs(held.r_AH_end - 1.0) < 0.02);
  CHECK(std::abs(held.M_AH_end - left.M_AH_end) < 2e-3 * left.M_AH_end);
}

TEST_CASE("evolve reports the data's ADM mass with the scalar field, which the Misner-Sharp mass "
          "beyond the pulse approaches with resolution") {
  // Outside the pulse the data are Schwarzschild's (Birkhoff), so m_ms there is the ADM mass the
  // conformal factor's ODE gives; on the grid it differs by the finite differences' error
  const auto error_at = [](int N, const std::string& data, double* reported) {
    const auto out = scratch("scalar_adm_" + std::to_string(N) + data.substr(5), true);
    std::filesystem::remove_all(out);
    const auto r = gbssn1d::testing::run("evolve " + data
                                         + " --matter scalar --scalar-amp 0.04 "
                                           "--scalar-r0 10 --scalar-width 2 --tmax 0 --N "
                                         + std::to_string(N) + " --out " + out.string());
    INFO(r.err);
    REQUIRE(r.status == 0);
    *reported = gbssn1d::testing::number_after(r.err, "the data's ADM mass: ");
    // the same in the files' headers, to the last digit
    const std::string header = gbssn1d::testing::slurp(out / "timeseries.dat");
    const std::string key = "\n# M-ADM = ";
    const auto line = header.find(key);
    REQUIRE(line != std::string::npos);
    CHECK(std::stod(header.substr(line + key.size())) == doctest::Approx(*reported).epsilon(1e-11));
    const auto t = gbssn1d::testing::read_table((out / "profiles.dat").string());
    std::size_t i = 0;
    while (t.at(i, "r") < 150.0)
      ++i;
    const double error = t.at(i, "m_ms") - *reported;
    std::filesystem::remove_all(out);
    return error;
  };
  double hole = 0.0, flat = 0.0;
  const double e200 = error_at(200, "--id wormhole", &hole);
  const double e400 = error_at(400, "--id wormhole", &hole);
  const double e800 = error_at(800, "--id wormhole", &hole);
  const double order = gbssn1d::testing::fit_order(
      {1.0 / 200, 1.0 / 400, 1.0 / 800}, {std::abs(e200), std::abs(e400), std::abs(e800)});
  INFO(fmt::format("wormhole: M_ADM {:.12g}, m_ms - M_ADM at r ~ 150: {:.3g}, {:.3g}", hole, e200,
                   e400));
  CHECK(std::abs(e200) < 2e-7);
  CHECK(std::abs(e400) < std::abs(e200) / 8.0);
  CHECK(order > 3.5); // the data's 4th-order differences (measured: 4.0 to N = 1600)
  CHECK(hole > 1.6);  // the hole's M = 1 and the shell's
  CHECK(hole < 1.8);
  error_at(400, "--id flat", &flat);
  CHECK(std::abs(hole - 1.0 - flat) < 0.1 * flat); // the shell weighs about as much on flat space
  MESSAGE(fmt::format("M_ADM {:.12g} (flat: {:.12g}); m_ms - M_ADM at r ~ 150: {:.3g}, {:.3g}, "
                      "{:.3g} (order {:.2f})",
                      hole, flat, e200, e400, e800, order));
  // a vacuum run says nothing of it
  const auto out = scratch("scalar_adm_vacuum", true);
  std::filesystem::remove_all(out);
  const auto v = gbssn1d::testing::run("evolve --tmax 0 --out " + out.string());
  CHECK(v.err.find("ADM mass") == std::string::npos);
  CHECK(gbssn1d::testing::slurp(out / "timeseries.dat").find("M-ADM") == std::string::npos);
  std::filesystem::remove_all(out);
}

TEST_CASE("converge: the scalar pulse at A = 0.01 on flat space converges at N = 200, 300, 400 to "
          "t = 20 (exit 0), in BSSN and in Z4c, Phi and Pi with the geometry") {
  for (const std::string f : {"bssn", "z4c"}) {
    const auto out = gbssn1d::testing::scratch("scalar_converge_" + f, true);
    std::filesystem::remove_all(out);
    const auto r = gbssn1d::testing::run(
        "converge --N 200,300,400 --id flat --matter scalar --scalar-amp 0.01 --grid uniform "
        "--rmax 40 --tmax 20 --fields alpha,chi,K,Phi,Pi --formulation "
        + f + " --out " + out.string());
    INFO(f << ": " << r.err);
    CHECK(r.status == 0);
    CHECK(r.err.find("converges: H converges") != std::string::npos);
    // the field itself converges too (its differences' orders are judged with the rest)
    const std::string text = gbssn1d::testing::slurp(out / "convergence.dat");
    CHECK(text.find("\n# order Phi N = 200, 300 and 400: ") != std::string::npos);
    CHECK(text.find("\n# order Pi N = 200, 300 and 400: ") != std::string::npos);
    std::filesystem::remove_all(out);
  }
}

TEST_CASE("--shift zero: beta stays exactly 0 through a collapse to a black hole (B is driven but "
          "never reaches it), where the Gamma-driver's shift does not") {
  const auto largest = [](ShiftCondition shift) {
    Params p = flat_pulse(400, 0.4, Formulation::bssn);
    p.scalar_r0 = 0.0;
    p.scalar_width = 1.0;
    p.rmax = 20.0;
    p.tmax = 4.0;
    p.dt_series = 0.5;
    p.shift = shift;
    Simulation sim = gbssn1d::testing::simulation(p);
    sim.run(nullptr);
    REQUIRE(sim.time() == doctest::Approx(4.0));
    CHECK(sim.horizons().horizon()); // it collapsed
    const Grid& g = sim.grid();
    const auto beta = field(sim.state(), g, Var::beta), B = field(sim.state(), g, Var::B);
    double beta_max = 0.0, B_max = 0.0;
    for (std::size_t i = 0; i < g.n_total(); ++i) {
      beta_max = std::max(beta_max, std::abs(beta[i]));
      B_max = std::max(B_max, std::abs(B[i]));
    }
    INFO("max |beta| = " << beta_max << ", max |B| = " << B_max);
    CHECK(B_max > 1e-3);
    return beta_max;
  };
  CHECK(largest(ShiftCondition::zero) == 0.0);
  CHECK(largest(ShiftCondition::gamma_driver) > 1e-3);
}
