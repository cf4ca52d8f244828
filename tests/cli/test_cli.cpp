// The command line as a user meets it: the real executable, bad input refused with one line
// naming the parameter and nothing written, and config files that repeat a run exactly.
#include "cli_support.hpp"
#include "config/config_file.hpp"
#include "config/folder_lock.hpp"
#include "config/param_rules.hpp"
#include "config/params.hpp"

#include <fmt/format.h>

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace gbssn1d::testing;

namespace {
using gbssn1d::ParamError;
using gbssn1d::read_config_text;
using gbssn1d::toml_string;
} // namespace

TEST_CASE("bad numbers are refused, naming the parameter and why") {
  check_refused("--N 0", "--N");
  check_refused("--box-taper 0.25", "--box-taper");              // a single grid has no boxes
  check_refused("--box-taper-from 8", "--box-taper-from");       // nor this
  check_refused("--grid boxes --box-taper 0.51", "--box-taper"); // 0 ... 0.5
  check_refused("--grid boxes --box-taper -0.1", "--box-taper");
  check_refused("--grid boxes --box-taper-from -1", "--box-taper-from");
  check_refused("--N -5", "--N");
  check_refused("--rmax -3", "--rmax");
  check_refused("--rmax 0", "--rmax");
  check_refused("--grid sinh --N 1000 --dr-inner 0.02 --rmax 7.9", "--rmax"); // needs > 400 x 0.02
  check_refused("--grid uniform --rmax 2", "--rmax");
  check_refused("--cfl 2", "--cfl");
  check_refused("--cfl 0", "--cfl");
  check_refused("--cfl -0.1", "--cfl");
  check_refused("--rmax nan", "--rmax");
  check_refused("--M inf", "--M");
  check_refused("--eta nan", "--eta");
  check_refused("--ko-sigma -1", "--ko-sigma");
  check_refused("--chi-floor -1e-5", "--chi-floor");
  check_refused("--chi-floor 1", "--chi-floor");
  check_refused("--tmax -1", "--tmax");
  check_refused("--N abc", "--N");
  check_refused("--eta -3", "--eta");
  check_refused("--N 1000000000", "--N");
  check_refused("--tmax 10 --dt-series 1e-10", "--dt-series");
  check_refused("--tmax 1e308", "--tmax");
}

TEST_CASE("unknown choices and flags are refused") {
  check_refused("--id kerr", "--id");
  check_refused("--grid log", "--grid");
  check_refused("--lapse0 zero", "--lapse0");
  check_refused("--rah-variant bogus", "--rah-variant");
  check_refused("--ah-every 0", "--ah-every");
  check_refused("--ah-every often", "--ah-every");
  check_refused("--rah0 -1", "--rah0");
  check_refused("--no-such-flag 3", "--no-such-flag");
}

TEST_CASE("the horizon-shift study options refuse bad values by name") {
  check_refused("--rah-profile bogus", "--rah-profile");
  check_refused("--rah-normal tangent", "--rah-normal");
  check_refused("--rah-chi-smooth 0", "--rah-chi-smooth");
  check_refused("--rah-ramp -1", "--rah-ramp");
  check_refused("--driver-advection sideways", "--driver-advection");
  check_refused("--delta-advection sideways", "--delta-advection");
  check_refused("--norm-Rmin 5 --norm-Rmax 4", "--norm-Rmax");
  check_refused("--norm-Rint 0", "--norm-Rint");
  check_refused("--rahA 0.5 --rah-hAH-file /no/such/horizon.dat", "--rah-hAH-file");
}

TEST_CASE("malformed or missing config files are refused") {
  const fs::path cfg = scratch("bad.toml");
  std::ofstream(cfg) << "N = 100\nbogus-key = 3\n";
  check_refused("--config " + cfg.string(), "bogus-key");
  std::ofstream(cfg) << "N = \"many\"\n";
  check_refused("--config " + cfg.string(), "N");
  check_refused("--config " + scratch("missing.toml").string(), "missing.toml");
  fs::remove(cfg);
}

