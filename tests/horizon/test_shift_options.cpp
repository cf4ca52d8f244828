// Options of the horizon-adjusting shift (profiles, normals, ramp, taper, width, open loop,
// midstep update) with the defaults and warnings that go with them, the areal-radius norms, the
// finder's failures, and the coarse-resolution convergence of the default method
// (docs/horizon-shift-study.md). The advection stencils of the shift's equations and B driven
// by the full shift: test_driver_advection.cpp.
#include "../test_support.hpp"
#include "config/config_file.hpp"
#include "config/params.hpp"
#include "diagnostics/constraints.hpp"
#include "evolution/simulation.hpp"
#include "gbssn/horizon_shift.hpp"
#include "horizon/apparent_horizon.hpp"

#include <fmt/format.h>

#include "../simulation_support.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <utility>

using namespace gbssn1d;
using gbssn1d::testing::simulation;
using gbssn1d::testing::small_trumpet_params;

namespace {

Params trumpet(int n, double rmax, double tmax) {
  Params p = small_trumpet_params(n, rmax);
  p.tmax = tmax;
  p.dt_series = 1.0;
  return p;
}

} // namespace

TEST_CASE("shift profiles: odd, their stated shapes at the origin, the peak and far away") {
  using P = ShiftProfile;
  for (P prof : {P::rational, P::rational3, P::gauss, P::gauss3})
    for (double q : {0.01, 0.3, 1.0, 2.5, 7.0})
      CHECK(shift_profile(prof, -q) == -shift_profile(prof, q));
  // closed forms at q = 1 and q = 2
  CHECK(shift_profile(P::rational, 1.0) == doctest::Approx(0.5).epsilon(1e-15));
  CHECK(shift_profile(P::rational, 2.0) == doctest::Approx(0.4).epsilon(1e-15));
  CHECK(shift_profile(P::rational3, 2.0) == doctest::Approx(8.0 / 17.0).epsilon(1e-15));
  CHECK(shift_profile(P::gauss, 1.0) == doctest::Approx(0.5).epsilon(1e-15));
  CHECK(shift_profile(P::gauss, 2.0) == doctest::Approx(std::exp(-1.5)).epsilon(1e-15));
  CHECK(shift_profile(P::gauss3, 1.0) == doctest::Approx(0.5).epsilon(1e-15));
  // the Gaussians peak at q = 1
  for (P prof : {P::gauss, P::gauss3}) {
    CHECK(shift_profile(prof, 0.99) < 0.5);
    CHECK(shift_profile(prof, 1.01) < 0.5);
  }
  // leading powers at the origin: f ~ q (rational, gauss) or q^3 (rational3, gauss3)
  const double q = 1e-3;
  CHECK(shift_profile(P::rational, q) / q == doctest::Approx(1.0).epsilon(1e-5));
  CHECK(shift_profile(P::gauss, q) / q == doctest::Approx(0.5 * std::exp(0.5)).epsilon(1e-5));
  CHECK(shift_profile(P::rational3, q) / (q * q * q) == doctest::Approx(1.0).epsilon(1e-5));
  CHECK(shift_profile(P::gauss3, q) / (q * q * q)
        == doctest::Approx(0.5 * std::exp(1.5)).epsilon(1e-5));
}

/// |got - sqrt(c / a)| in units of the last place of the correctly rounded value, the
/// reference in long double (64-bit mantissa on x86: 11 bits to spare)
double ulps_from_sqrt_quotient(double got, double c, double a) {
  const long double exact = std::sqrt(static_cast<long double>(c) / static_cast<long double>(a));
  const double rounded = static_cast<double>(exact);
  const double ulp = std::nextafter(rounded, std::numeric_limits<double>::infinity()) - rounded;
  return static_cast<double>(std::abs(static_cast<long double>(got) - exact) / ulp);
}

