// Configuration files written on Windows (CRLF line ends) read as their LF twins: the carriage
// return ends a bare value, a blank line and a comment line as a line end does.
#include "config/config_file.hpp"
#include "config/params.hpp"

#include "../test_support.hpp"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>

using namespace gbssn1d;
namespace fs = std::filesystem;

namespace {

std::string crlf(const std::string& lf) {
  std::string out;
  for (const char c : lf)
    out += c == '\n' ? std::string("\r\n") : std::string(1, c);
  return out;
}

/// The effective configuration of `evolve --config FILE` with `text` in FILE.
std::string config_of_file(const fs::path& dir, const std::string& name, const std::string& text) {
  const fs::path file = dir / name;
  std::ofstream(file, std::ios::binary) << text;
  return config_text(parse_evolve_args({"--config", file.string()}));
}

} // namespace

// Guards the bare value's end at '\r' (config/config_reader.cpp): without it every CRLF file was
// refused ('400\r' is not a number).
TEST_CASE("a config file with CRLF line ends reads as the same file with LF ones") {
  Params p;
  p.N = 400;
  p.rmax = 20.5;
  p.id = InitialDataKind::onelog_trumpet;
  p.grid = RadialGrid::uniform;
  p.rahA = 0.5;
  p.tmax = 12.25;
  p.out = "a folder#1";
  const std::string written = config_text(p); // as a run writes config.toml
  const std::string hand = "# written by hand\n"
                           "\n"
                           "N = 320   # cells\n"
                           "   \n"
                           "rmax = 24\n"
                           "id = 'maximal-trumpet'\n"
                           "out = \"run \\\"x\\\"\"  # quoted\n"
                           "tmax = 3"; // no line end after the last value
  const fs::path dir = gbssn1d::testing::scratch("config_crlf", true);
  for (const std::string& lf : {written, hand}) {
    INFO(lf);
    const auto items = read_config_text(lf, "lf.toml");
    REQUIRE(!items.empty());
    CHECK(read_config_text(crlf(lf), "crlf.toml") == items);
    for (const auto& [key, value] : items)
      CHECK(value.find('\r') == std::string::npos);
    // and through evolve's --config: the same parameters
    CHECK(config_of_file(dir, "crlf.toml", crlf(lf)) == config_of_file(dir, "lf.toml", lf));
  }
  // a last line ending in a lone carriage return, too
  CHECK(read_config_text("N = 320\r", "f") == read_config_text("N = 320", "f"));
  fs::remove_all(dir);
}