TEST_CASE("a value refused from a config file names the file and its key, not only the flag") {
  const fs::path cfg = scratch("refused value.toml");
  for (const std::string line : {"N = -5", "N = \"many\"", "rahA = nan", "grid = \"cubic\""}) {
    std::ofstream(cfg) << line << "\n";
    const std::string key = line.substr(0, line.find(' '));
    const Result r =
        run("evolve --tmax 0 --config '" + cfg.string() + "' --out " + scratch("out").string());
    INFO(line << "\nstderr: " << r.err);
    CHECK(r.status == 2);
    CHECK(count_lines(r.err) == 1);
    CHECK(r.err.find("--" + key) != std::string::npos);
    CHECK(r.err.find("(given as '" + key + "' in --config " + cfg.string() + ")")
          != std::string::npos);
  }
  // the same flag given on the command line overrides the file: its error is the command line's
  std::ofstream(cfg) << "N = 40\n";
  const Result r = run("evolve --tmax 0 --config '" + cfg.string() + "' --N -3 --out "
                       + scratch("out").string());
  INFO("stderr: " << r.err);
  CHECK(r.status == 2);
  CHECK(r.err.find("--N = -3") != std::string::npos);
  CHECK(r.err.find("given as") == std::string::npos);
  fs::remove(cfg);
}

TEST_CASE("--out: an existing non-empty directory is refused and left untouched") {
  const fs::path out = scratch("busy");
  fs::create_directories(out);
  std::ofstream(out / "keep.txt") << "precious\n";
  const Result r = run("evolve --tmax 0 --out " + out.string());
  CHECK(r.status != 0);
  CHECK(count_lines(r.err) == 1);
  CHECK(r.err.find("--out") != std::string::npos);
  CHECK(slurp(out / "keep.txt") == "precious\n");
  CHECK(std::distance(fs::directory_iterator(out), fs::directory_iterator{}) == 1);
  // --force writes into it
  CHECK(run("evolve --tmax 0 --force --out " + out.string()).status == 0);
  CHECK(fs::exists(out / "profiles.dat"));
  fs::remove_all(out);
}

TEST_CASE("--out -: refused (not standard output), and no folder named '-' made") {
  const fs::path dir = scratch("dash_out");
  fs::create_directories(dir);
  const fs::path err = scratch("dash_out_err");
  for (const std::string command :
       {"evolve --tmax 0", "sweep --sweep N=32,40 --tmax 0", "converge --N 32,48,64 --tmax 0"}) {
    INFO(command);
    // in a folder of its own, where '-' would be made
    const std::string line = "cd " + dir.string() + " && " + GBSSN1D_EXECUTABLE + " " + command
                             + " --out - >/dev/null 2>" + err.string();
    const int raw = std::system(line.c_str());
    CHECK((WIFEXITED(raw) ? WEXITSTATUS(raw) : -1) == 2);
    const std::string text = slurp(err);
    CHECK(text.find("error: --out = - is invalid: not standard input or output here")
          != std::string::npos);
    CHECK(count_lines(text) == 1);
    CHECK(fs::is_empty(dir));
  }
  fs::remove(err);
  fs::remove_all(dir);
}

TEST_CASE("--out: a directory that cannot be created is refused") {
  const fs::path file = scratch("plainfile");
  std::ofstream(file) << "x\n";
  const Result r = run("evolve --tmax 0 --out " + (file / "sub").string());
  CHECK(r.status != 0);
  CHECK(count_lines(r.err) == 1);
  CHECK(r.err.find("--out") != std::string::npos);
  CHECK(slurp(file) == "x\n");
  fs::remove(file);
}

