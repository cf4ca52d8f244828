// The output files hold what their column names say: each column of profiles.dat and
// timeseries.dat compared with the quantity computed directly from the state.
#include "config/params.hpp"
#include "evolution/simulation.hpp"
#include "io/output.hpp"

#include "../test_support.hpp"

#include "../simulation_support.hpp"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <random>
#include <string>
#include <unistd.h>
#include <vector>

using namespace gbssn1d;
using gbssn1d::testing::simulation;
using gbssn1d::testing::small_trumpet_params;

TEST_CASE("output columns: each named column holds that quantity (H, M_r, fields, norms)") {
  namespace fs = std::filesystem;
  const fs::path dir = gbssn1d::testing::scratch("columns", true);
  Params p;
  p.id = InitialDataKind::wormhole; // H and M_r differ clearly on these data (a coarse grid)
  p.grid = RadialGrid::uniform;
  p.N = 100;
  p.rmax = 20.0;
  p.tmax = 1.0;
  p.dt_series = 1.0;
  p.dt_profiles = 1.0;
  Simulation sim = simulation(p);
  {
    Output out(dir, sim.run_facts(), Formulation::bssn, {});
    sim.run(&out);
  }
  const Grid& g = sim.grid();
  const DerivedProfiles d = derived_profiles(sim.state(), g);
  // profiles.dat: the first block is t = 0; read the last block by hand
  const auto profiles = gbssn1d::testing::read_table((dir / "profiles.dat").string());
  REQUIRE(profiles.rows.size() == g.n_interior()); // the first block (t = 0)
  // timeseries.dat: the row at t = 1 against the norms of the final state
  const auto series = gbssn1d::testing::read_table((dir / "timeseries.dat").string());
  REQUIRE(series.rows.size() == 2);
  const double inf = std::numeric_limits<double>::infinity();
  CHECK(series.at(1, "t") == 1.0);
  CHECK(series.at(1, "H_L2") == doctest::Approx(l2_norm(d.H, g, 0.0, inf)).epsilon(1e-12));
  CHECK(series.at(1, "M_L2") == doctest::Approx(l2_norm(d.M_r, g, 0.0, inf)).epsilon(1e-12));
  CHECK(series.at(1, "G_L2") == doctest::Approx(l2_norm(d.G_r, g, 0.0, inf)).epsilon(1e-12));
  CHECK(std::abs(series.at(1, "H_L2") - series.at(1, "M_L2")) > 1e-6 * series.at(1, "H_L2"));
  // the initial block against the initial data's own derived profiles
  Simulation fresh = simulation(p);
  const DerivedProfiles d0 = derived_profiles(fresh.state(), fresh.grid());
  for (std::size_t k = 0; k < g.n_interior(); k += 7) {
    const std::size_t i = g.first_interior() + k;
    INFO("r = " << g.r()[i]);
    CHECK(profiles.rows[k][0] == doctest::Approx(g.r()[i]).epsilon(1e-15));
    CHECK(profiles.at(k, "H") == doctest::Approx(d0.H[k]).epsilon(1e-12).scale(1e-14));
    CHECK(profiles.at(k, "M_r") == doctest::Approx(d0.M_r[k]).epsilon(1e-12).scale(1e-14));
    CHECK(profiles.at(k, "G_r") == doctest::Approx(d0.G_r[k]).epsilon(1e-12).scale(1e-14));
    CHECK(profiles.at(k, "R_areal") == doctest::Approx(d0.R_areal[k]).epsilon(1e-14));
    CHECK(profiles.at(k, "Theta_plus") == doctest::Approx(d0.Theta_plus[k]).epsilon(1e-12));
    for (const auto& e : evolved(Formulation::bssn))
      CHECK(profiles.at(k, std::string(e.name))
            == doctest::Approx(field(fresh.state(), g, e.var)[i]).epsilon(1e-15));
  }
  fs::remove_all(dir);
}

TEST_CASE("output times are the decimals they stand for (23 x 0.1 prints as 2.3)") {
  namespace fs = std::filesystem;
  const fs::path dir = gbssn1d::testing::scratch("decimal_times", true);
  Params p = small_trumpet_params(60, 20.0);
  p.tmax = 3.05; // the last row at tmax, not a multiple of the cadence
  p.dt_series = 0.1;
  p.dt_profiles = 0.7;
  Simulation sim = simulation(p);
  {
    Output out(dir, sim.run_facts(), Formulation::bssn, {});
    sim.run(&out);
  }
  // the first word of every row (and of every profile block's "# t = " line)
  auto times = [](const fs::path& file, const std::string& prefix) {
    std::ifstream in(file);
    std::vector<std::string> t;
    for (std::string line; std::getline(in, line);)
      if (!line.empty() && (prefix.empty() ? line[0] != '#' : line.rfind(prefix, 0) == 0))
        t.push_back(line.substr(prefix.size(), line.find(' ', prefix.size()) - prefix.size()));
    return t;
  };
  const auto series = times(dir / "timeseries.dat", "");
  REQUIRE(series.size() == 32); // 0, 0.1, ..., 3.0, and 3.05
  for (std::size_t k = 0; k + 1 < series.size(); ++k) {
    // k/10 written the way a person writes it: "0", "0.1", ..., "2.3", ..., "3"
    const std::string expected = k % 10 == 0
                                     ? std::to_string(k / 10)
                                     : std::to_string(k / 10) + "." + std::to_string(k % 10);
    CHECK(series[k] == expected);
  }
  CHECK(series.back() == "3.05");
  CHECK(times(dir / "horizon.dat", "")[23] == "2.3");
  const auto blocks = times(dir / "profiles.dat", "# t = ");
  REQUIRE(blocks.size() == 6); // 0, 0.7, 1.4, 2.1, 2.8 and tmax
  CHECK(blocks[2] == "1.4");
  CHECK(blocks[3] == "2.1");
  CHECK(blocks.back() == "3.05");
}

