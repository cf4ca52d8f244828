// Every evolve flag, bound and tolerance has a test of its own number:
//  A. every flag of the table (config/flag_table.cpp: param_specs()) changes some number a run
//     writes, and the run key, in a configuration where its row says it acts; the flags that by
//     design change no number are listed with why, and what they do change is checked instead;
//     a flag in neither list fails (a new flag needs a row here);
//  B. every bound, and C. every tolerance: tests/config/test_every_bound.cpp.
#include "../cli/cli_support.hpp"
#include "config/config_file.hpp"
#include "config/flag_table.hpp"
#include "config/param_rules.hpp"
#include "config/params.hpp"
#include "config/same_run.hpp"
#include "evolution/evolution_config.hpp"
#include "evolution/levels.hpp"
#include "gbssn/rhs_params.hpp"
#include "grid/grid.hpp"
#include "mesh/hierarchy.hpp"
#include "mesh/layout.hpp"
#include "mesh/level_steps.hpp"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace gbssn1d;
using gbssn1d::testing::command_words;
using gbssn1d::testing::resolved_evolve;
using gbssn1d::testing::run;
using gbssn1d::testing::scratch;
using gbssn1d::testing::slurp;

// its own namespace: in the sanitizers' unity build it shares a translation unit with
// test_same_run.cpp, whose configurations (trumpet, shifted, boxes) have the same names
namespace every_flag_test {

namespace {

/// What a run wrote: each .dat file's lines that are not '#' comments (headers echo the flags,
/// which differ by design), the number of profile blocks, and whether it left a checkpoint.
struct Written {
  std::map<std::string, std::string> numbers;
  int profile_blocks = 0;
  bool checkpoint = false;
};

Written written(const fs::path& dir) {
  Written w;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().filename() == "checkpoint.bin")
      w.checkpoint = true;
    if (e.path().extension() != ".dat")
      continue;
    std::istringstream in(slurp(e.path()));
    std::string kept;
    for (std::string line; std::getline(in, line);) {
      if (line.rfind("# t = ", 0) == 0 && e.path().filename() == "profiles.dat")
        ++w.profile_blocks;
      if (line.rfind('#', 0) != 0)
        kept += line + "\n";
    }
    w.numbers[e.path().filename().string()] = kept;
  }
  return w;
}

/// What an evolve run with `args` wrote (it must succeed); runs of the same arguments are made
/// once.
const Written& run_of(const std::string& args) {
  static std::map<std::string, Written> done;
  if (const auto it = done.find(args); it != done.end())
    return it->second;
  const fs::path out = scratch("every_flag_run");
  const auto r = run("evolve " + args + " --out " + out.string());
  INFO(args << "\n" << r.err);
  REQUIRE(r.status == 0);
  Written w = written(out);
  REQUIRE(w.numbers.count("timeseries.dat") == 1);
  REQUIRE(w.numbers.count("profiles.dat") == 1);
  fs::remove_all(out);
  return done.emplace(args, std::move(w)).first->second;
}

std::vector<std::string> lines(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);)
    out.push_back(line);
  return out;
}

const ParamSpec* spec_of(const std::string& name) {
  const auto& specs = param_specs();
  const auto it =
      std::find_if(specs.begin(), specs.end(), [&](const ParamSpec& s) { return s.name == name; });
  return it == specs.end() ? nullptr : &*it;
}

// cheap configurations: a 1+log trumpet on 32 uniform cells to t = 0.5 (0.1 s a run)
const std::string rows = " --tmax 0.5 --dt-series 0.25 --dt-profiles 0.5";
const std::string trumpet = "--id 1log-trumpet --grid uniform --N 32 --rmax 16" + rows;
const std::string shifted = trumpet + " --rahA 0.5 --rah0 1";
const std::string boxes = "--id 1log-trumpet --grid boxes --N 32 --rmax 16" + rows;
const std::string z4c = trumpet + " --formulation z4c";
const std::string pulse = "--id flat --matter scalar --grid uniform --N 32 --rmax 16" + rows;

/// A row of A: `flag value` (value "" for a switch) acts on `base`, which does not give it.
struct Acting {
  std::string flag, base, value;
  std::string with() const { return base + " --" + flag + (value.empty() ? "" : " " + value); }
};

/// The flags that by design change no number a run writes, and why.
const std::map<std::string, std::string>& exempt_from_numbers() {
  static const std::map<std::string, std::string> exempt{
      {"dt-series", "a cadence: which rows of timeseries.dat are written, not their numbers"},
      {"dt-profiles", "a cadence: which blocks of profiles.dat are written, not their numbers"},
      {"checkpoint-every", "a cadence of checkpoint.bin, which a resume reads; no .dat number"},
      {"out", "the folder's name: the same run wherever it is written"},
      {"force", "permission to write into a non-empty folder: the same run"},
  };
  return exempt;
}

} // namespace

