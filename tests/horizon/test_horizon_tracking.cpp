// The horizon shift follows the apparent horizon down to the first cells of the grid, and a
// horizon it followed that is lost stops the run (exit 3, a message naming the time and the last
// radius, in stderr and as timeseries.dat's end line) instead of letting beta_H switch off.
#include "../test_support.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace fs = std::filesystem;

namespace {

using gbssn1d::testing::scratch;

struct Result {
  int status;
  std::string err;
};

using gbssn1d::testing::slurp;

Result run(const std::string& args) {
  const fs::path err = scratch("tracking_stderr");
  const std::string cmd =
      std::string(GBSSN1D_EXECUTABLE) + " " + args + " >/dev/null 2>" + err.string();
  const int raw = std::system(cmd.c_str());
  Result r{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(err)};
  fs::remove(err);
  return r;
}

} // namespace

// Spacing M/8, the horizon shift pulling the horizon towards 0.35 M: r_AH falls below 3.5 cells
// (0.4375 M) at t ~ 8.25, where the finder that skipped the innermost three cells lost it and
// beta_H switched off (exit 0, no word).
TEST_CASE("the horizon shift keeps its horizon below 3.5 cells from the origin") {
  const fs::path out = scratch("tracking_small_h");
  const Result r = run("evolve --id 1log-trumpet --grid uniform --N 128 --rmax 16 --rahA 0.5 "
                       "--rah0 0.35 --tmax 10 --dt-series 0.25 --out "
                       + out.string());
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto h = gbssn1d::testing::read_table((out / "horizon.dat").string());
  REQUIRE(h.rows.size() == 41);
  double r_min = 1e300;
  for (std::size_t k = 0; k < h.rows.size(); ++k) {
    INFO("t = " << h.at(k, "t"));
    CHECK(std::isfinite(h.at(k, "r_ah")));
    r_min = std::min(r_min, h.at(k, "r_ah"));
  }
  CHECK(r_min < 3.5 * 16.0 / 128.0); // the case is reached
  CHECK(r.err.find("no apparent horizon") == std::string::npos);
  fs::remove_all(out);
}

// Spacing M/2, pulled towards 0.1 M: the horizon reaches the first cell (r = 0.25) and is lost
// at t ~ 6, in each way the radius is measured (every RK substage, every step, every 4 steps).
TEST_CASE("a horizon lost while the horizon shift follows it stops the run, naming t and r_AH") {
  for (const char* every : {"", "--ah-every step", "--ah-every 4"}) {
    const fs::path out = scratch("tracking_lost");
    const Result r = run(std::string("evolve --id 1log-trumpet --grid uniform --N 32 --rmax 16 "
                                     "--rahA 0.5 --rah0 0.1 --tmax 10 --dt-series 0.5 ")
                         + every + " --out " + out.string());
    INFO(every << "\n" << r.err);
    CHECK(r.status == 3);
    const std::string what = "the apparent horizon was lost at t = ";
    const auto at = r.err.find("error: " + what);
    REQUIRE(at != std::string::npos);
    const double t_lost = std::strtod(r.err.c_str() + at + 7 + what.size(), nullptr);
    const auto last = r.err.find("last found at r_AH = ", at);
    REQUIRE(last != std::string::npos);
    const double r_last = std::strtod(r.err.c_str() + last + 21, nullptr);
    CHECK(r_last > 0.0);
    CHECK(r_last < 0.5); // within the first cell's width
    CHECK(t_lost > 4.0);
    CHECK(t_lost < 8.0);
    CHECK(r.err.find("beta_H would switch off") != std::string::npos);
    // the note in the output: timeseries.dat's end line, after its rows up to t_lost
    const std::string series = slurp(out / "timeseries.dat");
    const auto end = series.rfind("# end: ");
    REQUIRE(end != std::string::npos);
    CHECK(series.substr(end).find("# end: stopped: " + what) == 0);
    const auto rows = gbssn1d::testing::read_table((out / "timeseries.dat").string());
    CHECK(rows.at(rows.rows.size() - 1, "t") <= t_lost);
    CHECK(rows.at(rows.rows.size() - 1, "t") > t_lost - 0.5 - 1e-9);
    fs::remove_all(out);
  }
}