TEST_CASE("sqrt_quotient: sqrt(c / a) within 2 ulp without the divider, 0 at c = 0, NaN for a "
          "degenerate metric") {
  std::mt19937_64 gen(40);
  std::uniform_real_distribution<double> exponent(-150.0, 150.0), unit(0.0, 1.0);
  double worst = 0.0;
  for (int k = 0; k < 200000; ++k) {
    // c and a over 300 decades each, and the values a run meets: chi in (0, 1], a near 1
    const double c = k % 2 ? std::pow(10.0, exponent(gen)) : unit(gen);
    const double a = k % 2 ? std::pow(10.0, exponent(gen)) : 0.5 + unit(gen);
    worst = std::max(worst, ulps_from_sqrt_quotient(sqrt_quotient(c, a), c, a));
  }
  MESSAGE("largest error: " << worst << " ulp");
  CHECK(worst < 2.0);
  // c a subnormal (the estimate reads the exponent bits, so x is scaled first), and c a
  // near the largest double
  for (const auto& [c, a] : {std::pair{1e-160, 1e-160},
                             {4e-320, 1.0},
                             {1.0, 5e-324},
                             {1e154, 1e154},
                             {1.0, 1e-300},
                             {1e300, 1e-300}})
    CHECK(ulps_from_sqrt_quotient(sqrt_quotient(c, a), c, a) < 2.0);
  CHECK(sqrt_quotient(0.0, 1.7) == 0.0);
  CHECK(sqrt_quotient(1.0, 1.0) == 1.0);
  CHECK(sqrt_quotient(4.0, 1.0) == 2.0);
  for (const auto& [c, a] : {std::pair{1.0, 0.0},
                             {1.0, -1.0},
                             {-1.0, 1.0},
                             {1e200, 1e200},
                             {1e-200, 1e-200},
                             {1.0, std::numeric_limits<double>::infinity()},
                             {std::numeric_limits<double>::quiet_NaN(), 1.0},
                             {1.0, std::numeric_limits<double>::quiet_NaN()}}) {
    CAPTURE(c);
    CAPTURE(a);
    CHECK(std::isnan(sqrt_quotient(c, a)));
  }
}

TEST_CASE("shift normals: their values, and the unit normal's kink at a trumpet's puncture") {
  CHECK(shift_normal(ShiftNormal::unit, 0.25, 4.0, 0.05) == doctest::Approx(0.25));
  CHECK(shift_normal(ShiftNormal::conformal, 0.25, 4.0, 0.05) == doctest::Approx(0.5));
  CHECK(shift_normal(ShiftNormal::smooth, 0.25, 4.0, 0.05)
        == doctest::Approx(std::sqrt(0.3 / 4.0)));
  // chi < 0 (a coarse innermost cell) gives a finite s^r
  CHECK(shift_normal(ShiftNormal::unit, -1e-8, 1.0, 0.05) == 0.0);

  // On the 1+log trumpet chi ~ r^2 at the puncture: beta_H ~ r |r| with the unit normal (its
  // second difference across r = 0 jumps), ~ r with the conformal one (smooth and odd).
  Simulation sim = simulation(trumpet(400, 20.0, 0.0));
  const Grid& g = sim.grid();
  HorizonShiftParams hs;
  hs.A = 0.5;
  hs.h = 0.89;
  std::vector<double> unit, conformal;
  hs.normal = ShiftNormal::unit;
  horizon_shift_profile(sim.state(), g, hs, 0.83, unit);
  hs.normal = ShiftNormal::conformal;
  horizon_shift_profile(sim.state(), g, hs, 0.83, conformal);
  const std::size_t i1 = g.first_interior(), i2 = i1 + 1;
  // beta_H(r2)/beta_H(r1) = (r2/r1)^2 for r|r|, r2/r1 for a smooth odd function
  const double ratio = g.r()[i2] / g.r()[i1]; // = 3 on the cell-centred grid
  CHECK(unit[i2] / unit[i1] == doctest::Approx(ratio * ratio).epsilon(0.05));
  CHECK(conformal[i2] / conformal[i1] == doctest::Approx(ratio).epsilon(0.02));
  // both are odd through the parity ghosts
  for (const auto* v : {&unit, &conformal})
    for (std::size_t i = 0; i < Grid::n_ghost; ++i)
      CHECK((*v)[i] == doctest::Approx(-(*v)[Grid::mirror(i)]).epsilon(1e-14));
}

