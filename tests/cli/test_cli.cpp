// The command line as a user meets it: the real executable, bad input refused with one line
// naming the parameter and nothing written, and config files that repeat a run exactly.
#include "../test_support.hpp"
#include "config/config_file.hpp"
#include "config/folder_lock.hpp"
#include "config/params.hpp"

#include <fmt/format.h>

#include <doctest/doctest.h>

#include <algorithm>
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

namespace {

using gbssn1d::ParamError;
using gbssn1d::read_config_text;
using gbssn1d::toml_string;
using gbssn1d::testing::scratch;

struct Result {
  int status;
  std::string err, out;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

Result run(const std::string& args) {
  const fs::path err = scratch("stderr"), out = scratch("stdout");
  const std::string cmd =
      std::string(GBSSN1D_EXECUTABLE) + " " + args + " >" + out.string() + " 2>" + err.string();
  const int raw = std::system(cmd.c_str());
  Result r{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(err), slurp(out)};
  fs::remove(err);
  fs::remove(out);
  return r;
}

int count_lines(const std::string& s) {
  int n = 0;
  for (char c : s)
    n += c == '\n';
  return n;
}

/// A refused run: non-zero exit, one line on stderr that names `flag`, no output directory.
void check_refused(const std::string& args, const std::string& flag) {
  const fs::path out = scratch("out");
  const std::string tmax = args.find("--tmax") == std::string::npos ? "--tmax 0 " : "";
  const Result r = run("evolve " + tmax + "--out " + out.string() + " " + args);
  INFO("args: " << args << "\nstderr: " << r.err);
  if (flag != "more than once")
    CHECK(r.err.find("more than once") == std::string::npos); // refused for its own reason
  CHECK(r.status != 0);
  CHECK(count_lines(r.err) == 1);
  CHECK(r.err.find(flag) != std::string::npos);
  CHECK(r.err.find("error") != std::string::npos);
  CHECK_FALSE(fs::exists(out));
}

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

TEST_CASE("timeseries.dat ends with how the run ended: completed or stopped") {
  const fs::path out = scratch("end");
  REQUIRE(run("evolve --id 1log-trumpet --N 100 --rmax 20 --tmax 1 --out " + out.string()).status
          == 0);
  std::string text = slurp(out / "timeseries.dat");
  CHECK(text.substr(text.rfind("# end:")) == "# end: completed at t = 1\n");
  fs::remove_all(out);
  // --cfl 1 is unstable: the lapse leaves its range; stopped, with variable, place and time
  const Result r =
      run("evolve --grid uniform --N 100 --rmax 20 --cfl 1 --tmax 50 --out " + out.string());
  CHECK(r.status == 3);
  text = slurp(out / "timeseries.dat");
  const std::string last = text.substr(text.rfind("# end:"));
  INFO(last);
  CHECK(last.find("# end: stopped: the evolution left the physical range at t = ") == 0);
  CHECK(last.find("alpha = ") != std::string::npos);
  CHECK(last.find(", r = ") != std::string::npos);
  CHECK(
      std::count(text.begin() + static_cast<std::ptrdiff_t>(text.rfind("# end:")), text.end(), '\n')
      == 1);
  fs::remove_all(out);
}

TEST_CASE("SIGTERM: the run finishes its step, keeps complete files, says so, exits 143") {
  const fs::path out = scratch("sigterm");
  const std::string cmd = "sh -c '" + std::string(GBSSN1D_EXECUTABLE)
                          + " evolve --id 1log-trumpet --grid uniform --N 3200 --rmax 200"
                            " --tmax 2000 --dt-profiles 1 --out "
                          + out.string() + " 2>/dev/null & p=$!; while [ ! -s " + out.string()
                          + "/horizon.dat ]; do sleep 0.1; done; sleep 0.5; kill -TERM $p; "
                            "wait $p; exit $?'";
  const int raw = std::system(cmd.c_str());
  REQUIRE(WIFEXITED(raw));
  CHECK(WEXITSTATUS(raw) == 143);
  const std::string text = slurp(out / "timeseries.dat");
  CHECK(text.substr(text.rfind("# end:")).find("# end: stopped: interrupted by SIGTERM at t = ")
        == 0);
  CHECK(fs::exists(out / "checkpoint.bin")); // written on the signal: `resume` continues
  // every profile row is whole: 18 columns (the last: the level, 0 on a single grid)
  std::ifstream profiles(out / "profiles.dat");
  int rows = 0;
  for (std::string line; std::getline(profiles, line);) {
    if (line.empty() || line[0] == '#')
      continue;
    std::istringstream words(line);
    int n = 0;
    for (std::string w; words >> w;)
      ++n;
    CHECK(n == 18);
    ++rows;
  }
  CHECK(rows >= 3200);
  CHECK(rows % 3200 == 0);
  fs::remove_all(out);
}

TEST_CASE("a write that fails (file-size limit) stops the run with a message naming the file") {
  const fs::path out = scratch("fsize");
  REQUIRE(run("evolve --id 1log-trumpet --tmax 5 --dt-profiles 1 --out " + out.string()).status
          == 0); // the same run without the limit
  fs::remove_all(out);
  const std::string cmd = "sh -c 'ulimit -f 64; " + std::string(GBSSN1D_EXECUTABLE)
                          + " evolve --id 1log-trumpet --tmax 5 --dt-profiles 1 --out "
                          + out.string() + " 2>" + out.string() + ".err'";
  const int raw = std::system(cmd.c_str());
  REQUIRE(WIFEXITED(raw));
  CHECK(WEXITSTATUS(raw) == 1);
  const std::string err = slurp(out.string() + ".err");
  CHECK(err.find("cannot write") != std::string::npos);
  CHECK(err.find("profiles.dat") != std::string::npos);
  fs::remove_all(out);
  fs::remove(out.string() + ".err");
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

namespace {

/// The file without its `out = ...` header line (the directory's own name).
std::string without_out(const fs::path& file) {
  std::istringstream in(slurp(file));
  std::string kept;
  for (std::string line; std::getline(in, line);)
    if (line.rfind("# out = ", 0) != 0 && line.rfind("out = ", 0) != 0)
      kept += line + "\n";
  return kept;
}

} // namespace

TEST_CASE("resume with --rah-hAH-file continues with the copy the run took at its start, "
          "whatever the flag's path names now") {
  const fs::path whole = scratch("hAH_whole"), parts = scratch("hAH_parts");
  const fs::path file = scratch("hAH_file.dat"), other = scratch("hAH_other.dat");
  auto write = [](const fs::path& f, double slope) {
    std::ofstream out(f);
    out << "# t r_ah\n";
    for (int k = 0; k <= 24; ++k)
      out << 0.5 * k << " " << 0.8304 + slope * 0.5 * k << "\n";
  };
  write(file, 0.002);
  write(other, 0.002); // the uninterrupted run's input: the same content, another file
  const std::string flags = "evolve --id 1log-trumpet --grid uniform --N 200 --rmax 50 --rahA 0.5 "
                            "--rah0 0.89 --dt-series 0.5 --dt-profiles 5 --checkpoint-every 2 "
                            "--rah-hAH-file ";
  REQUIRE(run(flags + other.string() + " --tmax 10 --out " + whole.string()).status == 0);
  REQUIRE(run(flags + file.string() + " --tmax 5 --out " + parts.string()).status == 0);
  CHECK(slurp(parts / "rah-hAH-file.dat") == slurp(file)); // the run's own copy
  write(file, 0.02); // the file is edited after the run started
  const Result r = run("resume " + parts.string() + " --tmax 10");
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(r.err.find("note: --rah-hAH-file") != std::string::npos);
  // continued with the content it started with: the same numbers as the uninterrupted run
  for (const char* f : {"timeseries.dat", "horizon.dat"}) {
    auto data = [](const std::string& text) {
      std::string rows;
      std::istringstream in(text);
      for (std::string line; std::getline(in, line);)
        if (!line.empty() && line[0] != '#')
          rows += line + "\n";
      return rows;
    };
    CHECK(data(slurp(whole / f)) == data(slurp(parts / f)));
  }
  fs::remove_all(whole);
  fs::remove_all(parts);
  fs::remove(file);
  fs::remove(other);
}

TEST_CASE("resume: a run continued from its checkpoint is bit-identical to an uninterrupted one") {
  const fs::path whole = scratch("whole"), parts = scratch("parts");
  // substage searches, held searches every 4 steps, and the midstep-update variant (whose
  // searches are timed by the RHS-evaluation counter the checkpoint carries)
  for (const std::string mode :
       {"--ah-every substage", "--ah-every 4", "--ah-every 2 --rah-variant midstep-update"}) {
    fs::remove_all(whole);
    fs::remove_all(parts);
    const std::string flags = "evolve --id 1log-trumpet --grid uniform --N 400 --rmax 50 --rahA "
                              "0.5 --rah0 0.6 --dt-series 0.3 --dt-profiles 2.5 "
                              "--checkpoint-every 3 "
                              + mode;
    REQUIRE(run(flags + " --tmax 20 --out " + whole.string()).status == 0);
    REQUIRE(run(flags + " --tmax 10 --out " + parts.string()).status == 0);
    // a kill mid-write: a cut line after the checkpoint and a stale temporary checkpoint
    std::ofstream(parts / "profiles.dat", std::ios::app) << "1.25 3.5e-0";
    std::ofstream(parts / "checkpoint.bin.tmp") << "garbage";
    // checkpoints are replaced by renaming a complete new file over the old one, never
    // rewritten in place: a hard link to the old one keeps the old bytes
    const std::string old_checkpoint = slurp(parts / "checkpoint.bin");
    fs::create_hard_link(parts / "checkpoint.bin", parts / "old_checkpoint.bin");
    const Result r = run("resume " + parts.string() + " --tmax 20");
    INFO(mode << ": " << r.err);
    REQUIRE(r.status == 0);
    CHECK(r.err.find("resuming") != std::string::npos);
    for (const char* f : {"timeseries.dat", "profiles.dat", "horizon.dat", "config.toml"})
      CHECK(without_out(whole / f) == without_out(parts / f));
    CHECK(slurp(parts / "old_checkpoint.bin") == old_checkpoint);
    CHECK(slurp(parts / "checkpoint.bin") != old_checkpoint);
    fs::remove(parts / "old_checkpoint.bin");
  }
  // a checkpoint of another configuration, a missing one, and --tmax before it are refused
  const Result before = run("resume " + parts.string() + " --tmax 1");
  CHECK(before.status == 2);
  CHECK(before.err.find("--tmax") != std::string::npos);
  fs::remove(parts / "checkpoint.bin");
  const Result missing = run("resume " + parts.string());
  CHECK(missing.status == 2);
  CHECK(missing.err.find("checkpoint") != std::string::npos);
  fs::copy_file(whole / "checkpoint.bin", parts / "checkpoint.bin");
  std::ofstream(parts / "config.toml", std::ios::app) << "N = 200\n";
  CHECK(run("resume " + parts.string()).status == 2);
  fs::remove_all(whole);
  fs::remove_all(parts);
}

// RK4 is stable for d_t B = -eta B only while eta dt stays inside its real stability interval
// (-2.785..., 0]: at eta dt = 2.8 the amplification 1 - z + z^2/2 - z^3/6 + z^4/24 exceeds 1.
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
  // completed (converging, not converging or pre-asymptotic, at M/1.6)
  REQUIRE((status == 0 || status == 4 || status == 5));
  CHECK(header_N(conv / "N32") == 32);
  CHECK(header_N(conv / "N64") == 64);
  for (const auto& d : {flag, cfg, file, sweep, conv})
    fs::remove_all(d);
}

namespace {

/// Every file of a folder with its bytes.
std::map<std::string, std::string> folder(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file())
      files[e.path().filename().string()] = slurp(e.path());
  return files;
}

/// FNV-1a 64 (the checkpoint's checksum), written here from its definition.
std::uint64_t fnv1a64(const std::string& bytes) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (unsigned char c : bytes)
    h = (h ^ c) * 0x100000001b3ull;
  return h;
}

/// The checkpoint `bytes` with `value` written at `offset` and its checksum made valid again:
/// a counter changed consistently, which only the checks against the run can catch.
std::string patched(std::string bytes, std::size_t offset, const void* value, std::size_t n) {
  std::memcpy(bytes.data() + offset, value, n);
  bytes.resize(bytes.size() - 8);
  const std::uint64_t h = fnv1a64(bytes);
  bytes.append(reinterpret_cast<const char*>(&h), 8);
  return bytes;
}

} // namespace