TEST_CASE("--tmax 0 writes the initial data, the written config repeats a run exactly") {
  const fs::path a = scratch("run_a"), b = scratch("run_b");
  const std::string flags =
      "--id maximal-trumpet --grid sinh --N 120 --rmax 40 --dr-inner 0.05 --cfl 0.3 "
      "--tmax 2 --dt-series 0.5 --dt-profiles 1 --ko-sigma 0.2 --eta 1.5 --advective-shift";
  REQUIRE(run("evolve " + flags + " --out " + a.string()).status == 0);
  for (const char* f : {"config.toml", "timeseries.dat", "profiles.dat"})
    CHECK(fs::exists(a / f));
  const auto series = gbssn1d::testing::read_table((a / "timeseries.dat").string());
  CHECK(series.rows.size() == 5); // t = 0, 0.5, 1, 1.5, 2
  CHECK(series.at(4, "t") == 2.0);

  REQUIRE(run("evolve --config " + (a / "config.toml").string() + " --out " + b.string()).status
          == 0);
  // the same column names (the first line) and rows; only the parameter lines may differ
  auto names_and_rows = [](const std::string& text) {
    std::istringstream lines(text);
    std::string out, line;
    std::getline(lines, out);
    while (std::getline(lines, line))
      if (line.empty() || line[0] != '#')
        out += "\n" + line;
    return out;
  };
  CHECK(names_and_rows(slurp(a / "timeseries.dat")) == names_and_rows(slurp(b / "timeseries.dat")));
  CHECK(slurp(a / "profiles.dat").substr(slurp(a / "profiles.dat").find("# t ="))
        == slurp(b / "profiles.dat").substr(slurp(b / "profiles.dat").find("# t =")));

  // --print-config shows the effective configuration, which reads back to itself
  const Result printed = run("evolve --config " + (a / "config.toml").string() + " --print-config");
  CHECK(printed.status == 0);
  CHECK(printed.out.find("eta = 1.5") != std::string::npos);
  CHECK(printed.out.find("advective-shift = true") != std::string::npos);

  const fs::path c = scratch("run_c");
  REQUIRE(run("evolve --tmax 0 --out " + c.string()).status == 0);
  const std::string profiles = slurp(c / "profiles.dat");
  CHECK(profiles.find("# t = 0") != std::string::npos);
  CHECK(profiles.find("\n\n\n") == std::string::npos); // one block only
  for (const auto& d : {a, b, c})
    fs::remove_all(d);
}

namespace {

/// A refused study command (`cmd` is the whole command line after the executable, with --out
/// given as OUT): exit status 2, one line naming `flag`, nothing written.
void check_study_refused(const std::string& cmd, const std::string& flag) {
  const fs::path out = scratch("study_out");
  std::string line = cmd;
  line.replace(line.find("OUT"), 3, out.string());
  const Result r = run(line);
  INFO("command: " << line << "\nstderr: " << r.err);
  CHECK(r.status == 2);
  CHECK(count_lines(r.err) == 1);
  CHECK(r.err.find(flag) != std::string::npos);
  CHECK(r.err.find("what()") == std::string::npos); // no leaked exception texts
  CHECK(r.err.find("stod") == std::string::npos);
  CHECK(r.err.find("filesystem error") == std::string::npos);
  CHECK_FALSE(fs::exists(out));
}

} // namespace

TEST_CASE("input guards: lists, repeats, config values, sweep axes, -j, misleading messages") {
  check_study_refused("converge --N 40.5,80,160 --tmax 1 --out OUT", "--N");
  check_study_refused("converge --N 40 --factors 1,1.5,2.01 --tmax 1 --out OUT", "--factors");
  check_study_refused("converge --N 40,80,160 --order nan --tmax 1 --out OUT", "--order");
  check_study_refused("converge --N 40,80,160 --scaled-times 1,x --tmax 1 --out OUT",
                      "--scaled-times");
  check_study_refused("converge --N 40,80,160 -j 100000 --tmax 1 --out OUT", "-j");
  // a field twice would be two equal columns; an empty item in a list is refused everywhere
  check_study_refused("converge --N 40,80,160 --fields alpha,alpha --tmax 1 --out OUT",
                      "--fields = alpha,alpha is invalid: lists alpha twice");
  check_study_refused("converge --N 40,80,160 --factors 1,1.5,2, --tmax 1 --out OUT", "--factors");
  check_study_refused("sweep --sweep N=32, --tmax 0 --out OUT",
                      "--sweep = N=32, is invalid: must be a comma-separated list without empty "
                      "items");
  check_study_refused("sweep --sweep N=,32 --tmax 0 --out OUT", "--sweep");
  check_study_refused("sweep --sweep N=32,,40 --tmax 0 --out OUT", "--sweep");
  check_study_refused("sweep --sweep N,=32 --tmax 0 --out OUT", "--sweep");
  check_study_refused("sweep -j 100000 --sweep N=100,200 --tmax 0 --out OUT", "-j");
  check_study_refused("sweep --sweep cfl=0.2,0.3 --sweep cfl=0.25 --tmax 0 --out OUT", "cfl");
  check_study_refused("sweep --sweep N=100,200 --cfl 7 --tmax 0 --out OUT", "--cfl");
  check_study_refused("sweep --sweep N=100 --tmax 0 --out /etc/passwd/OUT", "--out");
  check_refused("--N 100 --N 200", "more than once");
  check_refused("--rmax 1e308", "--rmax");
  check_refused("--M 1e-300", "--M");
  check_refused("--rmax ''", "--rmax");
  check_study_refused("evolve --tmax 100 --dt-series 1e-10 --out OUT", "--dt-series");
  const fs::path cfg = scratch("guards.toml");
  std::ofstream(cfg) << "force = 7\n";
  check_refused("--config " + cfg.string(), "force");
  std::ofstream(cfg) << "\x01\x02\xff = 3\n";
  const Result r =
      run("evolve --tmax 0 --config " + cfg.string() + " --out " + scratch("o").string());
  CHECK(r.status == 2);
  CHECK(r.err.find("\\x01\\x02\\xff") != std::string::npos); // quoted, not echoed raw
  CHECK(r.err.find('\x01') == std::string::npos);
  // a config value overridden once on the command line is not a repeat
  std::ofstream(cfg) << "N = 100\n";
  CHECK(run("evolve --tmax 0 --config " + cfg.string() + " --N 120 --print-config").status == 0);
  fs::remove(cfg);
}