TEST_CASE("--rah-ramp: the strength grows as A (1 - exp(-(t/T)^2))") {
  HorizonShiftParams hs;
  hs.A = 0.5;
  hs.h = 0.89;
  CHECK(hs.strength(0.0) == 0.5); // no ramp
  hs.ramp = 20.0;
  CHECK(hs.strength(0.0) == 0.0);
  CHECK(hs.strength(20.0) == doctest::Approx(0.5 * (1.0 - std::exp(-1.0))).epsilon(1e-15));
  CHECK(hs.strength(200.0) == doctest::Approx(0.5).epsilon(1e-15));
  // beta_H scales with it
  Simulation sim = simulation(trumpet(200, 20.0, 0.0));
  std::vector<double> full, ramped;
  hs.ramp = 0.0;
  horizon_shift_profile(sim.state(), sim.grid(), hs, 0.83, full, 10.0);
  hs.ramp = 20.0;
  horizon_shift_profile(sim.state(), sim.grid(), hs, 0.83, ramped, 10.0);
  const std::size_t i = sim.grid().first_interior() + 30;
  REQUIRE(full[i] != 0.0);
  CHECK(ramped[i] / full[i] == doctest::Approx(1.0 - std::exp(-0.25)).epsilon(1e-14));
}

TEST_CASE("--rah-profile auto: rational with w = 3 max(h, M) to stretch, gauss with w = 1 M to "
          "shrink") {
  HorizonShiftParams stretch;
  stretch.A = 0.5;
  stretch.h = 1.7; // M = 2: the standard horizon is at 1.6608
  stretch.profile = ShiftProfile::automatic;
  HorizonShiftParams shrink = stretch;
  shrink.h = 1.6;
  resolve_automatic_profile(stretch, 2.0);
  resolve_automatic_profile(shrink, 2.0);
  CHECK(stretch.profile == ShiftProfile::rational);
  CHECK(stretch.width == 6.0); // h = 1.7 < M = 2: w = 3 M
  HorizonShiftParams wide = stretch;
  wide.profile = ShiftProfile::automatic;
  wide.h = 4.0; // h = 2 M: w = 3 h
  resolve_automatic_profile(wide, 2.0);
  CHECK(wide.width == 12.0);
  CHECK(shrink.profile == ShiftProfile::gauss);
  CHECK(shrink.width == 2.0);
  // an explicit profile keeps its width
  HorizonShiftParams fixed = stretch;
  fixed.profile = ShiftProfile::gauss3;
  fixed.width = 0.7;
  resolve_automatic_profile(fixed, 2.0);
  CHECK(fixed.profile == ShiftProfile::gauss3);
  CHECK(fixed.width == 0.7);
  // the run's parameters resolve it
  Params given = trumpet(200, 20.0, 0.0);
  given.rahA = 0.5;
  given.rah0 = 0.6;
  const ResolvedParams p = resolve(given);
  CHECK(evolution_config(p).rhs.horizon_shift.profile == ShiftProfile::gauss);
  // and config.toml records what auto stood for, so that a later change of auto is detected
  CHECK(p.rah_profile == ShiftProfile::gauss);
  CHECK(p.rah_width == 1.0);
  Params q_given = trumpet(200, 20.0, 0.0);
  q_given.rahA = 0.5;
  q_given.rah0 = 0.89;
  const ResolvedParams q = resolve(q_given);
  CHECK(evolution_config(q).rhs.horizon_shift.profile == ShiftProfile::rational);
  CHECK(evolution_config(q).rhs.horizon_shift.width == 3.0);
  CHECK(q.rah_profile == ShiftProfile::rational);
  CHECK(config_text(q).find("rah-width = 3\n") != std::string::npos);
  // without the horizon shift nothing is resolved (auto means nothing there)
  const ResolvedParams off = resolve(trumpet(200, 20.0, 0.0));
  CHECK(off.rah_profile == ShiftProfile::automatic);
  CHECK_FALSE(off.flags().rah_rcut.has_value());
}