TEST_CASE("a boxes run recorded before --box-taper existed resumes without the taper it never "
          "had, and today's default is another configuration") {
  const fs::path whole = scratch("whole"), parts = scratch("parts");
  fs::remove_all(whole);
  fs::remove_all(parts);
  const std::string flags = "evolve --grid boxes --levels 6 --rmax 64 --N 24 --box-taper 0 "
                            "--dt-series 0.5 --dt-profiles 5 --checkpoint-every 2";
  REQUIRE(run(flags + " --tmax 6 --out " + whole.string()).status == 0);
  REQUIRE(run(flags + " --tmax 4 --out " + parts.string()).status == 0);
  // the folder's config.toml as a version without the key wrote it (a key absent from a
  // recorded configuration means what runs did before it existed: box-taper = 0)
  std::string config = slurp(parts / "config.toml");
  const auto at = config.find("box-taper = 0\n");
  REQUIRE(at != std::string::npos);
  config.erase(at, std::string("box-taper = 0\n").size());
  std::ofstream(parts / "config.toml", std::ios::trunc) << config;
  const Result r = run("resume " + parts.string() + " --tmax 6");
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(without_out(whole / "timeseries.dat") == without_out(parts / "timeseries.dat"));
  CHECK(without_out(whole / "profiles.dat") == without_out(parts / "profiles.dat"));
  // the comparisons of checkpoints, converge studies and sweep members read it the same way
  const std::string old_text = config;
  std::string today = old_text;
  today.insert(at, "box-taper = 0.5\n");
  const auto diff = gbssn1d::config_differences(old_text, today, {});
  REQUIRE(diff.size() == 1);
  CHECK(diff.front() == "box-taper: 0 -> 0.5");
  today.replace(at, std::string("box-taper = 0.5\n").size(), "box-taper = 0\n");
  CHECK(gbssn1d::config_differences(old_text, today, {}).empty());
  CHECK(gbssn1d::absent_key_args(old_text) == std::vector<std::string>{"--box-taper=0"});
  CHECK(gbssn1d::absent_key_args(today).empty());
}

