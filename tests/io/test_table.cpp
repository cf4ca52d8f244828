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

TEST_CASE("table_cell: decimal numbers, the words gbssn1d writes for non-finite values, words") {
  using Kind = TableCell::Kind;
  CHECK(table_cell("0.9").kind == Kind::number);
  CHECK(table_cell("-2.5e-3").value == -2.5e-3);
  CHECK(table_cell("+1").value == 1.0);
  CHECK(table_cell(".5").value == 0.5);
  CHECK(table_cell("4.9406564584124654e-324").kind == Kind::number); // a denormal
  CHECK(std::isnan(table_cell("nan").value));
  CHECK(table_cell("nan").kind == Kind::number);
  CHECK(std::isnan(table_cell("-nan").value));
  CHECK(table_cell("inf").value == INFINITY);
  CHECK(table_cell("-inf").value == -INFINITY);
  for (const char* word : {"ok", "blew-up", "-", "along_rahA", "NaN", "infinity"}) {
    INFO(word);
    CHECK(table_cell(word).kind == Kind::word);
    CHECK(std::isnan(table_cell(word).value));
  }
  for (const char* bad : {"0,9", "0.9abc", "0x1", "1e999", "1e-400", "1..2", "-0x1p3", "1e", "1-2",
                          ".", "-.", "0.9\x1b"}) {
    INFO(bad);
    CHECK(table_cell(bad).kind == Kind::malformed);
  }
}

TEST_CASE("read_table: a malformed number is refused, naming the file, the line and the column") {
  const auto path = std::filesystem::temp_directory_path()
                    / ("gbssn1d_table_bad_" + std::to_string(::getpid()) + ".dat");
  auto refused = [&](const std::string& text) {
    std::ofstream(path) << text;
    try {
      (void)read_table(path);
    } catch (const TableError& e) {
      CHECK(std::string(e.what()).find(path.string() + ", ") == 0);
      return e.reason();
    }
    FAIL("not refused: " << text);
    return std::string();
  };
  CHECK(refused("# t r_ah\n0 0.9\n0.5 0,9\n")
        == "line 3: '0,9' in column r_ah is not a number "
           "(a decimal number, nan or inf)");
  CHECK(refused("# t r_ah\n0 0.9abc\n").find("line 2: '0.9abc' in column r_ah") == 0);
  CHECK(refused("# t r_ah\n0x1 0.9\n").find("line 2: '0x1' in column t") == 0);
  CHECK(refused("# t\n1 2 3e999x\n").find("line 2: '3e999x' is not a number") == 0); // no name
  // well formed but beyond a double: said so, not "not a number"
  CHECK(refused("# t r_ah\n0 1e999\n")
        == "line 2: '1e999' in column r_ah is too large in magnitude for a double (beyond about "
           "1.8e308)");
  CHECK(refused("# t r_ah\n1e-400 0.9\n").find("line 2: '1e-400' in column t is too small") == 0);
  // words and the non-finite values are read, each row with its line
  std::ofstream(path) << "# gbssn1d 0.1.0\n# N status t\n\n1 ok nan\n2 - -inf\n";
  const Table t = read_table(path);
  REQUIRE(t.rows.size() == 2);
  CHECK(t.lines == std::vector<std::size_t>{4, 5});
  CHECK(std::isnan(t.rows[0][1]));
  CHECK(std::isnan(t.rows[0][2]));
  CHECK(t.rows[1][2] == -INFINITY);
  std::filesystem::remove(path);
  try {
    (void)read_table(path);
    FAIL("a missing file read");
  } catch (const TableError& e) {
    CHECK(e.reason() == "cannot be opened");
  }
}