TEST_CASE("the Gamma-driver damping limit: eta dt = 2.7 runs, 2.8 is refused as unstable") {
  // uniform N = 20, rmax = 100, cfl = 0.25: dx = 5, dt = cfl dx = 1.25
  auto amplification = [](double z) {
    return 1 - z + z * z / 2 - z * z * z / 6 + z * z * z * z / 24;
  };
  CHECK(std::abs(amplification(2.7)) < 1.0);
  CHECK(std::abs(amplification(2.8)) > 1.0);
  const std::string grid = "--grid uniform --N 20 --rmax 100 --cfl 0.25 --tmax 0 ";
  const fs::path out = scratch("eta_ok");
  CHECK(run("evolve " + grid + "--eta " + std::to_string(2.7 / 1.25) + " --out " + out.string())
            .status
        == 0);
  fs::remove_all(out);
  check_refused(grid.substr(0, grid.find("--tmax")) + "--eta " + std::to_string(2.8 / 1.25),
                "--cfl");
}

// Guards Z4c's damping limit (config/validate.cpp): Theta decays at the rate
// alpha kappa1 (2 + kappa2) ((Z3), Sec. 17; at most kappa1 max(2, 2 + kappa2), alpha <= 1), and
// RK4 is stable for a decay rate times the step below eta_dt_max, the Gamma-driver's limit (the
// test above). A limit twice as loose let --kappa1 200 run on the default grid (limit 139), which
// then left the physical range at t = 0.32. The boundary here is computed from the step the run
// takes, dt = cfl x the smallest cell of the grid the flags give (time_step, as validate() does),
// on the default sinh grid (dt = 0.01) and a coarse uniform one (dt = 1.25), and kappa1 is put
// 0.1% either side of it; with kappa2 = 1 it is kappa2 that makes the rate too fast, and named.
TEST_CASE("Z4c's damping limit: kappa1 (2 + kappa2) dt just inside RK4's limit runs, just "
          "beyond it is refused, naming the flag") {
  auto amplification = [](double z) {
    return 1 - z + z * z / 2 - z * z * z / 6 + z * z * z * z / 24;
  };
  REQUIRE(std::abs(amplification(gbssn1d::eta_dt_max * 1.001)) < 1.0); // inside RK4's region
  struct Case {
    std::string flags;
    gbssn1d::Params p;
  };
  gbssn1d::Params coarse;
  coarse.grid = gbssn1d::RadialGrid::uniform;
  coarse.N = 20;
  coarse.rmax = 100.0;
  coarse.cfl = 0.25;
  for (const auto& [flags, p] : {Case{"", gbssn1d::Params{}},
                                 Case{"--grid uniform --N 20 --rmax 100 --cfl 0.25 ", coarse}}) {
    const double dt = gbssn1d::time_step(p.cfl, gbssn1d::make_grid(gbssn1d::grid_spec(p)));
    for (const double kappa2 : {0.0, 1.0}) {
      const double limit = gbssn1d::eta_dt_max / (std::max(2.0, 2.0 + kappa2) * dt);
      const std::string z4c =
          flags + fmt::format("--formulation z4c --kappa1-hole 0 --kappa2 {} --kappa1 ", kappa2);
      INFO(z4c << "...: dt = " << dt << ", kappa1 at most " << limit);
      const fs::path out = scratch("kappa1_limit");
      const Result inside = run("evolve --tmax 0 " + z4c + fmt::format("{:.17g}", 0.999 * limit)
                                + " --out " + out.string());
      INFO("inside: " << inside.err);
      CHECK(inside.status == 0);
      fs::remove_all(out);
      const Result beyond = run("evolve --tmax 0 " + z4c + fmt::format("{:.17g}", 1.001 * limit)
                                + " --out " + out.string());
      INFO("beyond: " << beyond.err);
      CHECK(beyond.status == 2);
      CHECK(count_lines(beyond.err) == 1);
      CHECK(beyond.err.find(kappa2 > 0.0 ? "--kappa2" : "--kappa1") != std::string::npos);
      CHECK(beyond.err.find("RK4 limit of the constraint damping") != std::string::npos);
      CHECK_FALSE(fs::exists(out));
      fs::remove_all(out);
    }
  }
}

