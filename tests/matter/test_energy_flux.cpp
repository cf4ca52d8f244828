// The energy flux through a sphere of fixed areal radius (docs/gbssn1d-equations.md (S7); the
// series' m_R<X> and flux_R<X>) against what nobody here wrote: its time integral is the change of
// the Misner-Sharp mass inside the sphere (Hayward's identity, which holds only where the
// constraints do), and all of a pulse's energy, the ADM mass of its data, crosses a sphere beyond
// it.

#include "../cli/cli_support.hpp"

#include "gbssn/equations.hpp"
#include "gbssn/point_data.hpp"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

using namespace gbssn1d;
using gbssn1d::testing::scratch;

namespace {

/// Simpson's rule over equally spaced samples (an even number of intervals).
double simpson(const std::vector<double>& f, double h) {
  REQUIRE(f.size() % 2 == 1);
  double sum = f.front() + f.back();
  for (std::size_t k = 1; k + 1 < f.size(); ++k)
    sum += (k % 2 == 1 ? 4.0 : 2.0) * f[k];
  return sum * h / 3.0;
}

struct Crossing {
  double M_adm;      ///< the data's ADM mass, as evolve reports it
  double integral;   ///< the integral of flux_R20 over t
  double m_0, m_end; ///< m_R20 at the first and the last row
};

/// The pulse A = 0.01 at r0 = 10 (w = 2) on flat space, uniform rmax 60, to t = 38 with a row
/// every 0.05: by then both of its halves have crossed R = 20 (the inward one through the centre
/// by t ~ 36), and the outer boundary's signal, which breaks the constraints (its Sommerfeld
/// condition is not constraint preserving), reaches R = 20 only at t ~ 40.
Crossing crossing(int N) {
  const auto out = scratch("energy_flux_" + std::to_string(N), true);
  std::filesystem::remove_all(out);
  const auto r = gbssn1d::testing::run(
      "evolve --id flat --matter scalar --scalar-amp 0.01 --scalar-r0 10 --scalar-width 2 "
      "--grid uniform --rmax 60 --tmax 38 --dt-series 0.05 --flux-R 20 --N "
      + std::to_string(N) + " --out " + out.string());
  INFO(r.err);
  REQUIRE(r.status == 0);
  const double M_adm = gbssn1d::testing::number_after(r.err, "the data's ADM mass: ");
  const auto t = gbssn1d::testing::read_table((out / "timeseries.dat").string());
  std::vector<double> F;
  for (std::size_t k = 0; k < t.rows.size(); ++k)
    F.push_back(t.at(k, "flux_R20"));
  REQUIRE(t.rows.size() == 761);
  REQUIRE(t.at(t.rows.size() - 1, "t") == doctest::Approx(38.0));
  Crossing c{M_adm, simpson(F, 0.05), t.at(0, "m_R20"), t.at(t.rows.size() - 1, "m_R20")};
  std::filesystem::remove_all(out);
  return c;
}

} // namespace

TEST_CASE("energy_flux: the scalar field's (S7) is 4 pi R^2 (alpha/Gamma)(Gamma Pi - U Phi_e)"
          "(U Pi - Gamma Phi_e), and on a flat slice with alpha = 1 the flux 4 pi r^2 j") {
  PointData p{};
  using enum Var;
  // a point of a curved slice with matter moving through it
  p.r = 3.0;
  p.inv_r = 1.0 / p.r;
  p.f[a] = 1.3;
  p.f[b] = 0.8;
  p.f[chi] = 0.6;
  p.f[K] = 0.21;
  p.f[A_a] = -0.07;
  p.f[alpha] = 0.7;
  p.f[Pi] = 0.04;
  p.d[a] = 0.05;
  p.d[b] = -0.03;
  p.d[chi] = 0.11;
  p.d[Phi] = -0.025;
  const double inv_a = 1.0 / p.f[a];
  const StressEnergy s = ScalarField::stress_energy(p, inv_a);
  const double e = std::sqrt(p.f[chi] * inv_a), R = p.r * std::sqrt(p.f[b] / p.f[chi]);
  const double Gamma = e * R * (1.0 / p.r + 0.5 * (p.d[b] / p.f[b] - p.d[chi] / p.f[chi]));
  const double U = -R * (p.f[K] / 3.0 - 0.5 * p.f[A_a]), Phi_e = e * p.d[Phi];
  const double factored = 4.0 * std::numbers::pi * R * R * p.f[alpha] / Gamma
                          * (Gamma * p.f[Pi] - U * Phi_e) * (U * p.f[Pi] - Gamma * Phi_e);
  CHECK(energy_flux(p, s) == doctest::Approx(factored).epsilon(1e-13));
  CHECK(std::abs(energy_flux(p, s)) > 1e-3); // not a vanishing case
  // flat space, time-symmetric slice, unit lapse: an outgoing wave (Pi = -Phi') leaves
  PointData q{};
  q.r = 5.0;
  q.inv_r = 0.2;
  q.f[a] = q.f[b] = q.f[chi] = q.f[alpha] = 1.0;
  q.d[Phi] = -0.3;
  q.f[Pi] = 0.3;
  const StressEnergy w = ScalarField::stress_energy(q, 1.0);
  CHECK(energy_flux(q, w) == doctest::Approx(4.0 * std::numbers::pi * 25.0 * 0.09));
  q.f[Pi] = -0.3; // and an ingoing one enters
  CHECK(energy_flux(q, ScalarField::stress_energy(q, 1.0)) < 0.0);
}

