// An open-loop h_AH(t) read from a file (io/horizon_file.hpp): every number checked, t finite
// and increasing, r_ah a finite positive radius, each refusal naming the line and why.
#include "io/horizon_file.hpp"

#include "../test_support.hpp"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

using namespace gbssn1d;

namespace {

/// A file of five rows at t = 0, 0.5, ... 2 whose second row (line 3) is `row`.
std::string with_row(const std::string& row) {
  return "# t r_ah\n0 0.9\n" + row + "\n1 0.9\n1.5 0.9\n2 0.9\n";
}

} // namespace

TEST_CASE("an h_AH file: every number checked, each refusal naming the line and why") {
  const auto path = gbssn1d::testing::scratch("hAH_file.dat");
  auto refusal = [&](const std::string& text) {
    std::ofstream(path) << text;
    try {
      (void)read_horizon_history(path.string(), 1.0);
    } catch (const HorizonFileError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  CHECK(refusal(with_row("0.5 0,9")).find("line 3: '0,9' in column r_ah is not a number") == 0);
  CHECK(refusal(with_row("0.5 0.9abc")).find("line 3: '0.9abc' in column r_ah") == 0);
  CHECK(refusal(with_row("0.5 0x1")).find("line 3: '0x1' in column r_ah") == 0);
  CHECK(refusal(with_row("0.5e 0.9")).find("line 3: '0.5e' in column t") == 0);
  CHECK(refusal(with_row("0.5 -0.9")) == "line 3: r_ah = -0.9 is not a radius (must be positive)");
  CHECK(refusal(with_row("0.5 0")) == "line 3: r_ah = 0 is not a radius (must be positive)");
  CHECK(refusal(with_row("0.5 -inf")) == "line 3: r_ah = '-inf' is not finite");
  CHECK(refusal(with_row("0.5 nan")) == "line 3: has no horizon (r_ah = nan) at t = 0.5");
  CHECK(refusal(with_row("0.5 abc")) == "line 3: r_ah = 'abc' is not a number");
  CHECK(refusal(with_row("nan 0.9")) == "line 3: t = 'nan' is not finite");
  CHECK(refusal(with_row("inf 0.9")) == "line 3: t = 'inf' is not finite");
  CHECK(refusal(with_row("0 0.9"))
        == "line 3: t = 0 does not follow t = 0 of the row before (times must increase)");
  CHECK(refusal(with_row("0.5"))
        == "line 3: 1 column where the header names 2 (t r_ah): a row cut short (the file "
           "truncated?)");
  CHECK(refusal(with_row("0.5 0.9 1")).find("line 3: 3 columns where the header names 2") == 0);
  // a horizon.dat cut short in its last row: t and r_ah are there, the other columns are not
  // (the row is not the run's: its r_ah lost digits with them)
  const std::string columns = "# t r_ah R_ah M_ah n_ah r_in R_in r_in2 R_in2 level\n";
  auto full = [](double t) { return fmt::format("{} 0.9 1.8 1 2 0.5 0.9 nan nan 0\n", t); };
  std::string cut = columns;
  for (int k = 0; k < 4; ++k)
    cut += full(0.5 * k);
  CHECK(refusal(cut + "2 1.140")
        == "line 6: 2 columns where the header names 10 (t r_ah R_ah M_ah n_ah r_in R_in r_in2 "
           "R_in2 level): a row cut short (the file truncated?)");
  CHECK(refusal(cut + full(2.0)) == "accepted");
  CHECK(refusal(with_row("0.7 0.9")) == "line 3: t = 0.7: its times are not equally spaced");
  // comments and the blank lines between header and rows count as lines
  CHECK(refusal("# gbssn1d 0.1.0\n\n# t r_ah\n0 0.9\n0.5 0.9\n1 -1\n")
        == "line 6: r_ah = -1 is not a radius (must be positive)");
  // a good file: the spline through its radii
  CHECK(refusal(with_row("0.5 0.9")) == "accepted");
  std::ofstream(path) << with_row("0.5 0.9");
  CHECK(read_horizon_history(path.string(), 2.0)(0.75) == doctest::Approx(0.9));
  std::filesystem::remove(path);
}