// CLI11 and strtol read "032" as octal 26; the one number reader reads decimal everywhere, so
// the command line, a config file, a sweep value (and its fitted order) and a converge list
// agree on what a text means.

TEST_CASE("numbers are decimal on every path: 032 is 32 in flags, config files, sweeps, lists") {
  auto header_N = [](const fs::path& dir) {
    std::ifstream in(dir / "timeseries.dat");
    for (std::string line; std::getline(in, line);)
      if (line.rfind("# N = ", 0) == 0)
        return std::stoi(line.substr(6));
    return -1;
  };
  const fs::path flag = scratch("octal_flag");
  REQUIRE(run("evolve --N 032 --tmax 0 --out " + flag.string()).status == 0);
  CHECK(header_N(flag) == 32);
  const fs::path cfg = scratch("octal.toml");
  std::ofstream(cfg) << "N = 040\ndr-inner = 0.020\n";
  const fs::path file = scratch("octal_file");
  REQUIRE(run("evolve --config " + cfg.string() + " --tmax 0 --out " + file.string()).status == 0);
  CHECK(header_N(file) == 40);
  const fs::path sweep = scratch("octal_sweep");
  REQUIRE(
      run("sweep --sweep N=040,060,0100 --tmax 0 --progress-every 0 --out " + sweep.string()).status
      == 0);
  CHECK(header_N(sweep / "N=040") == 40);
  CHECK(header_N(sweep / "N=060") == 60);
  CHECK(header_N(sweep / "N=0100") == 100);
  const fs::path conv = scratch("octal_converge");
  const int status = run("converge --N 032,048,064 --tmax 0 --out " + conv.string()).status;
  // completed: tmax 0 is one output time, too short to judge (exit 6)
  REQUIRE(status == 6);
  CHECK(header_N(conv / "N32") == 32);
  CHECK(header_N(conv / "N64") == 64);
  for (const auto& d : {flag, cfg, file, sweep, conv})
    fs::remove_all(d);
}

TEST_CASE("a value's control characters are escaped in error messages: one line each") {
  const fs::path dir = scratch("ctl_values");
  fs::create_directories(dir);
  const fs::path cfg = dir / "c.toml";
  // a config string with a newline and a tab, in a choice (ParamError) and a number (CLI11)
  for (const auto& [line, shown] : std::vector<std::pair<std::string, std::string>>{
           {"id = \"worm\\nhole\"\n", "--id = worm\\x0ahole is invalid"},
           {"grid = \"uni\\tform\"\n", "--grid = uni\\x09form is invalid"},
           {"rah-hAH-file = \"h\\n.dat\"\nrahA = 0.5\n", "h\\x0a.dat"},
           {"N = \"6\\n4\"\n", "\\x0a"}}) {
    INFO(line);
    std::ofstream(cfg) << line;
    const Result r =
        run("evolve --tmax 0 --config " + cfg.string() + " --out " + (dir / "out").string());
    INFO(r.err);
    CHECK(r.status == 2);
    CHECK(count_lines(r.err) == 1);
    CHECK(r.err.find(shown) != std::string::npos);
    CHECK(r.err.find('\t') == std::string::npos);
    CHECK_FALSE(fs::exists(dir / "out"));
  }
  fs::remove_all(dir);
}