TEST_CASE("every flag acts where its table row says it acts: a number the run writes and the run "
          "key change with it, and the flags that change no number by design do what they do") {
  const fs::path hAH = scratch("every_flag_hAH.dat");
  {
    std::ofstream f(hAH);
    f << "# t r_ah\n";
    for (int k = 0; k <= 4; ++k)
      f << 0.25 * k << " " << 0.8304 + 0.01 * k << "\n";
  }
  const std::string boxes64 = "--id 1log-trumpet --grid boxes --N 32 --rmax 64" + rows;
  const std::vector<Acting> table{
      // the grid (a base without the flag takes its default)
      {"N", "--id 1log-trumpet --grid uniform --rmax 16" + rows, "48"},
      {"rmax", "--id 1log-trumpet --grid uniform --N 32 --eta 0.1" + rows, "16"},
      {"grid", "--id 1log-trumpet --N 32 --rmax 16" + rows, "uniform"},
      {"levels", boxes, "2"}, // (the rule gives 3)
      {"time-interp", boxes, "quadratic"},
      {"no-subcycling", boxes, ""},
      // tapered only where a fine box reaches beyond --box-taper-from (16 M): rmax 64
      {"box-taper", boxes64, "0.25"},
      {"box-taper-from", boxes, "2"},
      {"dr-inner", "--id 1log-trumpet --N 32 --rmax 16" + rows, "0.03"},
      // initial data and formulation
      {"id", "--grid uniform --N 32 --rmax 16" + rows, "1log-trumpet"},
      {"M", trumpet, "1.1"},
      {"lapse0", "--grid uniform --N 32 --rmax 16" + rows, "one"},
      {"formulation", trumpet, "z4c"},
      {"gbssn-volume", trumpet, "eulerian"},
      {"kappa1", z4c, "0.3"},
      {"kappa1-hole", z4c, "0"},
      {"kappa2", z4c, "0.5"},
      {"z4c-lapse-adm", z4c, ""},
      {"matter", "--id flat --grid uniform --N 32 --rmax 16" + rows, "scalar"},
      {"scalar-amp", pulse, "0.02"},
      {"scalar-r0", pulse, "8"},
      {"scalar-width", pulse, "1.5"},
      {"flux-R", pulse, "5"},
      // gauge and numerics
      {"eta", trumpet, "1"},
      {"advective-shift", trumpet, ""},
      {"non-advective-lapse", trumpet, ""},
      {"shift", "--id wormhole --grid uniform --N 32 --rmax 16" + rows, "zero"},
      {"cfl", trumpet, "0.25"},
      {"ko-sigma", trumpet, "0.2"},
      {"fd-order", trumpet, "6"},
      {"upwind", trumpet, "biased"},
      {"chi-floor", trumpet, "0.1"}, // (0.01 lies below chi at every cell of this run)
      {"driver-advection", trumpet, "centred"},
      {"delta-advection", trumpet, "centred"},
      {"tmax",
       "--id 1log-trumpet --grid uniform --N 32 --rmax 16 --dt-series 0.25 --dt-profiles "
       "0.5",
       "1"},
      // the norm windows
      {"norm-rmin", trumpet, "2"},
      {"norm-rmax", trumpet, "6"},
      {"norm-Rmin", trumpet, "3"},
      {"norm-Rmax", trumpet, "6"},
      {"norm-Rint", trumpet, "1.5"},
      // the horizon-adjusting shift and its searches
      {"rahA", trumpet, "0.5"},
      {"rah0", trumpet + " --rahA 0.5", "1.2"},
      {"rah-width", shifted + " --rah-profile rational", "2"},
      {"rah-rcut", shifted, "6"},
      {"rah-taper", shifted, "step"},
      {"rah-ramp", shifted, "3"},
      {"rah-profile", shifted, "gauss"},
      {"rah-normal", shifted, "unit"},
      {"rah-chi-smooth", shifted + " --rah-normal smooth", "0.1"},
      {"rah-hAH-file", shifted, hAH.string()},
      {"ah-every", shifted, "4"},
      {"ah-interval", shifted, "0.1"},
      {"ah-tmin", shifted, "0.25"},
      {"ah-tmax", shifted, "0.25"},
      {"ah-tol", trumpet, "1e-5"},
      {"rah-variant", shifted, "driver-full-shift"},
  };

  // complete: every flag of the table has a row or a reason, and no row names another
  std::set<std::string> covered;
  for (const auto& row : table) {
    INFO("row --" << row.flag);
    CHECK(spec_of(row.flag) != nullptr);
    CHECK(covered.insert(row.flag).second); // one row a flag
    CHECK(exempt_from_numbers().count(row.flag) == 0);
  }
  for (const auto& [flag, why] : exempt_from_numbers()) {
    INFO("exempt --" << flag << ": " << why);
    CHECK(spec_of(flag) != nullptr);
    CHECK_FALSE(why.empty());
  }
  for (const auto& spec : param_specs()) {
    INFO("--" << std::string(spec.name)
              << " has no row in this test's table and no reason to have none: add "
                 "a configuration where it acts");
    CHECK((covered.count(spec.name) + exempt_from_numbers().count(spec.name)) == 1);
  }

  // each row: the table says the flag acts there, and the key and some number change with it
  for (const auto& row : table) {
    const ParamSpec* spec = spec_of(row.flag);
    if (spec == nullptr)
      continue;
    INFO("--" << row.flag << " " << row.value << " on: " << row.base);
    const auto given = command_words(row.base);
    CHECK(std::find(given.begin(), given.end(), "--" + row.flag) == given.end());
    const ResolvedParams base = resolved_evolve(row.base), with = resolved_evolve(row.with());
    CHECK(acts(spec->acts, with));
    CHECK(run_key(with) != run_key(base));
    CHECK(run_of(row.with()).numbers != run_of(row.base).numbers);
  }

  // the exempt flags: what each does change
  {
    INFO("--dt-series: more rows, the same numbers at the times both write");
    const std::string base = "--id 1log-trumpet --grid uniform --N 32 --rmax 16 --tmax 0.5 "
                             "--dt-profiles 0.5"; // every 0.25 (the default)
    const std::string with = base + " --dt-series 0.125";
    CHECK(run_key(resolved_evolve(with)) != run_key(resolved_evolve(base)));
    const Written &a = run_of(base), &b = run_of(with);
    // the rows of timeseries.dat and horizon.dat, at t = 0, 0.125, ..., 0.5 against 0, 0.25, 0.5
    for (const std::string file : {"timeseries.dat", "horizon.dat"}) {
      INFO(file);
      const std::vector<std::string> c = lines(a.numbers.at(file)), f = lines(b.numbers.at(file));
      CHECK(c.size() == 3);
      CHECK(f.size() == 2 * c.size() - 1);
      for (std::size_t k = 0; k < c.size() && 2 * k < f.size(); ++k)
        CHECK(f[2 * k] == c[k]);
    }
    CHECK(b.numbers.at("profiles.dat") == a.numbers.at("profiles.dat"));
    CHECK(b.numbers.size() == a.numbers.size());
  }
  {
    INFO("--dt-profiles: more blocks of profiles.dat, nothing else");
    const std::string base = "--id 1log-trumpet --grid uniform --N 32 --rmax 16 --tmax 0.5 "
                             "--dt-series 0.25"; // every 5 (the default): t = 0 and the end
    const std::string with = base + " --dt-profiles 0.125";
    CHECK(run_key(resolved_evolve(with)) != run_key(resolved_evolve(base)));
    const Written &a = run_of(base), &b = run_of(with);
    CHECK(a.profile_blocks == 2);
    CHECK(b.profile_blocks == 5);
    CHECK(b.numbers.at("profiles.dat").size() > a.numbers.at("profiles.dat").size());
    for (const auto& [file, numbers] : a.numbers)
      if (file != "profiles.dat")
        CHECK(b.numbers.at(file) == numbers);
  }
  {
    INFO("--checkpoint-every: a checkpoint, the same numbers");
    const std::string with = trumpet + " --checkpoint-every 0.25";
    CHECK(run_key(resolved_evolve(with))
          != run_key(resolved_evolve(trumpet))); // recorded: resume keeps it
    CHECK(run_of(with).checkpoint);
    CHECK_FALSE(run_of(trumpet).checkpoint);
    CHECK(run_of(with).numbers == run_of(trumpet).numbers);
  }
  {
    INFO("--out and --force: the same run, the same numbers");
    Params elsewhere = resolved_evolve(trumpet).flags();
    elsewhere.out = "elsewhere";
    elsewhere.force = true;
    CHECK(run_key(resolve(elsewhere)) == run_key(resolved_evolve(trumpet)));
    const fs::path full = scratch("every_flag_force", true);
    std::ofstream(full / "notes.txt") << "kept\n";
    const auto r = run("evolve " + trumpet + " --force --out " + full.string());
    INFO(r.err);
    REQUIRE(r.status == 0);
    CHECK(written(full).numbers == run_of(trumpet).numbers); // (run_of: another --out)
    fs::remove_all(full);
  }

  // (--box-taper where no fine box reaches beyond --box-taper-from, and --delta-advection or
  // --driver-advection's upwind stencils without the horizon shift, once rows here whose numbers
  // did not change, are idle in the table now: tests/config/test_same_run.cpp holds them both
  // ways)
  fs::remove(hAH);
}

} // namespace every_flag_test