TEST_CASE("beta_H is tapered to zero before the outer boundary: quartic (default) and step") {
  // quartic: exp(-(2 s)^4), 1 at the origin, e^-1 at rcut/2, about 1e-7 at rcut; monotone
  CHECK(outer_taper(0.0) == 1.0);
  CHECK(outer_taper(0.25) == doctest::Approx(std::exp(-1.0 / 16.0)).epsilon(1e-15));
  CHECK(outer_taper(0.5) == doctest::Approx(std::exp(-1.0)).epsilon(1e-15));
  CHECK(outer_taper(1.0) == doctest::Approx(std::exp(-16.0)).epsilon(1e-15));
  CHECK(outer_taper(1.0) < 1.2e-7);
  CHECK(outer_taper(2.0) < 1e-100);
  for (double s = 0.0; s < 2.0; s += 0.01)
    CHECK(outer_taper(s + 0.01) < outer_taper(s));
  // the step: 1 to rcut/2, 1/2 at the middle (g(1 - u) = g(u) there), 0 from rcut, monotone
  const Taper step = Taper::step;
  CHECK(outer_taper(0.0, step) == 1.0);
  CHECK(outer_taper(0.5, step) == 1.0);
  CHECK(outer_taper(0.75, step) == doctest::Approx(0.5).epsilon(1e-15));
  CHECK(outer_taper(1.0, step) == 0.0);
  CHECK(outer_taper(3.0, step) == 0.0);
  for (double s = 0.5; s < 1.0; s += 0.01)
    CHECK(outer_taper(s + 0.01, step) <= outer_taper(s, step));
  // smooth: near each end the step departs from 1 (or 0) faster than any power (here: below
  // 1e-6 within 0.03 of the end, where a C^3 polynomial step would still be ~1e-5)
  CHECK(1.0 - outer_taper(0.5 + 0.03, step) < 1e-6);
  CHECK(outer_taper(1.0 - 0.03, step) < 1e-6);
  // what the quartic taper is for: its high derivatives, which set the truncation error of the
  // shift's derivatives where coarse boxes sample the taper, are far smaller than the step's.
  // Largest 6th difference / h^6 over 0 <= s <= 1.2 (h = 1e-3): measured 5.4e5 and 3.1e8
  auto largest_sixth = [](Taper taper) {
    const double h = 1e-3;
    double largest = 0.0;
    for (double s = 0.0; s <= 1.2; s += h) {
      const double d = outer_taper(s - 3 * h, taper) - 6 * outer_taper(s - 2 * h, taper)
                       + 15 * outer_taper(s - h, taper) - 20 * outer_taper(s, taper)
                       + 15 * outer_taper(s + h, taper) - 6 * outer_taper(s + 2 * h, taper)
                       + outer_taper(s + 3 * h, taper);
      largest = std::max(largest, std::abs(d) / std::pow(h, 6));
    }
    return largest;
  };
  const double quartic6 = largest_sixth(Taper::quartic), step6 = largest_sixth(step);
  MESSAGE("largest 6th derivative: quartic " << quartic6 << ", step " << step6);
  CHECK(quartic6 * 100.0 < step6);
  // in a run: default rcut = rmax / 2 and the quartic taper; beta_H / (f(r)/sqrt(a)) is
  // A (h_AH - h) times the taper everywhere
  Params given = trumpet(400, 40.0, 0.0);
  given.rahA = 0.5;
  given.rah0 = 1.2;
  given.rah_profile = ShiftProfile::rational;
  given.rah_width = 3.0;
  given.rah_normal = ShiftNormal::conformal;
  const ResolvedParams p = resolve(given);
  CHECK(p.rah_taper() == Taper::quartic);
  CHECK(p.flags().rah_taper == Taper::quartic);
  const std::string text = config_text(p);
  CHECK(text.find("rah-taper = \"quartic\"\n") != std::string::npos);
  {
    // a configuration written before the option existed (its runs used the step) is told apart
    // from today's, so that its checkpoint or sweep member is not continued with the quartic
    std::string old_text = text;
    old_text.erase(old_text.find("rah-taper"), std::string("rah-taper = \"quartic\"\n").size());
    const auto diff = config_differences(old_text, text, {});
    REQUIRE(diff.size() == 1);
    CHECK(diff.front() == "rah-taper: (unset) -> \"quartic\"");
    // without the horizon shift nothing is recorded, and nothing differs
    const ResolvedParams off = resolve(trumpet(400, 40.0, 0.0));
    CHECK_FALSE(off.flags().rah_taper.has_value());
    CHECK(config_text(off).find("rah-taper") == std::string::npos);
  }
  Simulation sim = simulation(p);
  REQUIRE(p.flags().rah_rcut.has_value());
  CHECK(*p.flags().rah_rcut == 20.0);
  CHECK(p.rah_rcut() == 20.0);
  const auto beta_H = sim.horizon_shift();
  const Grid& g = sim.grid();
  const auto a = field(sim.state(), g, Var::a);
  const std::size_t i0 = g.first_interior() + 20;
  auto ratio = [&](std::size_t i) {
    const double q = g.r()[i] / 3.0;
    return beta_H[i] / (q / (1.0 + q * q) / std::sqrt(a[i]));
  };
  const double amplitude = ratio(i0) / outer_taper(g.r()[i0] / 20.0);
  REQUIRE(std::abs(amplitude) > 1e-6);
  for (std::size_t i = g.first_interior(); i < g.end_interior(); ++i) {
    const double r = g.r()[i];
    INFO("r = " << r);
    CHECK(ratio(i) == doctest::Approx(amplitude * outer_taper(r / 20.0)).epsilon(1e-12));
    if (r >= 20.0)
      CHECK(std::abs(beta_H[i]) < 1e-7 * std::abs(amplitude));
  }
  // --rah-taper step: 1 up to rcut/2, exactly 0 from rcut
  Params q = p;
  q.rah_taper = Taper::step;
  Simulation sim_step = simulation(q);
  const auto beta_step = sim_step.horizon_shift();
  for (std::size_t i = g.first_interior(); i < g.end_interior(); ++i) {
    const double r = g.r()[i];
    INFO("r = " << r);
    if (r <= 10.0)
      CHECK(beta_step[i] == doctest::Approx(beta_H[i] / outer_taper(r / 20.0)).epsilon(1e-12));
    else if (r >= 20.0)
      CHECK(beta_step[i] == 0.0);
  }
}