TEST_CASE("config files read back every string exactly: '#', quotes, backslashes, newlines") {
  for (const std::string value :
       {"a#b", "q\"b", "back\\slash", "nl\nx", "tab\tx", "sq'x", "ctl\x01x", "trailing "}) {
    INFO(value);
    CHECK(read_config_text("out = " + toml_string(value) + "  # a comment\n", "f").at(0).second
          == value);
    // through a run's config.toml: --print-config of it gives the same text back
    const fs::path dir = scratch("cfg_strings");
    fs::create_directories(dir);
    const fs::path cfg = dir / "config.toml";
    std::ofstream(cfg) << "out = " << toml_string(value) << "\n";
    const Result r = run("evolve --config " + cfg.string() + " --print-config");
    CHECK(r.status == 0);
    CHECK(r.out.find("out = " + toml_string(value) + "\n") != std::string::npos);
    fs::remove_all(dir);
  }
  // what the reader refuses, naming the line
  for (const auto& [text, why] : std::vector<std::pair<std::string, std::string>>{
           {"[evolve]\nN = 1\n", "line 1: '[evolve]': sections are not read"},
           {"N = 1\nN = 2\n", "line 2: key 'N' is given again (first on line 1)"},
           {"out = \"abc\n", "line 1: key 'out': its string has no closing"},
           {"out = \"a\\qb\"\n", "unknown escape"},
           {"out = \"run\\u00E9\"\n", "\\u escapes above 007F are not read"},
           {"out = \"run\\u0080\"\n", "\\u escapes above 007F are not read"},
           {"N = 1 2\n", "'2' after its value"},
           {"N = [1, 2]\n", "needs exactly one value"}}) {
    INFO(text);
    try {
      (void)read_config_text(text, "f");
      FAIL("not refused");
    } catch (const ParamError& e) {
      CHECK(std::string(e.what()).find(why) != std::string::npos);
    }
  }
  // the highest escape read: 007F, one byte
  CHECK(read_config_text("out = \"a\\u007Fb\\u0041\"\n", "f").at(0).second
        == "a\x7f"
           "bA");
}

TEST_CASE("help pages say what a newcomer needs: evolve's few common flags first, each study's "
          "output files and columns, a sweep says where its summary is") {
  const Result evolve = run("evolve --help");
  CHECK(evolve.status == 0);
  const auto common = evolve.out.find("Most runs need only");
  REQUIRE(common != std::string::npos);
  CHECK(common < evolve.out.find("Options:")); // before the full list
  const Result converge = run("converge --help");
  for (const char* text : {"convergence.dat (columns", "scaled_H.dat", "N<n>/", "p3_<field>"})
    CHECK(converge.out.find(text) != std::string::npos);
  const Result sweep_help = run("sweep --help");
  for (const char* text : {"summary.dat: a row per member, columns", "H_L2_R_max", "logs/"})
    CHECK(sweep_help.out.find(text) != std::string::npos);
  const fs::path dir = scratch("sweep_summary_path");
  fs::remove_all(dir);
  const Result sweep = run("sweep --progress-every 0 --sweep rahA=0.25,0.5 --id 1log-trumpet "
                           "--grid uniform --N 64 --rmax 20 --tmax 1 --out "
                           + dir.string());
  CHECK(sweep.status == 0);
  CHECK(sweep.err.find("summary: " + (dir / "summary.dat").string()) != std::string::npos);
  fs::remove_all(dir);
}