TEST_CASE("resume checks the checkpoint and every file before it changes any: corrupt, patched, "
          "foreign or incomplete input is refused and the run is left byte for byte") {
  const fs::path dir = scratch("resume_checks");
  REQUIRE(run("evolve --id 1log-trumpet --grid uniform --N 64 --rmax 20 --tmax 4 "
              "--checkpoint-every 1 --out "
              + dir.string())
              .status
          == 0);
  const auto finished = folder(dir);
  const std::string good = finished.at("checkpoint.bin");
  // a completed run is complete: nothing to do, nothing touched
  const Result complete = run("resume " + dir.string());
  CHECK(complete.status == 0);
  CHECK(complete.err.find("complete at t = 4") != std::string::npos);
  CHECK(folder(dir) == finished);
  CHECK(run("resume " + dir.string() + " --tmax 3.5").status == 0);
  CHECK(folder(dir) == finished);
  // a killed run (no end line) resumed to a --tmax before its last output would lose the
  // output after it: refused
  {
    std::string series = finished.at("timeseries.dat");
    series = series.substr(0, series.rfind("# end:"));
    std::ofstream(dir / "timeseries.dat", std::ios::trunc) << series;
  }
  const auto killed = folder(dir);
  const Result cut = run("resume " + dir.string() + " --tmax 3.5");
  CHECK(cut.status == 2);
  CHECK(cut.err.find("--tmax") != std::string::npos);
  CHECK(folder(dir) == killed);

  // offsets of the fields after the magic line and the configuration text
  const std::string magic = "gbssn1d checkpoint 3\n";
  REQUIRE(good.rfind(magic, 0) == 0);
  std::uint64_t n_config = 0;
  std::memcpy(&n_config, good.data() + magic.size(), 8);
  const std::size_t step_at = magic.size() + 8 + n_config, t_at = step_at + 8;
  const std::size_t evaluations_at = t_at + 8 + 8 + 8 + 8 + 1 + 8 + 1 + 1;
  const std::size_t count_at = evaluations_at + 8 + 6 * 8;
  std::string flipped = good;
  for (std::size_t k = 0; k < 4; ++k) // 4 bytes inside the state
    flipped[count_at + 8 + 800 + k] ^= 0x5a;
  const double t_patched = 2.5;
  const std::int64_t step_patched = 3;
  const std::uint64_t evaluations_patched = 0, count_patched = std::uint64_t{1} << 60;
  std::string old_format = good;
  old_format[magic.size() - 2] = '1';
  const std::pair<const char*, std::string> bad[] = {
      {"checksum", flipped},
      {"time", patched(good, t_at, &t_patched, 8)},
      {"step", patched(good, step_at, &step_patched, 8)},
      {"RHS count", patched(good, evaluations_at, &evaluations_patched, 8)},
      {"value count", patched(good, count_at, &count_patched, 8)},
      {"another checkpoint format", old_format},
      {"truncated", good.substr(0, magic.size() + 4)},
  };
  for (const auto& [why, bytes] : bad) {
    std::ofstream(dir / "checkpoint.bin", std::ios::binary | std::ios::trunc) << bytes;
    const auto before = folder(dir);
    const Result r = run("resume " + dir.string() + " --tmax 6");
    INFO(why << ": " << r.err);
    CHECK(r.status == 2);
    CHECK(r.err.find("DIR") != std::string::npos);
    CHECK(r.err.find("std::") == std::string::npos);
    CHECK(folder(dir) == before);
  }
  // a missing output file: refused before timeseries.dat is cut back
  std::ofstream(dir / "checkpoint.bin", std::ios::binary | std::ios::trunc) << good;
  fs::rename(dir / "profiles.dat", dir / "profiles.moved");
  const auto before = folder(dir);
  const Result missing = run("resume " + dir.string() + " --tmax 6");
  CHECK(missing.status == 2);
  CHECK(missing.err.find("profiles.dat") != std::string::npos);
  CHECK(folder(dir) == before);
  fs::rename(dir / "profiles.moved", dir / "profiles.dat");
  // and with everything in place the run continues
  CHECK(run("resume " + dir.string() + " --tmax 6").status == 0);
  fs::remove_all(dir);
}