TEST_CASE("--rah-hAH-file: h_AH(t) read from a file and interpolated smoothly (open loop)") {
  const auto dir = gbssn1d::testing::scratch("prescribed", true);
  const auto path = dir / "horizon.dat";
  {
    std::ofstream f(path);
    f << "# some header\n# t r_ah R_ah\n";
    for (int k = 0; k <= 80; ++k) {
      const double t = 0.25 * k;
      f << t << " " << 0.8 + 0.1 * std::sin(0.3 * t) << " 2\n";
    }
  }
  const auto h = load_prescribed_horizon(path.string(), 20.0);
  double max_error = 0;
  for (double t = 0.0; t <= 20.0; t += 0.01)
    max_error = std::max(max_error, std::abs(h(t) - (0.8 + 0.1 * std::sin(0.3 * t))));
  MESSAGE("cubic B-spline of h_AH(t), dt = 0.25: max error ", max_error);
  CHECK(max_error < 1e-5);
  // a run uses it: beta_H follows the prescribed h_AH, not the horizon of the state
  Params p = trumpet(200, 20.0, 2.0);
  p.rahA = 0.5;
  p.rah_hAH_file = path.string();
  Simulation sim = simulation(p);
  sim.run(nullptr);
  REQUIRE(sim.horizon_radius().has_value());
  CHECK(*sim.horizon_radius() == doctest::Approx(0.8 + 0.1 * std::sin(0.6)).epsilon(1e-6));
  // refusals: too short, unequal spacing, no horizon
  CHECK_THROWS_AS(load_prescribed_horizon(path.string(), 30.0), ParamError);
  {
    std::ofstream f(dir / "gap.dat");
    f << "# t r_ah\n0 0.8\n1 0.8\n2 0.8\n4 0.8\n5 0.8\n";
    std::ofstream g(dir / "nan.dat");
    g << "# t r_ah\n0 0.8\n1 nan\n2 0.8\n3 0.8\n4 0.8\n";
  }
  CHECK_THROWS_AS(load_prescribed_horizon((dir / "gap.dat").string(), 1.0), ParamError);
  CHECK_THROWS_AS(load_prescribed_horizon((dir / "nan.dat").string(), 1.0), ParamError);
  CHECK_THROWS_AS(load_prescribed_horizon((dir / "missing.dat").string(), 1.0), ParamError);
}

