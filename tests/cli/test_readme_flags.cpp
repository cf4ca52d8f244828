// The README's flag table and the evolve flags cannot drift apart: every flag of `evolve` is in
// the table, every flag the table names exists, and every default the table shows as a number
// is the flag's default (the value --help shows).
#include "config/config_file.hpp"

#include <CLI/CLI.hpp>
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>

using namespace gbssn1d;

TEST_CASE("the README's flag table lists every evolve flag with its default") {
  std::ifstream in(std::filesystem::path(GBSSN1D_SOURCE_DIR) / "README.md");
  REQUIRE(in);
  // the table: the lines from "| group | flags" to the first line that is not a table row
  std::string table, line;
  bool inside = false;
  while (std::getline(in, line)) {
    if (line.rfind("| group | flags", 0) == 0)
      inside = true;
    else if (inside && line.rfind("|", 0) != 0)
      break;
    if (inside)
      table += line + "\n";
  }
  REQUIRE(!table.empty());

  CLI::App app;
  Params p;
  add_options(app, p);
  std::map<std::string, std::string> defaults; // flag -> default text shown by --help
  for (const CLI::Option* opt : app.get_options()) {
    for (const std::string& name : opt->get_lnames())
      if (name != "help")
        defaults["--" + name] = opt->get_default_str();
  }
  REQUIRE(defaults.size() > 40);

  // every evolve flag is in the table
  for (const auto& [flag, value] : defaults) {
    INFO(flag);
    CHECK(std::regex_search(table, std::regex("`" + flag + "([ `\\\\]|$)")));
  }
  // every flag the table names exists (besides the configuration flags of the command line)
  const std::regex named("`(--[A-Za-z0-9-]+)");
  for (auto it = std::sregex_iterator(table.begin(), table.end(), named);
       it != std::sregex_iterator(); ++it) {
    const std::string flag = (*it)[1];
    if (flag == "--config" || flag == "--print-config" || flag == "--help")
      continue;
    INFO(flag);
    CHECK(defaults.count(flag) == 1);
  }
  // a default shown as a number is the flag's default
  const std::regex with_number("`(--[A-Za-z0-9-]+) (-?[0-9][0-9.e+-]*)`");
  int compared = 0;
  for (auto it = std::sregex_iterator(table.begin(), table.end(), with_number);
       it != std::sregex_iterator(); ++it) {
    const std::string flag = (*it)[1], shown = (*it)[2];
    if (defaults.count(flag) == 0)
      continue;
    INFO(flag << ": README " << shown << ", --help " << defaults[flag]);
    CHECK(std::stod(shown) == doctest::Approx(std::stod(defaults[flag])));
    ++compared;
  }
  MESSAGE(compared, " defaults compared");
  CHECK(compared >= 15);
}
