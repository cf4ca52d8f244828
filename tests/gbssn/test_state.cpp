// A state carries its formulation as a tag (gbssn/state.hpp), and each formulation declares
// what the rest of the code asks of it (FormulationTraits, core/registry.hpp).
#include "gbssn/rhs.hpp"
#include "gbssn/state.hpp"
#include "io/output.hpp"

#include <doctest/doctest.h>

#include <stdexcept>
#include <string>
#include <vector>

using namespace gbssn1d;

TEST_CASE("a state carries its formulation: made, fitted, through a right-hand side, and from "
          "a checkpoint's values") {
  const Grid g(RadialMap::uniform(10.0), 40);
  for (const Formulation f : {Formulation::bssn, Formulation::z4c}) {
    INFO(static_cast<int>(f));
    const State u = make_state(g, f);
    CHECK(u.formulation() == f);
    CHECK(u.size() == n_evolved(f) * g.n_total());
    CHECK(u.vars().size() == n_evolved(f));
    State other = make_state(g, f == Formulation::bssn ? Formulation::z4c : Formulation::bssn);
    other.fit(u);
    CHECK(other.formulation() == f);
    CHECK(other.size() == u.size());
    // a right-hand side written into a state of another shape takes its input's
    State flat = make_state(g, f);
    for (const auto& e : flat.vars())
      for (double& v : field(flat, g, e.var))
        v = e.asymptotic;
    State dudt = make_state(g, f == Formulation::bssn ? Formulation::z4c : Formulation::bssn);
    RhsParams params;
    params.formulation = f;
    GbssnRhs(g, params)(flat, dudt, 0.0);
    CHECK(dudt.formulation() == f);
    CHECK(dudt.size() == flat.size());
    // values of whole rows only
    CHECK(State(f, std::vector<double>(u.size(), 1.0), g.n_total()).formulation() == f);
    CHECK_THROWS_AS(State(f, std::vector<double>(u.size() + 1, 1.0), g.n_total()),
                    std::invalid_argument);
  }
  // two states of equal size but other formulations are not equal
  CHECK_FALSE(State(Formulation::bssn, 10) == State(Formulation::z4c, 9));
  CHECK(State(Formulation::bssn, 10).size() == State(Formulation::z4c, 9).size());
}

TEST_CASE("each formulation declares its rows, its ADM K and its own series columns") {
  const FormulationTraits& bssn = traits(Formulation::bssn);
  const FormulationTraits& z4c = traits(Formulation::z4c);
  CHECK(bssn.formulation == Formulation::bssn);
  CHECK(z4c.formulation == Formulation::z4c);
  CHECK_FALSE(bssn.evolves(Var::Theta));
  CHECK(bssn.evolves(Var::Delta_r));
  CHECK(z4c.evolves(Var::Theta));
  CHECK(bssn.K_is_adm());
  CHECK_FALSE(z4c.K_is_adm());
  CHECK(adm_K(bssn, 0.25, 7.0) == 0.25);      // Theta is not BSSN's: not read
  CHECK(adm_K(z4c, 0.25, 0.5) == 0.25 + 1.0); // K = K-hat + 2 Theta (Z1)
  // the series: every formulation's columns, then its own, in its order
  const auto plain = series_columns(Formulation::bssn);
  const auto own = series_columns(Formulation::z4c);
  REQUIRE(own.size() == plain.size() + z4c.extra_series.size());
  CHECK(bssn.extra_series.empty());
  for (std::size_t k = 0; k < z4c.extra_series.size(); ++k)
    CHECK(own[plain.size() + k] == std::string(z4c.extra_series[k]));
  // each of them has a value in the series row, by name
  SeriesRow row{};
  row.G_L2_R = 1.0;
  row.Theta_L2_ext = 2.0;
  row.Theta_L2_R = 3.0;
  CHECK(row.extra("G_L2_R") == 1.0);
  CHECK(row.extra("Theta_L2_ext") == 2.0);
  CHECK(row.extra("Theta_L2_R") == 3.0);
  CHECK_THROWS_AS((void)row.extra("H_L2"), std::invalid_argument);
  CHECK(bssn.series_legend.empty());
  CHECK(std::string(z4c.series_legend).find("K-hat + 2 Theta") != std::string::npos);
}