TEST_CASE("areal-radius norms: weights the areal widths, select by R, only the outer sheet, and "
          "the interior window") {
  // R_k = k + 1 (uniform in R): the |dR|-weighted mean of f = R over [3, 7] is exact for a
  // linear function on equal weights.
  const std::size_t n = 20;
  std::vector<double> R(n), f(n), ones(n, 1.0);
  for (std::size_t k = 0; k < n; ++k) {
    R[k] = static_cast<double>(k) + 1.0;
    f[k] = R[k];
  }
  CHECK(l2_norm_areal(ones, R, 3.0, 7.0) == doctest::Approx(1.0));
  // sqrt(mean of R^2 over R = 3..7) = sqrt((9+16+25+36+49)/5)
  CHECK(l2_norm_areal(f, R, 3.0, 7.0) == doctest::Approx(std::sqrt(135.0 / 5.0)));
  // stretching the coordinate (R sampled twice as densely on one side) does not change the
  // norm of a function of R: the weights are |dR|, not dr
  std::vector<double> R2, f2;
  for (double x = 1.0; x < 5.0; x += 0.25) {
    R2.push_back(x);
    f2.push_back(1.0 + x);
  }
  for (double x = 5.0; x <= 12.0; x += 1.0) {
    R2.push_back(x);
    f2.push_back(1.0 + x);
  }
  std::vector<double> R3, f3; // the same spacings at the window's edges, another inside
  for (double x = 1.0; x < 5.0; x += 0.25) {
    R3.push_back(x);
    f3.push_back(1.0 + x);
  }
  for (double x = 5.0; x < 8.0; x += 0.5) {
    R3.push_back(x);
    f3.push_back(1.0 + x);
  }
  for (double x = 8.0; x <= 12.0; x += 1.0) {
    R3.push_back(x);
    f3.push_back(1.0 + x);
  }
  CHECK(l2_norm_areal(f2, R2, 3.0, 10.0)
        == doctest::Approx(l2_norm_areal(f3, R3, 3.0, 10.0)).epsilon(0.02));
  CHECK(std::isnan(l2_norm_areal(f, R, 100.0, 200.0))); // empty window: no value
  // a wormhole: R falls to a throat and rises again; only the outer sheet counts
  std::vector<double> Rw{9.0, 6.0, 4.0, 3.0, 2.0, 3.0, 4.0, 6.0, 9.0};
  std::vector<double> fw{50.0, 50.0, 50.0, 50.0, 1.0, 1.0, 1.0, 1.0, 1.0};
  CHECK(l2_norm_areal(fw, Rw, 2.5, 12.0) == doctest::Approx(1.0));
  // ... also when the innermost cell's R dips below the throat's (chi on its floor near a
  // collapsing wormhole's puncture): the outermost minimum is the throat, not the global one
  std::vector<double> Rd{1.5, 4.7, 4.5, 3.0, 2.0, 3.0, 4.0, 6.0, 9.0};
  std::vector<double> fd{0.5, 50.0, 50.0, 50.0, 1.0, 1.0, 1.0, 1.0, 1.0};
  CHECK(l2_norm_areal(fd, Rd, 2.5, 12.0) == doctest::Approx(1.0));

  // interior: from the innermost point out to R = Rint, dr-weighted
  Simulation sim = simulation(trumpet(200, 20.0, 0.0));
  const Grid& g = sim.grid();
  std::vector<double> Rt(g.n_interior()), two(g.n_interior(), 2.0);
  for (std::size_t k = 0; k < Rt.size(); ++k)
    Rt[k] = k < 10 ? 1.5 : 3.0;
  CHECK(l2_norm_interior(two, Rt, g, 1.8) == doctest::Approx(2.0));
  std::vector<double> ramp(g.n_interior(), 0.0);
  ramp[12] = 100.0; // outside the interior window
  CHECK(l2_norm_interior(ramp, Rt, g, 1.8) == 0.0);
  Rt[0] = 5.0; // a wormhole's other sheet: no interior window
  CHECK(std::isnan(l2_norm_interior(two, Rt, g, 1.8)));
}