// A norm window that holds no point: the run warns, naming the flags, and writes NaN in the
// window's columns (no value), never 0 (a vanishing constraint); converge refuses an empty areal
// window before anything runs (its verdict judges H_L2_R and M_L2_R).
TEST_CASE("empty norm windows: evolve warns and writes NaN, converge refuses") {
  const std::filesystem::path out = scratch("empty_windows");
  const Result r = run("evolve --id 1log-trumpet --N 100 --tmax 1 --norm-rmin 5 --norm-rmax "
                       "5.0001 --norm-Rmin 5000 --norm-Rmax 6000 --out "
                       + out.string());
  INFO("stderr: " << r.err);
  REQUIRE(r.status == 0);
  CHECK(r.err.find("warning: --norm-rmin/--norm-rmax") != std::string::npos);
  CHECK(r.err.find("warning: --norm-Rmin/--norm-Rmax") != std::string::npos);
  const auto series = gbssn1d::testing::read_table((out / "timeseries.dat").string());
  REQUIRE(series.rows.size() == 5); // t = 0, 0.25, ... 1
  for (std::size_t row = 0; row < series.rows.size(); ++row) {
    for (const char* empty :
         {"H_L2_ext", "M_L2_ext", "G_L2_ext", "dtalpha_max_ext", "H_L2_R", "M_L2_R"}) {
      CAPTURE(empty);
      CHECK(std::isnan(series.at(row, empty)));
    }
    CHECK(series.at(row, "H_L2") > 0.0); // the other norms have their values
  }
  const std::filesystem::path study = scratch("empty_areal_converge");
  const Result c = run("converge --N 50,60,70 --grid uniform --rmax 40 --tmax 0 --norm-Rmin 500 "
                       "--norm-Rmax 600 --out "
                       + study.string());
  CHECK(c.status == 2);
  CHECK(c.err.find("--norm-Rmin") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(study));
}

// A horizon-adjusting shift faster than the grid's Courant limit at the start is warned about,
// naming --rahA, not refused: such runs can go through (--rahA 200 here reaches 1000 M).
TEST_CASE("--rahA far above the Courant limit at the start is warned about, naming --rahA") {
  const std::filesystem::path out = scratch("courant_warning");
  const Result fast =
      run("evolve --id 1log-trumpet --N 200 --rahA 500 --rah0 1.2 --tmax 0 --out " + out.string());
  INFO(fast.err);
  CHECK(fast.status == 0);
  CHECK(fast.err.find("warning: --rahA 500") != std::string::npos);
  CHECK(fast.err.find("Courant number") != std::string::npos);
  std::filesystem::remove_all(out);
  const Result usual =
      run("evolve --id 1log-trumpet --N 200 --rahA 0.5 --rah0 1.2 --tmax 0 --out " + out.string());
  CHECK(usual.status == 0);
  CHECK(usual.err.find("warning") == std::string::npos);
  std::filesystem::remove_all(out);
}

// Horizon-shift settings that silently do less than they say are warned about, naming the flag.
TEST_CASE("--rah-rcut beyond --rmax, --ah-tmin after --tmax and --rah0 within two cells are "
          "warned about") {
  const std::filesystem::path out = scratch("shift_warnings");
  const Result r = run("evolve --id 1log-trumpet --N 100 --rahA 0.5 --rah-rcut 5000 --ah-tmin 5 "
                       "--tmax 2 --out "
                       + out.string());
  INFO(r.err);
  CHECK(r.status == 0);
  CHECK(r.err.find("warning: --rah-rcut 5000 lies beyond --rmax 1000") != std::string::npos);
  CHECK(r.err.find("warning: --ah-tmin 5 is at or after --tmax 2") != std::string::npos);
  std::filesystem::remove_all(out);
  // a target within two cells of the origin (such runs lose the horizon or go non-finite: sinh
  // N = 200, rah0 0.01, 0.05 and 0.1 did at t = 11-16)
  const Result small =
      run("evolve --id 1log-trumpet --N 200 --rahA 0.5 --rah0 0.01 --tmax 0 --out " + out.string());
  CHECK(small.status == 0);
  CHECK(small.err.find("warning: --rah0 0.01 lies within two cells of the origin")
        != std::string::npos);
  std::filesystem::remove_all(out);
  const Result quiet =
      run("evolve --id 1log-trumpet --N 100 --rahA 0.5 --ah-tmin 1 --tmax 2 --out " + out.string());
  CHECK(quiet.status == 0);
  CHECK(quiet.err.find("warning") == std::string::npos);
  std::filesystem::remove_all(out);
}