TEST_CASE("sweep: a rerun with other inputs is refused, naming the member and the flags that "
          "changed, before anything runs or changes, the same inputs continue the sweep") {
  const fs::path dir = scratch("sweep_rerun");
  const std::string sweep = "sweep --progress-every 0 --sweep N=32,40 --grid uniform --rmax 20 ";
  REQUIRE(run(sweep + "--tmax 1 --out " + dir.string()).status == 0);
  // an interrupted member: its status gone, a checkpoint left (as a stopped sweep leaves it)
  fs::remove(dir / "logs" / "N=40.status");
  auto snapshot = [&] {
    std::map<std::string, std::string> all;
    for (const auto& e : fs::recursive_directory_iterator(dir))
      if (e.is_regular_file())
        all[fs::relative(e.path(), dir).string()] = slurp(e.path());
    return all;
  };
  const auto before = snapshot();
  const Result changed = run(sweep + "--tmax 2 --out " + dir.string());
  CHECK(changed.status == 2);
  CHECK(changed.err.find("N=32 (tmax: 1 -> 2)") != std::string::npos);
  CHECK(changed.err.find("N=40 (tmax: 1 -> 2)") != std::string::npos);
  CHECK(snapshot() == before);
  // the remedy that keeps the results comes first: the flags the members ran with
  CHECK(changed.err.find("give the flags they ran with (--tmax 1)") != std::string::npos);
  CHECK(changed.err.find("give the flags") < changed.err.find("remove those members"));
  const Result eta = run(sweep + "--tmax 1 --eta 1 --out " + dir.string());
  CHECK(eta.status == 2);
  CHECK(eta.err.find("eta: 2 -> 1") != std::string::npos);
  CHECK(eta.err.find("(--eta 2)") != std::string::npos);
  CHECK(snapshot() == before);
  // the same inputs: the finished member is kept, the interrupted one runs again
  const Result same = run(sweep + "--tmax 1 --out " + dir.string());
  CHECK(same.status == 0);
  CHECK(slurp(dir / "N=32" / "timeseries.dat") == before.at("N=32/timeseries.dat"));
  CHECK(fs::exists(dir / "logs" / "N=40.status"));
  fs::remove_all(dir);
}

TEST_CASE("converge: samples saved with a member's checkpoint are reused only for the same fields "
          "and radii (a rerun with another coarsest member gives a fresh run's numbers)") {
  const fs::path a = scratch("converge_a"), fresh = scratch("converge_fresh");
  const std::string flags = " --grid uniform --rmax 20 --tmax 3 --checkpoint-every 1 ";
  // (grids this coarse need not converge: 4 or 5, completed but not converging or
  // pre-asymptotic, is a completed run)
  const int first = run("converge --N 32,48,64" + flags + "--out " + a.string()).status;
  REQUIRE((first == 0 || first == 4 || first == 5));
  // members N48 and N64 have checkpoints and samples at the radii of N32's grid
  const int rerun = run("converge --N 40,48,64 --force" + flags + "--out " + a.string()).status;
  REQUIRE((rerun == 0 || rerun == 4 || rerun == 5));
  REQUIRE(run("converge --N 40,48,64" + flags + "--out " + fresh.string()).status == rerun);
  CHECK(without_out(a / "convergence.dat") == without_out(fresh / "convergence.dat"));
  fs::remove_all(a);
  fs::remove_all(fresh);
}

TEST_CASE("converge: a member's saved samples with a flipped byte are not reused: the member "
          "starts afresh, says so, and the study's numbers are an uninterrupted study's") {
  const fs::path a = scratch("converge_flip");
  const std::string cmd = "converge --N 32,48,64 --grid uniform --rmax 20 --tmax 3 "
                          "--checkpoint-every 1 --out "
                          + a.string();
  const int first = run(cmd).status;
  REQUIRE((first == 0 || first == 4 || first == 5));
  const std::string before = without_out(a / "convergence.dat");
  const fs::path samples = a / "N48" / "converge_samples.bin";
  std::string bytes = slurp(samples);
  REQUIRE(bytes.size() > 64);
  bytes[bytes.size() / 2] = static_cast<char>(bytes[bytes.size() / 2] ^ 0x5a);
  std::ofstream(samples, std::ios::binary) << bytes;
  const Result rerun = run(cmd + " --force");
  INFO(rerun.err);
  CHECK(rerun.status == first);
  CHECK(rerun.err.find("member N = 48 starts afresh") != std::string::npos);
  CHECK(rerun.err.find("checksum") != std::string::npos);
  CHECK(without_out(a / "convergence.dat") == before);
  fs::remove_all(a);
}

// A closed terminal (SIGHUP) and a batch scheduler's warning ahead of its time limit (SIGUSR1,
// SIGUSR2) stop a run as SIGTERM does: the step finished, a checkpoint, the end line, 128 + n.
TEST_CASE("SIGTERM in a run's first milliseconds: nothing written, or a folder that resumes") {
  // the stop handlers are in place before the first file is created: a folder holding only
  // config.toml.tmp (and no checkpoint) was what a signal in the first ~20 ms left
  for (int delay_us : {0, 1000, 2000, 4000, 8000, 16000, 32000}) {
    const fs::path out = scratch("early_stop");
    const std::string cmd = "sh -c '" + std::string(GBSSN1D_EXECUTABLE)
                            + " evolve --N 400 --tmax 20 --out " + out.string()
                            + " 2>/dev/null & p=$!; usleep_s=$(printf \"%d.%06d\" 0 "
                            + std::to_string(delay_us)
                            + "); sleep $usleep_s; kill -TERM $p; "
                              "wait $p; exit $?'";
    const int raw = std::system(cmd.c_str());
    INFO("delay " << delay_us << " us");
    REQUIRE(WIFEXITED(raw));
    CHECK(WEXITSTATUS(raw) == 143);
    if (fs::exists(out)) {
      CHECK(fs::exists(out / "checkpoint.bin"));
      CHECK_FALSE(fs::exists(out / "config.toml.tmp"));
      CHECK(run("resume " + out.string()).status == 0);
    }
    fs::remove_all(out);
  }
}

