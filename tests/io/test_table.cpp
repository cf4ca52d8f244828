// Reading gbssn1d's own tables back (io/table.hpp).
#include "io/table.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

using namespace gbssn1d;

TEST_CASE("read_table: columns from the last '#' line, the first block only") {
  const auto path = std::filesystem::temp_directory_path()
                    / ("gbssn1d_table_" + std::to_string(::getpid()) + ".dat");
  {
    std::ofstream f(path);
    f << "# gbssn1d 0.1.0\n# N = 400\n# r alpha beta\n# t = 0\n"
         "0.5 1 -2\n1.5 0.25 nan\n\n\n# t = 5\n9 9 9\n";
  }
  const Table t = read_table(path);
  REQUIRE(t.columns == std::vector<std::string>{"r", "alpha", "beta"});
  REQUIRE(t.rows.size() == 2); // the second block is not read
  CHECK(t.rows[0] == std::vector<double>{0.5, 1.0, -2.0});
  CHECK(t.rows[1][1] == 0.25);
  CHECK(std::isnan(t.rows[1][2]));
  CHECK(t.column("beta") == 2u);
  CHECK_FALSE(t.column("K").has_value());
  std::filesystem::remove(path);
  CHECK_THROWS_AS(read_table(path), std::runtime_error);
}
