// A sweep's spike flag (study/sweep_summary.cpp) on member folders written here, as a finished
// sweep leaves them: the median a member is compared with is that of its neighbours along an
// axis, the other members only, so that even a sweep of two members flags a spike.
#include "study/sweep_summary.hpp"

#include "../test_support.hpp"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace gbssn1d;
namespace fs = std::filesystem;

namespace {

/// The summary.dat rows of a sweep over rahA whose members finished with the given maxima of
/// H_L2_R (written into folders under `dir`).
std::vector<std::string> summary_for(const fs::path& dir, const std::vector<double>& H_R_max) {
  fs::create_directories(dir / "logs");
  SweepAxis axis{{"rahA"}, {}};
  std::vector<SweepMember> members;
  for (std::size_t k = 0; k < H_R_max.size(); ++k) {
    const std::string value = fmt::format("0.{}", k + 1);
    axis.values.push_back({value});
    SweepMember m;
    m.name = "rahA=" + value;
    m.values = {{"rahA", value}};
    m.tmax = 1.0;
    members.push_back(m);
    fs::create_directories(dir / m.name);
    std::ofstream(dir / "logs" / (m.name + ".status")) << "ok 1.0 -\n";
    std::ofstream(dir / m.name / "timeseries.dat") << fmt::format(
        "# t H_L2_R\n0 {:.6e}\n1 {:.6e}\n# end: completed at t = 1\n", H_R_max[k] / 2, H_R_max[k]);
  }
  SweepOptions options;
  options.sweeps = {"rahA=..."};
  options.out = dir.string();
  options.collect = true;
  const auto statuses = write_summary(dir, options, {axis}, members);
  CHECK(exit_status(statuses, members.size()) == 0);
  std::ifstream in(dir / "summary.dat");
  std::vector<std::string> rows;
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#')
      rows.push_back(line);
  REQUIRE(rows.size() == H_R_max.size());
  return rows;
}

} // namespace

// Guards the neighbours' median: with the member itself among them, a two-member sweep's
// median is the geometric mean of the pair, and a member 4495 times the other was not flagged.
TEST_CASE("sweep spikes: the median is the neighbours' alone, so a two-member sweep flags its "
          "spike") {
  const fs::path dir = gbssn1d::testing::scratch("sweep_spikes_pair", true);
  auto rows = summary_for(dir, {1e-7, 4.495e-4});
  CHECK(rows[0].find("0.1 ok - ") == 0);
  CHECK(rows[1].find("0.2 ok spike ") == 0);
  CHECK(rows[1].find("is_4495_times_the_median_1.00e-07_of_its_neighbours_along_rahA")
        != std::string::npos);
  // below the factor (100 times the other) nothing is flagged, in either order
  fs::remove_all(dir);
  rows = summary_for(dir, {5e-6, 1e-7}); // 50 times
  CHECK(rows[0].find("0.1 ok - ") == 0);
  CHECK(rows[1].find("0.2 ok - ") == 0);
  // three members: the median of the other two
  fs::remove_all(dir);
  rows = summary_for(dir, {1e-7, 3e-7, 2.5e-5});
  CHECK(rows[0].find("0.1 ok - ") == 0);
  CHECK(rows[1].find("0.2 ok - ") == 0);
  CHECK(rows[2].find("0.3 ok spike ") == 0);
  CHECK(rows[2].find("is_144_times_the_median_1.73e-07") != std::string::npos);
  fs::remove_all(dir);
}