TEST_CASE("resume: a run's file that is a loop of symbolic links is refused, naming DIR") {
  const fs::path out = scratch("resume_loop");
  REQUIRE(run("evolve --N 64 --tmax 1 --checkpoint-every 0.5 --out " + out.string()).status == 0);
  for (const char* name : {"checkpoint.bin", "config.toml"}) {
    const fs::path keep = scratch("resume_loop_keep");
    fs::rename(out / name, keep);
    fs::create_symlink(name, out / name); // points at itself
    const Result r = run("resume " + out.string() + " --tmax 2");
    INFO(name << ": " << r.err);
    CHECK(r.status == 2);
    CHECK(r.err.find("DIR = ") != std::string::npos);
    CHECK(r.err.find(std::string("its ") + name + " cannot be read") != std::string::npos);
    fs::remove(out / name);
    fs::rename(keep, out / name);
  }
  fs::remove_all(out);
}

TEST_CASE("out of memory is a message and exit 1, not an abort") {
  // under a 400 MB address-space limit a grid of 9e6 cells (about 4 GB of state) cannot be made
#if defined(__SANITIZE_ADDRESS__)
  MESSAGE("skipped: AddressSanitizer reserves more address space than the limit allows");
  return;
#endif
  const fs::path out = scratch("no_memory");
  const std::string cmd = "sh -c 'ulimit -v 400000; " + std::string(GBSSN1D_EXECUTABLE)
                          + " evolve --N 9000000 --grid uniform --rmax 100 --tmax 0 --out "
                          + out.string() + "' 2>" + out.string() + ".err";
  const int raw = std::system(cmd.c_str());
  REQUIRE(WIFEXITED(raw));
  CHECK(WEXITSTATUS(raw) == 1);
  const std::string err = slurp(out.string() + ".err");
  CHECK(err.find("gbssn1d: error: out of memory") != std::string::npos);
  CHECK(err.find("bad_alloc") == std::string::npos);
  fs::remove(out.string() + ".err");
  fs::remove_all(out);
}

TEST_CASE("SIGHUP, SIGUSR1 and SIGUSR2 stop a run resumably, as SIGTERM does") {
  for (const auto& [name, status] :
       {std::pair{"HUP", 129}, std::pair{"USR1", 138}, std::pair{"USR2", 140}}) {
    const fs::path out = scratch(std::string("signal_") + name);
    const std::string cmd = "sh -c '" + std::string(GBSSN1D_EXECUTABLE)
                            + " evolve --id 1log-trumpet --grid uniform --N 3200 --rmax 200"
                              " --tmax 2000 --out "
                            + out.string() + " 2>/dev/null & p=$!; while [ ! -s " + out.string()
                            + "/horizon.dat ]; do sleep 0.05; done; sleep 0.2; kill -" + name
                            + " $p; wait $p; exit $?'";
    const int raw = std::system(cmd.c_str());
    INFO(name);
    REQUIRE(WIFEXITED(raw));
    CHECK(WEXITSTATUS(raw) == status);
    const std::string text = slurp(out / "timeseries.dat");
    CHECK(text.substr(text.rfind("# end:")).find(std::string("interrupted by SIG") + name)
          != std::string::npos);
    CHECK(fs::exists(out / "checkpoint.bin"));
    fs::remove_all(out);
  }
}

// Closed standard streams (`2>&-`, `>&-`, `<&-`) are reopened on /dev/null at start-up, so
// that no file the run opens takes descriptor 0-2 and console lines never land in data files.
TEST_CASE("closed standard streams: the run completes and its files hold data only") {
  const fs::path out = scratch("closed_streams");
  const std::string cmd = "sh -c '" + std::string(GBSSN1D_EXECUTABLE)
                          + " evolve --id 1log-trumpet --N 200 --tmax 2 --dt-profiles 1 --out "
                          + out.string() + " <&- >&- 2>&-'";
  const int raw = std::system(cmd.c_str());
  REQUIRE(WIFEXITED(raw));
  CHECK(WEXITSTATUS(raw) == 0);
  for (const char* file : {"timeseries.dat", "profiles.dat", "horizon.dat", "config.toml"}) {
    const std::string text = slurp(out / file);
    INFO(file);
    CHECK(!text.empty());
    CHECK(text.find("gbssn1d:") == std::string::npos); // no console line inside
  }
  CHECK(slurp(out / "timeseries.dat").find("# end: completed at t = 2") != std::string::npos);
  fs::remove_all(out);
}

// The reader of stderr going away (a pager quit, `| head`) must neither kill nor fail a run or a
// sweep: SIGPIPE is ignored and console messages are best effort; the files say how it ended.
TEST_CASE("a closed stderr pipe stops neither a run nor a sweep: exit 0, complete files") {
  const fs::path out = scratch("pipe_run"), sweep = scratch("pipe_sweep");
  auto piped = [](const std::string& args) {
    // the reader takes one byte and leaves; the status is gbssn1d's (pipefail)
    const std::string cmd = "bash -c 'set -o pipefail; " + std::string(GBSSN1D_EXECUTABLE) + " "
                            + args + " 2>&1 >/dev/null | head -c 1 >/dev/null'";
    const int raw = std::system(cmd.c_str());
    return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  };
  CHECK(piped("evolve --id wormhole --N 200 --tmax 30 --out " + out.string()) == 0);
  const std::string text = slurp(out / "timeseries.dat");
  CHECK(text.find("# end: completed at t = 30") != std::string::npos);
  CHECK(piped("sweep --progress-every 0 --sweep N=32,40,48 --tmax 20 --out " + sweep.string())
        == 0);
  const auto summary = gbssn1d::testing::read_table((sweep / "summary.dat").string());
  CHECK(summary.rows.size() == 3);
  fs::remove_all(out);
  fs::remove_all(sweep);
}