TEST_CASE("the horizon finder reports non-finite data instead of crashing") {
  Simulation sim = simulation(trumpet(200, 20.0, 0.0));
  State u = sim.state();
  const Grid& g = sim.grid();
  field(u, g, Var::chi)[g.first_interior() + 20] = std::numeric_limits<double>::quiet_NaN();
  HorizonFinderParams finder;
  try {
    (void)find_horizons(u, g, finder);
    FAIL("no HorizonFinderError");
  } catch (const HorizonFinderError& e) {
    const std::string what = e.what();
    CHECK(what.find("non-finite expansion") != std::string::npos);
    // the derivative stencils spread the NaN over points 18 ... 22; the scan, from outside in,
    // meets point 22 first
    CHECK(what.find(fmt::format("r = {:.6g}", g.r()[g.first_interior() + 22]))
          != std::string::npos);
  }
}

// The published method loses convergence at coarse spacing (M/8 ... M/16), the default does
// not: H outside the horizon (areal R in [2.5, 12] M), averaged over 10 ... 100 M, within 2x of
// the standard gauge at M/8, M/12, M/16, and converging at order >= 3.5 over M/12, M/16, M/24.
// (Measured on the published form: 11.6x, 2.7x, 4.1x the standard; orders 6.4, 2.3.)
TEST_CASE("a stretched horizon (0.89 M) converges at coarse spacing, M/8 to M/24") {
  auto rms_H = [&](const std::vector<int>& Ns, double rahA) {
    std::vector<double> out;
    for (int n : Ns) {
      Params p = trumpet(n, 200.0, 100.0);
      p.rahA = rahA;
      p.rah0 = 0.89;
      Simulation sim = simulation(p);
      double sum = 0;
      int count = 0;
      sim.on_series = [&](Simulation& s) {
        if (s.time() < 10.0 - 1e-9)
          return;
        const double H = s.series_row(derived_profiles(s.state(), s.grid())).H_L2_R;
        sum += H * H;
        ++count;
      };
      sim.run(nullptr);
      out.push_back(std::sqrt(sum / count));
    }
    return out;
  };
  const std::vector<int> coarse{1600, 2400, 3200};
  const auto standard = rms_H(coarse, 0.0);
  const auto stretch = rms_H({1600, 2400, 3200, 4800}, 0.5);
  for (std::size_t k = 0; k < coarse.size(); ++k) {
    MESSAGE("N = ", coarse[k], ": H_L2_R rms standard ", standard[k], ", stretched ", stretch[k],
            ", ratio ", stretch[k] / standard[k]);
    CHECK(stretch[k] <= 2.0 * standard[k]);
  }
  for (std::size_t k = 1; k + 1 < stretch.size(); ++k) {
    const double N1 = k == 1 ? 2400 : 3200, N2 = k == 1 ? 3200 : 4800;
    const double p = std::log(stretch[k] / stretch[k + 1]) / std::log(N2 / N1);
    MESSAGE("order N = ", N1, " -> ", N2, ": ", p);
    CHECK(p >= 3.5);
    CHECK(p <= 4.6);
  }
}