TEST_CASE("flux_R20 over t is the change of m_R20 (Hayward's identity on the constraints), at "
          "4th order, and carries the pulse's ADM mass across R = 20") {
  const Crossing c300 = crossing(300), c600 = crossing(600), c1200 = crossing(1200);
  std::vector<double> identity, adm;
  for (const Crossing& c : {c300, c600, c1200}) {
    identity.push_back(std::abs(c.integral - (c.m_0 - c.m_end)));
    adm.push_back(std::abs(c.integral + c.m_end - c.M_adm));
  }
  const std::vector<double> h{1.0 / 300, 1.0 / 600, 1.0 / 1200};
  const double order = gbssn1d::testing::fit_order(h, identity);
  const double adm_order = gbssn1d::testing::fit_order(h, adm);
  MESSAGE(
      fmt::format("M_ADM {:.12g}; integral of flux_R20 {:.12g}, {:.12g}, {:.12g}; "
                  "identity's error {:.3g}, {:.3g}, {:.3g} (order {:.2f}); m_R20(38) + integral "
                  "- M_ADM {:.3g}, {:.3g}, {:.3g} (order {:.2f})",
                  c1200.M_adm, c300.integral, c600.integral, c1200.integral, identity[0],
                  identity[1], identity[2], order, adm[0], adm[1], adm[2], adm_order));
  // measured: 1.4e-6, 9.0e-8, 5.6e-9 (orders 4.0, 4.0); 1.4e-6, 9.0e-8, 5.3e-9
  CHECK(order > 3.5);
  CHECK(identity[2] < 1e-8);
  CHECK(adm_order > 3.5);
  CHECK(adm[2] < 2e-8);
  // the whole pulse has crossed: what is left inside is below 1e-6 of what crossed
  CHECK(std::abs(c1200.m_end) < 1e-6 * c1200.integral);
  CHECK(c1200.integral == doctest::Approx(c1200.M_adm).epsilon(1e-6));
}

TEST_CASE("--flux-R: a column pair per sphere in the order given, NaN where no sphere of that "
          "areal radius lies on the outer sheet, and no columns without it") {
  const auto out = scratch("energy_flux_columns", true);
  std::filesystem::remove_all(out);
  const auto r = gbssn1d::testing::run(
      "evolve --id wormhole --matter scalar --scalar-amp 0.04 --scalar-r0 10 --scalar-width 2 "
      "--tmax 1 --dt-series 0.5 --flux-R '30, 1.5,1e4' --out "
      + out.string());
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto t = gbssn1d::testing::read_table((out / "timeseries.dat").string());
  const std::vector<std::string> tail(t.columns.end() - 6, t.columns.end());
  CHECK(tail
        == std::vector<std::string>{"m_R30", "flux_R30", "m_R1.5", "flux_R1.5", "m_R10000",
                                    "flux_R10000"});
  // R = 30 lies beyond the shell: the hole's M = 1 and the shell's mass, nothing crossing yet
  CHECK(t.at(0, "m_R30") > 1.6);
  CHECK(t.at(0, "m_R30") < 1.8);
  CHECK(std::abs(t.at(0, "flux_R30")) < 1e-6);
  // 1.5 M lies below the throat's areal radius (2 M), 1e4 M beyond the outer boundary's
  for (const char* column : {"m_R1.5", "flux_R1.5", "m_R10000", "flux_R10000"})
    CHECK(std::isnan(t.at(0, column)));
  std::filesystem::remove_all(out);
  const auto plain =
      gbssn1d::testing::run("evolve --id wormhole --matter scalar --tmax 0 --out " + out.string());
  REQUIRE(plain.status == 0);
  const auto none = gbssn1d::testing::read_table((out / "timeseries.dat").string());
  CHECK(none.columns.back() == "Pi_center");
  std::filesystem::remove_all(out);
}

TEST_CASE("converge with --flux-R: every member completes and its series carries the sphere's "
          "columns") {
  const auto out = scratch("energy_flux_converge", true);
  std::filesystem::remove_all(out);
  const auto r = gbssn1d::testing::run(
      "converge --N 100,150,200 --id flat --matter scalar --grid uniform --rmax 40 --tmax 2 "
      "--dt-series 0.1 --flux-R 20 --out "
      + out.string());
  INFO(r.err);
  CHECK(r.status == 0);
  CHECK(r.err.find("completed at t = 2") != std::string::npos);
  for (const char* member : {"N100", "N150", "N200"}) {
    const auto t = gbssn1d::testing::read_table((out / member / "timeseries.dat").string());
    CHECK(t.columns.back() == "flux_R20");
    CHECK(t.at(0, "m_R20") > 0.04); // the pulse's mass, 0.0406
  }
  std::filesystem::remove_all(out);
}