TEST_CASE("converge interrupted: exit 130, and its files and message say they are partial") {
  const fs::path out = scratch("converge_sigint");
  const std::string cmd = "sh -c '" + std::string(GBSSN1D_EXECUTABLE)
                          + " converge --N 800,1000,1200 -j 3 --grid uniform --rmax 100"
                            " --id 1log-trumpet --tmax 200 --out "
                          + out.string() + " 2>" + out.string() + ".err & p=$!; while [ ! -s "
                          + out.string()
                          + "/N1200/horizon.dat ]; do sleep 0.05; done; sleep 0.3; kill -INT $p;"
                            " wait $p; exit $?'";
  const int raw = std::system(cmd.c_str());
  REQUIRE(WIFEXITED(raw));
  CHECK(WEXITSTATUS(raw) == 130);
  const std::string err = slurp(out.string() + ".err");
  CHECK(err.find("interrupted by SIGINT") != std::string::npos);
  CHECK(err.find("done;") == std::string::npos);
  for (const char* file : {"convergence.dat", "scaled_H.dat"}) {
    const std::string text = slurp(out / file);
    INFO(file);
    CHECK(text.find("# status: interrupted by SIGINT") != std::string::npos);
    CHECK(text.substr(text.rfind("# end:")).find("# end: interrupted by SIGINT") == 0);
  }
  // "rerun the same command to resume", as its files say: the same command continues the
  // study, its members from their checkpoints, to the end
  CHECK(err.find("rerun the same command") != std::string::npos);
  const Result again = run("converge --N 800,1000,1200 -j 3 --grid uniform --rmax 100"
                           " --id 1log-trumpet --tmax 200 --out "
                           + out.string());
  INFO(again.err);
  CHECK((again.status == 0 || again.status == 4 || again.status == 5));
  CHECK(again.err.find("members continue from their checkpoints") != std::string::npos);
  CHECK(again.err.find("resumes at t =") != std::string::npos);
  const std::string text = slurp(out / "convergence.dat");
  CHECK(text.substr(text.rfind("# end:")).find("# end: completed at t = 200") == 0);
  fs::remove_all(out);
  fs::remove(out.string() + ".err");
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
}

TEST_CASE("the output folder removed during a run: the run stops with exit 1 and says why") {
  const fs::path out = scratch("removed_during");
  const std::string cmd = "sh -c '" + std::string(GBSSN1D_EXECUTABLE)
                          + " evolve --id 1log-trumpet --grid uniform --N 1600 --rmax 200"
                            " --tmax 2000 --out "
                          + out.string() + " 2>" + out.string()
                          + ".err & p=$!; for i in $(seq "
                            "1200); do [ -s "
                          + out.string()
                          + "/horizon.dat ] && break; sleep 0.05; "
                            "done; rm -rf "
                          + out.string() + "; wait $p; exit $?'";
  const int raw = std::system(cmd.c_str());
  REQUIRE(WIFEXITED(raw));
  CHECK(WEXITSTATUS(raw) == 1);
  const std::string err = slurp(out.string() + ".err");
  CHECK(err.find("was removed or replaced during the run") != std::string::npos);
  CHECK(err.find("reached t =") == std::string::npos);
  fs::remove(out.string() + ".err");
  fs::remove_all(out);
}