// An argument CLI11 cannot place is named as typed (CLI11's own message listed them reversed:
// "0.5 --rah"), with the command's nearest flags, or as a flag before the subcommand.
TEST_CASE(
    "unknown flags are named as typed, with the nearest flags, and flags before the subcommand "
    "are told to follow it") {
  const std::filesystem::path out = scratch("unknown_flags");
  const Result typo = run("evolve --tmax 0 --rah 0.5 --out " + out.string());
  CHECK(typo.status == 2);
  CHECK(count_lines(typo.err) == 1);
  CHECK(typo.err.find("--rah is not a flag of gbssn1d evolve; did you mean --rahA or --rah0")
        != std::string::npos);
  CHECK(typo.err.find("0.5 --rah") == std::string::npos);
  // two edits away (kapa: a p and a digit short) is still near; a name far from every flag is not
  const Result two = run("evolve --tmax 0 --kapa 0.1 --out " + out.string());
  CHECK(two.status == 2);
  CHECK(two.err.find("did you mean --kappa1 or --kappa2?") != std::string::npos);
  const Result three = run("evolve --tmax 0 --zzzzzz 0.1 --out " + out.string());
  CHECK(three.status == 2);
  CHECK(three.err.find("did you mean") == std::string::npos);
  const Result before = run("--out " + out.string() + " evolve --tmax 0");
  CHECK(before.status == 2);
  CHECK(before.err.find("--out before the subcommand: flags follow it") != std::string::npos);
  const Result stray = run("evolve --tmax 0 stray --out " + out.string());
  CHECK(stray.status == 2);
  CHECK(stray.err.find("does not take 'stray'") != std::string::npos);
  const Result resume_flag = run("resume " + out.string() + " --rahA 0.5");
  CHECK(resume_flag.status == 2);
  CHECK(resume_flag.err.find("--rahA is not a flag of gbssn1d resume") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(out));
}

// evolve into the folder of a run that has a checkpoint (interrupted, or with
// --checkpoint-every) names resume as well as --force, and leaves the folder as it was.
TEST_CASE("--out holding a run with a checkpoint: the refusal names resume and --force") {
  const std::filesystem::path out = scratch("out_with_checkpoint");
  REQUIRE(run("evolve --N 60 --tmax 1 --checkpoint-every 0.5 --out " + out.string()).status == 0);
  REQUIRE(std::filesystem::exists(out / "checkpoint.bin"));
  const auto before = gbssn1d::testing::contents(out);
  const Result r = run("evolve --N 60 --tmax 1 --out " + out.string());
  CHECK(r.status == 2);
  CHECK(r.err.find("holds a run with a checkpoint: `gbssn1d resume") != std::string::npos);
  CHECK(r.err.find("--force overwrites it") != std::string::npos);
  CHECK(gbssn1d::testing::contents(out) == before);
  std::filesystem::remove_all(out);
}

// converge says the warnings evolve says for its members (once each, with the members' N when
// they concern only some), before anything runs.
TEST_CASE("converge passes on its members' parameter warnings") {
  const std::filesystem::path out = scratch("converge_warnings");
  const Result r = run("converge --N 40,60,80 --grid uniform --rmax 16 --rahA 0.5 --rah0 0.5 "
                       "--rah-rcut 40 --tmax 0 --out "
                       + out.string());
  INFO(r.err);
  CHECK(r.status != 2);
  // the same for every member: once, without N
  CHECK(r.err.find("gbssn1d converge: warning: --rah-rcut 40 lies beyond --rmax 16")
        != std::string::npos);
  // spacing 0.4 and 0.267 M at N = 40 and 60; not at N = 80 (0.2 M)
  CHECK(r.err.find("warning (N = 40): --rah0 0.5 lies within two cells") != std::string::npos);
  CHECK(r.err.find("warning (N = 60): --rah0 0.5 lies within two cells") != std::string::npos);
  CHECK(r.err.find("(N = 80)") == std::string::npos);
  std::filesystem::remove_all(out);
}

// A --scaled-times value between output rows gets the nearest row's block, and says so.
TEST_CASE("converge --scaled-times between rows: the nearest row's block, with a note") {
  const std::filesystem::path out = scratch("converge_scaled_between");
  const Result r = run("converge --N 40,60,80 --grid uniform --rmax 16 --scaled-times 3,4 "
                       "--dt-series 2 --tmax 4 --out "
                       + out.string());
  INFO(r.err);
  CHECK(r.status != 2);
  CHECK(r.err.find("note: --scaled-times 3 is no output time (rows every --dt-series 2): its "
                   "block is the nearest row's, t = 2")
        != std::string::npos);
  CHECK(r.err.find("--scaled-times 4 is no output time") == std::string::npos);
  const std::string scaled = slurp(out / "scaled_H.dat");
  CHECK(scaled.find("# t = 2\n") != std::string::npos);
  CHECK(scaled.find("# t = 4\n") != std::string::npos);
  std::filesystem::remove_all(out);
}
