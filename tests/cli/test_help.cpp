// What the top-level help and the resume message print: a help page that ends in a sentence, and
// times as the decimals they stand for.
#include "cli_support.hpp"

#include <doctest/doctest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace fs = std::filesystem;

namespace {

using gbssn1d::testing::scratch;

using gbssn1d::testing::Result;
using gbssn1d::testing::run;
using gbssn1d::testing::slurp;

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

/// The value after `key` in `text` up to the next space or parenthesis: "0.3" of "t = 0.3 (".
std::string value_after(const std::string& text, const std::string& key) {
  const auto at = text.find(key);
  if (at == std::string::npos)
    return "(no '" + key + "')";
  const auto start = at + key.size();
  return text.substr(start, text.find_first_of(" )\n", start) - start);
}

} // namespace

TEST_CASE("gbssn1d --help ends in a sentence that names the subcommands' own help pages, and "
          "announces no list it does not give") {
  const Result r = run("--help");
  REQUIRE(r.status == 0);
  const auto lines = lines_of(r.out);
  std::vector<std::string> filled;
  for (const auto& line : lines)
    if (line.find_first_not_of(' ') != std::string::npos)
      filled.push_back(line);
  REQUIRE(!filled.empty());
  INFO(r.out);
  // a line ending in ':' announces what follows: only CLI11's own sections do (before the fix
  // the evolve entry ended in "All flags, grouped:", followed by the next subcommand)
  for (const auto& line : filled)
    if (line.back() == ':')
      CHECK_MESSAGE((line == "Options:" || line == "Subcommands:"), line);
  const std::string& last = filled.back();
  CHECK(last.back() == '.');
  CHECK(r.out.find("gbssn1d evolve --help") != std::string::npos);
  for (const char* sub : {"evolve", "resume", "converge", "sweep"})
    CHECK(r.out.find(std::string("gbssn1d ") + sub + " --help") != std::string::npos);
}

TEST_CASE("resume says the checkpoint's time as the decimal it stands for: t = 0.3, not "
          "0.30000000000000004") {
  // dt = 0.1 (cfl 0.5 x dr 0.2): three steps give t = 0.1 + 0.1 + 0.1 = 0.30000000000000004 in
  // binary, where --checkpoint-every 0.25 writes the checkpoint
  const fs::path dir = scratch("help_resume_time");
  REQUIRE(run("evolve --id 1log-trumpet --grid uniform --N 100 --rmax 20 --tmax 0.5 "
              "--checkpoint-every 0.25 --out "
              + dir.string())
              .status
          == 0);
  const Result early = run("resume " + dir.string() + " --tmax 0.2");
  INFO(early.err);
  CHECK(early.status == 2);
  CHECK(value_after(early.err, "before the checkpoint at t = ") == "0.3");
  const Result resumed = run("resume " + dir.string() + " --tmax 0.6");
  INFO(resumed.err);
  CHECK(resumed.status == 0);
  CHECK(value_after(resumed.err, "resuming " + dir.string() + " at t = ") == "0.3");
  CHECK(value_after(resumed.err, "to t = ") == "0.6");
  fs::remove_all(dir);
}