TEST_CASE("the resume hint is a command that works as pasted: the program as invoked, quoted") {
  const fs::path out = scratch("hint dir");
  const std::string cmd = "sh -c '" + std::string(GBSSN1D_EXECUTABLE)
                          + " evolve --id 1log-trumpet --grid uniform --N 3200 --rmax 200"
                            " --tmax 2000 --out \""
                          + out.string() + "\" 2>\"" + out.string()
                          + ".err\" & p=$!; for i in $(seq 1200); do [ -s \"" + out.string()
                          + "/horizon.dat\" ] && break; sleep 0.05; done; kill -TERM $p; "
                            "wait $p; exit $?'";
  const int raw = std::system(cmd.c_str());
  REQUIRE(WIFEXITED(raw));
  CHECK(WEXITSTATUS(raw) == 143);
  const std::string err = slurp(out.string() + ".err");
  const std::string hint = std::string(GBSSN1D_EXECUTABLE) + " resume '" + out.string() + "'";
  CHECK(err.find("resume with: " + hint) != std::string::npos);
  // pasted into a shell, it finds the program and the run: asked for an end before the
  // checkpoint (so that it is quick), it names the checkpoint
  const fs::path hint_err = scratch("hint.err");
  const int resumed =
      std::system((hint + " --tmax 0.001 >/dev/null 2>" + hint_err.string()).c_str());
  CHECK(WIFEXITED(resumed));
  CHECK(WEXITSTATUS(resumed) == 2);
  CHECK(slurp(hint_err).find("is before the checkpoint at t =") != std::string::npos);
  fs::remove(hint_err);
  fs::remove(out.string() + ".err");
  fs::remove_all(out);
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

TEST_CASE("a resumed run's progress line counts its speed from the resume, not from t = 0") {
  // The progress line shows only on a terminal: `script` gives the run one. Before the fix the
  // speed was t / wall time since the resume, 3-20 times too high and its time left too short.
  if (std::system("command -v script >/dev/null 2>&1") != 0) {
    MESSAGE("script (util-linux) is not installed: skipped");
    return;
  }
  const fs::path dir = scratch("progress_resume");
  fs::remove_all(dir);
  REQUIRE(run("evolve --id 1log-trumpet --N 400 --tmax 300 --checkpoint-every 150 --out "
              + dir.string())
              .status
          == 0);
  const fs::path log = scratch("progress_resume.log");
  const std::string cmd = "script -qec '" + std::string(GBSSN1D_EXECUTABLE) + " resume "
                          + dir.string() + " --tmax 600' /dev/null >" + log.string() + " 2>&1";
  REQUIRE(std::system(cmd.c_str()) == 0);
  const std::string out = slurp(log);
  fs::remove(log);
  fs::remove_all(dir);
  // "  t = 211.20 / 600 M   121.8 M/s   3 s left" ... "reached t = 600 in 3.68 s"
  const auto first = out.find(" M/s");
  const auto reached = out.find("reached t = 600 in ");
  INFO(out);
  REQUIRE(first != std::string::npos);
  REQUIRE(reached != std::string::npos);
  const double speed = std::stod(out.substr(out.rfind("M ", first) + 2, first));
  const double wall = std::stod(out.substr(reached + 19));
  const double true_speed = (600.0 - 150.0) / wall; // the checkpoint is at t = 150
  CHECK(speed < 1.6 * true_speed);                  // from t = 0 it read 2.2 times this
  CHECK(speed > 0.5 * true_speed);
}

TEST_CASE("one writer per folder: a folder another process writes is refused by evolve and "
          "resume, with or without --force, nothing written, the lock ends with its holder") {
  const fs::path out = scratch("locked");
  {
    const gbssn1d::FolderLock held("--out", out); // this process holds it
    for (const char* force : {"", "--force "}) {
      const Result r = run(std::string("evolve --tmax 0 ") + force + "--out " + out.string());
      INFO(r.err);
      CHECK(r.status == 2);
      CHECK(count_lines(r.err) == 1);
      CHECK(r.err.find("--out") != std::string::npos);
      CHECK(r.err.find(fmt::format("being written by another gbssn1d process (pid {})",
                                   static_cast<long>(::getpid())))
            != std::string::npos);
      CHECK(gbssn1d::folder_is_empty(out)); // only the lock file
    }
  }
  // released: the folder (holding the old lock file only) counts as empty
  REQUIRE(run("evolve --id 1log-trumpet --grid uniform --N 100 --rmax 20 --tmax 1 "
              "--checkpoint-every 0.5 --out "
              + out.string())
              .status
          == 0);
  REQUIRE(fs::exists(out / "checkpoint.bin"));
  const std::string series = slurp(out / "timeseries.dat");
  {
    const gbssn1d::FolderLock held("DIR", out);
    const Result r = run("resume " + out.string() + " --tmax 2");
    INFO(r.err);
    CHECK(r.status == 2);
    CHECK(r.err.find("being written by another gbssn1d process") != std::string::npos);
    CHECK(slurp(out / "timeseries.dat") == series);
  }
  CHECK(run("resume " + out.string() + " --tmax 2").status == 0);
  CHECK(slurp(out / "timeseries.dat") != series);
  // a lock file that is a symbolic link is refused, not followed
  const fs::path other = scratch("locked-link");
  fs::create_directories(other);
  fs::create_symlink(scratch("elsewhere") / "x", other / gbssn1d::folder_lock_name);
  const Result r = run("evolve --tmax 0 --force --out " + other.string());
  CHECK(r.status == 2);
  CHECK(r.err.find("symbolic link") != std::string::npos);
  CHECK_FALSE(fs::exists(scratch("elsewhere")));
  fs::remove_all(out);
  fs::remove_all(other);
}

TEST_CASE("one writer per folder: converge and a whole sweep are refused on a folder another "
          "process writes, a sweep's member tasks share their folder, and exclude a whole sweep") {
  const fs::path study = scratch("locked-study");
  const std::string common = " --id 1log-trumpet --grid uniform --N 40,60,80 --rmax 20 --tmax 0.5";
  {
    const gbssn1d::FolderLock held("--out", study);
    const Result r = run("converge --out " + study.string() + common);
    INFO(r.err);
    CHECK(r.status == 2);
    CHECK(r.err.find("being written by another gbssn1d process") != std::string::npos);
    CHECK(gbssn1d::folder_is_empty(study));
  }
  const fs::path sweep = scratch("locked-sweep");
  const std::string axes =
      " --sweep rahA=0,0.5 --id 1log-trumpet --grid uniform --N 100 --rmax 20 --tmax 0.5";
  {
    // a member task of this sweep runs (shared), a whole sweep of the folder does not
    const gbssn1d::FolderLock task("--out", sweep, gbssn1d::LockMode::shared);
    const Result whole = run("sweep --out " + sweep.string() + axes);
    INFO(whole.err);
    CHECK(whole.status == 2);
    CHECK(whole.err.find("being written by another gbssn1d process") != std::string::npos);
    const Result member = run("sweep --out " + sweep.string() + axes + " --member rahA=0");
    INFO(member.err);
    CHECK(member.status == 0);
  }
  {
    // a whole sweep holds its folder: a member task is refused
    const gbssn1d::FolderLock whole("--out", sweep);
    const Result member = run("sweep --out " + sweep.string() + axes + " --member rahA=0.5");
    INFO(member.err);
    CHECK(member.status == 2);
    CHECK(member.err.find("being written by another gbssn1d process") != std::string::npos);
    CHECK_FALSE(fs::exists(sweep / "logs" / "rahA=0.5.status"));
  }
  fs::remove_all(study);
  fs::remove_all(sweep);
}

TEST_CASE("sweep: a member recorded ok whose folder is gone or whose timeseries.dat is cut short "
          "is missing, not ok: --collect says so (exit 1: not complete), a rerun runs it again") {
  const fs::path dir = scratch("sweep_gone");
  const std::string cmd = "sweep --out " + dir.string()
                          + " --sweep rahA=0,0.5 --id 1log-trumpet --grid uniform --N 100 "
                            "--rmax 20 --tmax 1";
  REQUIRE(run(cmd).status == 0);
  const std::string complete = slurp(dir / "rahA=0" / "timeseries.dat");
  fs::remove_all(dir / "rahA=0.5");
  {
    // cut short: the end line and the last rows gone (a copy interrupted, a full disk)
    std::ofstream(dir / "rahA=0" / "timeseries.dat") << complete.substr(0, complete.size() / 2);
  }
  const Result collect = run(cmd + " --collect");
  INFO(collect.err);
  CHECK(collect.status == 1); // members missing: collect again once they have run
  CHECK(collect.err.find("2 missing") != std::string::npos);
  const std::string summary = slurp(dir / "summary.dat");
  CHECK(summary.find("0 missing") != std::string::npos);
  CHECK(summary.find("0.5 missing") != std::string::npos);
  CHECK(summary.find("is_cut_short") != std::string::npos);
  CHECK(summary.find("is_missing") != std::string::npos);
  const Result rerun = run(cmd);
  INFO(rerun.err);
  CHECK(rerun.status == 0);
  CHECK(rerun.err.find("rahA=0.5 was recorded ok, but its folder") != std::string::npos);
  CHECK(rerun.err.find("rahA=0 was recorded ok, but its") != std::string::npos);
  CHECK(slurp(dir / "rahA=0" / "timeseries.dat") == complete);
  CHECK(slurp(dir / "summary.dat").find("missing") == std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("--force into a folder holding a symbolic link is refused, naming the link, and the "
          "file it points at is left alone, --out a dangling link is refused as one") {
  const fs::path out = scratch("forced_link"), outside = scratch("outside_file");
  fs::create_directories(out);
  std::ofstream(outside) << "precious\n";
  fs::create_symlink(outside, out / "horizon.dat");
  const Result r = run("evolve --tmax 0 --force --out " + out.string());
  INFO(r.err);
  CHECK(r.status == 2);
  CHECK(count_lines(r.err) == 1);
  CHECK(r.err.find("holds a symbolic link, horizon.dat") != std::string::npos);
  CHECK(slurp(outside) == "precious\n");
  CHECK_FALSE(fs::exists(out / "config.toml"));
  // --out itself a link to nothing
  const fs::path dangling = scratch("dangling_out");
  fs::create_symlink(scratch("nowhere"), dangling);
  const Result d = run("evolve --tmax 0 --out " + dangling.string());
  INFO(d.err);
  CHECK(d.status == 2);
  CHECK(d.err.find("symbolic link to nothing") != std::string::npos);
  CHECK_FALSE(fs::exists(scratch("nowhere")));
  fs::remove_all(out);
  fs::remove(outside);
  fs::remove(dangling);
}

TEST_CASE("sweep --emit-tasks - writes the task lines to standard output, not to a file named -") {
  const fs::path dir = scratch("emit_stdout", true);
  const Result r = run("sweep --out " + (dir / "sw").string()
                       + " --sweep rahA=0,0.5 --id 1log-trumpet --tmax 1 --emit-tasks -");
  INFO(r.err);
  CHECK(r.status == 0);
  CHECK(count_lines(r.out) == 2);
  CHECK(r.out.find("--member rahA=0.5") != std::string::npos);
  CHECK_FALSE(fs::exists(fs::current_path() / "-"));
  CHECK_FALSE(fs::exists(dir / "-"));
  fs::remove_all(dir);
}

TEST_CASE("converge killed (SIGKILL, no chance to write) continues when the same command is "
          "rerun, without --force, each member folder has its config.toml and resumes alone") {
  const fs::path out = scratch("converge_kill9");
  const std::string args = " converge --N 400,500,600 -j 3 --grid uniform --rmax 50"
                           " --id 1log-trumpet --tmax 30 --checkpoint-every 0.5 --out "
                           + out.string();
  // killed once every member has written a checkpoint (the study's config.toml is written
  // before the members start)
  const std::string cmd = "sh -c '" + std::string(GBSSN1D_EXECUTABLE) + args
                          + " 2>/dev/null & p=$!; while [ ! -s " + out.string()
                          + "/N600/checkpoint.bin ]; do sleep 0.02; done; kill -KILL $p;"
                            " wait $p; exit $?'";
  const int raw = std::system(cmd.c_str());
  REQUIRE(WIFEXITED(raw));
  REQUIRE(WEXITSTATUS(raw) == 128 + 9);
  CHECK(fs::exists(out / "config.toml"));
  for (const char* member : {"N400", "N500", "N600"})
    CHECK(fs::exists(out / member / "config.toml"));
  // a member continues alone from its checkpoint, as any run
  const Result alone = run("resume " + (out / "N400").string());
  INFO(alone.err);
  CHECK(alone.status == 0);
  const Result again = run(args.substr(1));
  INFO(again.err);
  CHECK((again.status == 0 || again.status == 4 || again.status == 5));
  CHECK(again.err.find("members continue from their checkpoints") != std::string::npos);
  CHECK(again.err.find("is invalid") == std::string::npos);
  fs::remove_all(out);
}

TEST_CASE("converge: a member's failed write (file-size limit) exits 1, a write failure, not "
          "3 or 4 as a study that does not converge") {
  const fs::path out = scratch("converge_fsize");
  const std::string cmd = "sh -c 'ulimit -f 20; " + std::string(GBSSN1D_EXECUTABLE)
                          + " converge --N 100,140,180 --grid uniform --rmax 20 --tmax 3 --out "
                          + out.string() + " 2>" + out.string() + ".err; exit $?'";
  const int raw = std::system(cmd.c_str());
  REQUIRE(WIFEXITED(raw));
  const std::string err = slurp(out.string() + ".err");
  INFO(err);
  CHECK(WEXITSTATUS(raw) == 1);
  CHECK(err.find("could not write its output") != std::string::npos);
  CHECK(err.find("File too large") != std::string::npos);
  fs::remove_all(out);
  fs::remove(out.string() + ".err");
}

TEST_CASE("converge interrupted with members still to run: no new member starts, and the running "
          "one says it stopped (a checkpoint kept), not that it failed") {
  const fs::path out = scratch("converge_sigint_j1");
  const std::string cmd = "sh -c '" + std::string(GBSSN1D_EXECUTABLE)
                          + " converge --N 400,500,600 -j 1 --grid uniform --rmax 50 --tmax 60 "
                            "--out "
                          + out.string() + " 2>" + out.string() + ".err & p=$!; while [ ! -s "
                          + out.string()
                          + "/N400/horizon.dat ]; do sleep 0.01; done; kill -INT $p; wait $p; "
                            "exit $?'";
  const int raw = std::system(cmd.c_str());
  REQUIRE(WIFEXITED(raw));
  const std::string err = slurp(out.string() + ".err");
  INFO(err);
  CHECK(WEXITSTATUS(raw) == 130);
  CHECK(err.find("member N = 400 stopped: interrupted by SIGINT") != std::string::npos);
  CHECK(err.find("member N = 500 started") == std::string::npos);
  CHECK(err.find("failed: interrupted") == std::string::npos);
  fs::remove_all(out);
  fs::remove(out.string() + ".err");
}

TEST_CASE("sweep: a task line's --member builds its own member, not the whole sweep's "
          "configurations (a 100 x 100 sweep's line took 2.3 s of CPU before its 0.1 s run)") {
  const fs::path dir = scratch("big_sweep");
  std::string a, b;
  for (int k = 1; k <= 100; ++k) {
    a += fmt::format("{}{}", k == 1 ? "" : ",", 0.001 * k);
    b += fmt::format("{}{}", k == 1 ? "" : ",", 0.5 + 0.01 * k);
  }
  rusage before{}, after{};
  getrusage(RUSAGE_CHILDREN, &before);
  const Result r = run("sweep --out " + dir.string() + " --sweep rahA=" + a + " --sweep rah0=" + b
                       + " --id 1log-trumpet --grid uniform --N 50 --rmax 20 --tmax 0 "
                         "--member rahA=0.001_rah0=0.51");
  getrusage(RUSAGE_CHILDREN, &after);
  INFO(r.err);
  CHECK(r.status == 0);
  const double cpu = (after.ru_utime.tv_sec - before.ru_utime.tv_sec)
                     + 1e-6 * (after.ru_utime.tv_usec - before.ru_utime.tv_usec);
  INFO("CPU " << cpu << " s");
  CHECK(cpu < 1.0); // about 0.02 s: one member's configuration and a --tmax 0 run
  CHECK(fs::exists(dir / "rahA=0.001_rah0=0.51" / "timeseries.dat"));
  fs::remove_all(dir);
}