TEST_CASE("a wormhole shrink defaults to eta = 1/M, and is warned about with eta > 1/M, "
          "trumpets and stretches keep 2/M") {
  Params p;
  p.id = InitialDataKind::wormhole;
  p.rahA = 0.5;
  p.rah0 = 0.6;
  p.M = 2.0;
  p.rah0 = 1.2; // below the standard 0.8304 M = 1.66
  const ResolvedParams q = resolve(p);
  CHECK(q.eta() == 0.5); // 1/M
  CHECK(warnings(q).empty());
  Params q_eta = p;
  q_eta.eta = 1.0; // 2/M, given
  REQUIRE(warnings(resolve(q_eta)).size() == 1);
  CHECK(warnings(resolve(q_eta))[0].find("eta = 1/M, their default") != std::string::npos);
  for (auto change : {+[](Params& x) { x.id = InitialDataKind::onelog_trumpet; },
                      +[](Params& x) { x.rah0 = 1.7; }, +[](Params& x) { x.rahA = 0.0; }}) {
    Params r_given = p;
    change(r_given);
    const ResolvedParams r = resolve(r_given);
    CHECK(r.eta() == 1.0); // 2/M
    // no eta warning; with rahA = 0 the idle --rah0 is warned about instead
    const auto w = warnings(r);
    CHECK(w.size() == (r.rahA == 0.0 ? 1u : 0u));
    for (const auto& text : w)
      CHECK(text.find("does nothing with --rahA 0") != std::string::npos);
  }
}

TEST_CASE("--rah-width reaches the shift: f(r) = (r/w)/(1 + (r/w)^2) with the width given") {
  for (double w : {1.0, 2.0, 3.5}) {
    Params p = trumpet(200, 20.0, 0.0);
    p.rahA = 0.5;
    p.rah0 = 0.6;
    p.rah_profile = ShiftProfile::rational;
    p.rah_width = w;
    p.rah_normal = ShiftNormal::conformal;
    p.rah_rcut = 1e6; // the taper far outside the grid (it has its own test)
    Simulation sim = simulation(p);
    const auto beta_H = sim.horizon_shift();
    const Grid& g = sim.grid();
    const auto a = field(sim.state(), g, Var::a);
    // beta_H / (f(r) / sqrt(a)) is the same constant A (h_AH - h) at every point
    std::vector<double> amplitude;
    for (std::size_t i = g.first_interior(); i < g.end_interior(); i += 37) {
      const double q = g.r()[i] / w;
      amplitude.push_back(beta_H[i] / (q / (1.0 + q * q) / std::sqrt(a[i])));
    }
    INFO("w = " << w);
    REQUIRE(std::abs(amplitude.front()) > 1e-6);
    for (double c : amplitude)
      CHECK(c == doctest::Approx(amplitude.front()).epsilon(1e-12));
  }
}

TEST_CASE("midstep-update searches inside the step: the shrink moves the horizon") {
  Params p = trumpet(400, 40.0, 10.0);
  p.rahA = 0.5;
  p.rah0 = 0.6;
  p.rah_variant = ShiftVariant::midstep_update;
  p.ah_every = AhEvery::parse("2");
  Simulation sim = simulation(p);
  const double r0 = sim.horizons().horizon()->r;
  sim.run(nullptr);
  const double r10 = sim.horizons().horizon()->r;
  MESSAGE("r_AH " << r0 << " -> " << r10);
  REQUIRE(sim.rhs().horizon_radius().has_value()); // searched during the run
  CHECK(r10 < r0 - 0.05);                          // towards h = 0.6
}

// The boundary's light cone (gauge speed sqrt(2)) reaches the norm windows (r <= 12 M) after
// (rmax - 12) / sqrt(2): a run past that is warned about, once, with the rmax that avoids it.
TEST_CASE("a tmax that lets the outer boundary reach the norm windows is warned about") {
  Params p;
  p.rmax = 100.0;
  p.tmax = 60.0; // (100 - 12) / sqrt(2) = 62.2
  CHECK(warnings(resolve(p)).empty());
  p.tmax = 64.0;
  const auto w = warnings(resolve(p));
  REQUIRE(w.size() == 1);
  CHECK(w[0].find("t ~ 62 M") != std::string::npos);
  CHECK(w[0].find("--rmax > 103") != std::string::npos); // 12 + sqrt(2) 64 = 102.5
  p.rmax = 120.0;
  CHECK(warnings(resolve(p)).empty());
}