TEST_CASE("output files are never written through a symbolic link: a link where a file goes is "
          "an error naming it, and its target is left alone") {
  const auto dir = gbssn1d::testing::scratch("output_links", true);
  const auto target = dir / "target.txt";
  std::ofstream(target) << "precious\n";
  std::filesystem::create_symlink(target, dir / "timeseries.dat");
  std::filesystem::create_symlink(target, dir / "config.toml.tmp");
  for (auto write :
       {std::function<void()>([&] { DataFile(dir / "timeseries.dat", "", {"t"}); }),
        std::function<void()>([&] { write_file_atomically(dir / "config.toml", "N = 1\n"); })}) {
    try {
      write();
      FAIL("written through a link");
    } catch (const OutputError& e) {
      CHECK(std::string(e.what()).find("symbolic link") != std::string::npos);
    }
  }
  std::ifstream in(target);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(text == "precious\n");
  std::filesystem::remove_all(dir);
}

TEST_CASE("append_scientific writes every double as fmt's {:.16e} does, byte for byte") {
  // random bit patterns (every exponent, subnormals, NaNs of both signs) and decimal magnitudes
  // from 1e-300 to 1e300, then the special values
  std::mt19937_64 bits(7);
  std::uniform_real_distribution<double> decade(-300.0, 300.0);
  std::vector<double> values;
  for (int k = 0; k < 500000; ++k) {
    const std::uint64_t b = bits();
    double x = 0.0;
    std::memcpy(&x, &b, sizeof x);
    values.push_back(x);
    values.push_back((b & 1 ? -1.0 : 1.0) * std::pow(10.0, decade(bits)));
  }
  for (double x :
       {0.0, -0.0, 1.0, -1.0, 0.1, 1e23, 9.9999999999999995e22, 5e-324, -5e-324,
        2.2250738585072014e-308, 1.7976931348623157e308, std::numeric_limits<double>::quiet_NaN(),
        -std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
        -std::numeric_limits<double>::infinity()})
    values.push_back(x);
  long differ = 0;
  for (double x : values) {
    fmt::memory_buffer fast;
    gbssn1d::append_scientific(fast, x);
    const std::string reference = fmt::format("{:.16e}", x);
    if (std::string(fast.data(), fast.size()) != reference) {
      if (differ < 5)
        MESSAGE("append_scientific " << std::string(fast.data(), fast.size()) << ", fmt "
                                     << reference);
      ++differ;
    }
  }
  CHECK(differ == 0);
}

// The profiles' beta is the whole shift the equations see, beta_GD + beta_H (the evolved
// beta is beta_GD alone), with beta_GD and beta_H beside it: with the horizon shift on, the
// three columns at t = 0 on a 1+log trumpet whose horizon (0.83 M) is pushed towards 1.2 M.
TEST_CASE("profiles.dat: beta is beta_GD + beta_H, beta_GD the evolved shift, with the horizon "
          "shift on") {
  namespace fs = std::filesystem;
  const fs::path dir = gbssn1d::testing::scratch("beta_columns", true);
  Params p = small_trumpet_params(64, 16.0);
  p.tmax = 0.0;
  p.rahA = 0.5;
  p.rah0 = 1.2;
  Simulation sim = simulation(p);
  {
    Output out(dir, sim.run_facts(), Formulation::bssn, {});
    sim.run(&out);
  }
  const Grid& g = sim.grid();
  const auto profiles = gbssn1d::testing::read_table((dir / "profiles.dat").string());
  REQUIRE(profiles.rows.size() == g.n_interior());
  std::size_t shifted = 0;
  for (std::size_t k = 0; k < g.n_interior(); ++k) {
    const std::size_t i = g.first_interior() + k;
    INFO("r = " << g.r()[i]);
    const double beta_GD = profiles.at(k, "beta_GD"), beta_H = profiles.at(k, "beta_H");
    CHECK(beta_GD == field(sim.state(), g, Var::beta)[i]); // 17 digits: read back exactly
    CHECK(profiles.at(k, "beta") == beta_GD + beta_H);
    shifted += std::abs(beta_H) > 1e-4 ? 1 : 0;
  }
  // the check is not about zeros: beta_H is well away from zero over much of the grid
  CHECK(shifted > g.n_interior() / 4);
  fs::remove_all(dir);
}
