// resume: a run continued from its checkpoint is the uninterrupted run, and whatever was done to
// its folder since (a corrupt, patched, foreign or legacy checkpoint, a missing or linked file)
// is refused before anything changes.
#include "cli_support.hpp"
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
#include <initializer_list>
#include <map>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <utility>
#include <vector>

namespace fs = std::filesystem;
using namespace gbssn1d::testing;

namespace {
using gbssn1d::ParamError;
using gbssn1d::read_config_text;
using gbssn1d::toml_string;
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
  // substage searches, held searches every 4 steps or every 0.7 M (timed by the steps' times
  // alone: the run resumes at t = 10 between two multiples of 0.7), the midstep-update variant
  // (whose searches are timed by the RHS-evaluation counter the checkpoint carries), and h_AH
  // extrapolated from the radii of the last steps (which the checkpoint carries)
  for (const std::string mode :
       {"--ah-every substage", "--ah-every 4", "--ah-interval 0.7",
        "--ah-every 2 --rah-variant midstep-update", "--ah-every extrapolated"}) {
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
    // ... through its temporary file, which the rename consumed: the stale one is gone (a
    // checkpoint written in place at its path would leave it, and a kill mid-write there
    // would leave no whole checkpoint)
    CHECK_FALSE(fs::exists(parts / "checkpoint.bin.tmp"));
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

// Subcycled boxes with the horizon shift take h_AH over their first three steps of the
// hierarchy from a pilot run without subcycling (ExtrapolatedRadius::before_run); a run resumed
// inside that span makes the same pilot again and continues bit for bit.
TEST_CASE("resume: subcycled boxes stopped inside the start's pilot span continue bit for bit") {
  const fs::path whole = scratch("pilot_whole"), parts = scratch("pilot_parts");
  fs::remove_all(whole);
  fs::remove_all(parts);
  const std::string flags = "evolve --id 1log-trumpet --grid boxes --levels 8 --rmax 256 --N 32 "
                            "--rahA 0.5 --rah0 0.89 --dt-series 0.25 --dt-profiles 1 "
                            "--checkpoint-every 0.5";
  REQUIRE(run(flags + " --tmax 4 --out " + whole.string()).status == 0);
  REQUIRE(run(flags + " --tmax 1 --out " + parts.string()).status == 0); // the pilot's to 1.5 M
  const Result r = run("resume " + parts.string() + " --tmax 4");
  INFO(r.err);
  REQUIRE(r.status == 0);
  for (const char* f : {"timeseries.dat", "profiles.dat", "horizon.dat", "config.toml"})
    CHECK(without_out(whole / f) == without_out(parts / f));
  fs::remove_all(whole);
  fs::remove_all(parts);
}

// A Z4c run (Theta in its state, its own series columns) resumes bit for bit, on a single grid
// and on boxes; its checkpoint refuses a resume as BSSN, naming the formulation, and changes
// nothing.
TEST_CASE(
    "resume: a Z4c run continues bit for bit, and its checkpoint refuses --formulation bssn") {
  const fs::path whole = scratch("z4c_whole"), parts = scratch("z4c_parts");
  for (const std::string grid : {"--grid uniform --N 200 --rmax 50",
                                 "--grid boxes --N 32 --rmax 64 --time-interp quadratic"}) {
    fs::remove_all(whole);
    fs::remove_all(parts);
    const std::string flags = "evolve --formulation z4c --kappa1 0.1 --id 1log-trumpet " + grid
                              + " --rahA 0.5 --rah0 0.7 --dt-series 0.5 --dt-profiles 3 "
                                "--checkpoint-every 2";
    REQUIRE(run(flags + " --tmax 8 --out " + whole.string()).status == 0);
    REQUIRE(run(flags + " --tmax 4 --out " + parts.string()).status == 0);
    const Result r = run("resume " + parts.string() + " --tmax 8");
    INFO(grid << ": " << r.err);
    REQUIRE(r.status == 0);
    for (const char* f : {"timeseries.dat", "profiles.dat", "horizon.dat"})
      CHECK(without_out(whole / f) == without_out(parts / f));
    CHECK(slurp(parts / "timeseries.dat").find("Theta_L2_R") != std::string::npos);
  }
  // the checkpoint is Z4c's: config.toml edited to bssn is refused, naming the formulation
  std::string config = slurp(parts / "config.toml");
  const auto at = config.find("formulation = \"z4c\"");
  REQUIRE(at != std::string::npos);
  config.replace(at, std::string("formulation = \"z4c\"").size(), "formulation = \"bssn\"");
  std::ofstream(parts / "config.toml", std::ios::trunc) << config;
  const std::string series = slurp(parts / "timeseries.dat");
  const Result refused = run("resume " + parts.string() + " --tmax 12");
  INFO(refused.err);
  CHECK(refused.status == 2);
  CHECK(refused.err.find("formulation: \"z4c\" -> \"bssn\"") != std::string::npos);
  CHECK(slurp(parts / "timeseries.dat") == series);
  fs::remove_all(whole);
  fs::remove_all(parts);
}

// A checkpoint or study member written before Z4c records no formulation, kappa1, kappa2 or
// z4c-lapse-adm: it is today's BSSN run (whose kappa1 is left unset, being idle), and a Z4c
// configuration is told apart from it.
TEST_CASE("a BSSN configuration written before Z4c reads as today's BSSN run, for any M") {
  for (const double M : {1.0, 2.0}) {
    gbssn1d::Params p;
    p.M = M;
    const std::string text = gbssn1d::config_text(gbssn1d::resolve(p));
    CHECK(text.find("kappa1") == std::string::npos);
    std::istringstream lines(text);
    std::string old, line;
    while (std::getline(lines, line))
      if (line.rfind("formulation =", 0) != 0 && line.rfind("kappa", 0) != 0
          && line.rfind("z4c-lapse-adm =", 0) != 0)
        old += line + "\n";
    CHECK(old.size() < text.size());
    CHECK(gbssn1d::config_differences(old, text, {}).empty());
    gbssn1d::Params z = p;
    z.formulation = gbssn1d::Formulation::z4c;
    const auto diff =
        gbssn1d::config_differences(old, gbssn1d::config_text(gbssn1d::resolve(z)), {});
    REQUIRE(diff.size() == 3);
    CHECK(diff[0] == "formulation: \"bssn\" -> \"z4c\"");
    CHECK(diff[1] == fmt::format("kappa1: (unset) -> {}", 0.02 / M));
    // a configuration without the key had no damping raised near the hole
    CHECK(diff[2] == fmt::format("kappa1-hole: 0 -> {}", 1.0 / M));
    CHECK(gbssn1d::absent_key_args(old).empty());
  }
}

// RK4 is stable for d_t B = -eta B only while eta dt stays inside its real stability interval
// (-2.785..., 0]: at eta dt = 2.8 the amplification 1 - z + z^2/2 - z^3/6 + z^4/24 exceeds 1.

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

TEST_CASE("resume refuses output files whose rows were edited or replaced since the checkpoint "
          "(same length), changing nothing, and a format-3 checkpoint resumes by lengths alone") {
  const fs::path a = scratch("rows_a"), b = scratch("rows_b"), whole = scratch("rows_whole");
  for (const auto& d : {a, b, whole})
    fs::remove_all(d);
  const std::string flags = "evolve --id 1log-trumpet --grid uniform --N 64 --rmax 40 --rahA 0.5 "
                            "--rah0 1.0 --dt-series 0.25 --dt-profiles 1 --checkpoint-every 1";
  REQUIRE(run(flags + " --tmax 4 --out " + a.string()).status == 0);
  REQUIRE(run(flags + " --ko-sigma 0.2 --tmax 4 --out " + b.string()).status == 0);
  REQUIRE(run(flags + " --tmax 8 --out " + whole.string()).status == 0);
  const auto original = folder(a);
  // another run's rows, and one digit of one row: each file the same length as before
  for (const char* file : {"timeseries.dat", "profiles.dat", "horizon.dat"}) {
    std::string text = slurp(b / file);
    if (std::string(file) == "horizon.dat") { // one digit changed in a's own file
      text = original.at(file);
      const auto row = text.find("\n0.5 ");
      REQUIRE(row != std::string::npos);
      char& digit = text[row + 8];
      digit = digit == '1' ? '2' : '1';
    }
    REQUIRE(text.size() >= original.at(file).size() - 64);
    std::ofstream(a / file, std::ios::binary | std::ios::trunc) << text;
    const auto edited = folder(a);
    const Result r = run("resume " + a.string() + " --tmax 8");
    INFO(file << ": " << r.err);
    CHECK(r.status == 2);
    CHECK(r.err.find(std::string(file) + " is not what the run wrote up to its checkpoint")
          != std::string::npos);
    CHECK(folder(a) == edited);
    std::ofstream(a / file, std::ios::binary | std::ios::trunc) << original.at(file);
  }
  // the checkpoint as format 3 wrote it (no row hashes): resumed, bit for bit
  std::string cp = slurp(a / "checkpoint.bin");
  const std::string magic = "gbssn1d checkpoint 4\n";
  REQUIRE(cp.rfind(magic, 0) == 0);
  std::uint64_t n_config = 0;
  std::memcpy(&n_config, cp.data() + magic.size(), 8);
  const std::size_t marks_at = magic.size() + 8 + n_config + 8 + 8 + 8 + 8 + 8 + 1 + 8 + 1 + 1 + 8;
  cp.erase(marks_at + 6 * 8, 3 * 8); // the three row hashes
  cp[magic.size() - 2] = '3';
  cp.resize(cp.size() - 8);
  const std::uint64_t h = fnv1a64(cp);
  cp.append(reinterpret_cast<const char*>(&h), 8);
  std::ofstream(a / "checkpoint.bin", std::ios::binary | std::ios::trunc) << cp;
  const Result r = run("resume " + a.string() + " --tmax 8");
  INFO(r.err);
  REQUIRE(r.status == 0);
  for (const char* f : {"timeseries.dat", "profiles.dat", "horizon.dat"})
    CHECK(without_out(whole / f) == without_out(a / f));
  for (const auto& d : {a, b, whole})
    fs::remove_all(d);
}

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

TEST_CASE("a Z4c run recorded before --kappa1-hole existed resumes with kappa1 everywhere, and "
          "today's default is another configuration") {
  const fs::path whole = scratch("z4c_whole"), parts = scratch("z4c_parts");
  fs::remove_all(whole);
  fs::remove_all(parts);
  const std::string flags = "evolve --id 1log-trumpet --grid uniform --N 64 --rmax 20 "
                            "--formulation z4c --kappa1-hole 0 --dt-series 0.5 --dt-profiles 5 "
                            "--checkpoint-every 2";
  REQUIRE(run(flags + " --tmax 6 --out " + whole.string()).status == 0);
  REQUIRE(run(flags + " --tmax 4 --out " + parts.string()).status == 0);
  std::string config = slurp(parts / "config.toml");
  const auto at = config.find("kappa1-hole = 0\n");
  REQUIRE(at != std::string::npos);
  config.erase(at, std::string("kappa1-hole = 0\n").size());
  std::ofstream(parts / "config.toml", std::ios::trunc) << config;
  CHECK(gbssn1d::absent_key_args(config) == std::vector<std::string>{"--kappa1-hole=0"});
  const Result r = run("resume " + parts.string() + " --tmax 6");
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(without_out(whole / "timeseries.dat") == without_out(parts / "timeseries.dat"));
  CHECK(without_out(whole / "profiles.dat") == without_out(parts / "profiles.dat"));
  std::string today = config;
  today.insert(at, "kappa1-hole = 1\n");
  const auto diff = gbssn1d::config_differences(config, today, {});
  REQUIRE(diff.size() == 1);
  CHECK(diff.front() == "kappa1-hole: 0 -> 1");
  for (const auto& d : {whole, parts})
    fs::remove_all(d);
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
  const std::string magic = "gbssn1d checkpoint 4\n";
  REQUIRE(good.rfind(magic, 0) == 0);
  std::uint64_t n_config = 0;
  std::memcpy(&n_config, good.data() + magic.size(), 8);
  const std::size_t step_at = magic.size() + 8 + n_config, t_at = step_at + 8;
  const std::size_t evaluations_at = t_at + 8 + 8 + 8 + 8 + 1 + 8 + 1 + 1;
  const std::size_t count_at = evaluations_at + 8 + 9 * 8; // 6 marks, 3 row hashes
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

// Guards the flag bytes of checkpoint.bin (evolution/checkpoint.cpp): each is 0 or 1, and resume
// refuses any other value as a corrupt checkpoint, naming the flag, before it changes anything.
// The byte is set with the checksum made valid again (patched), as only a deliberate edit or a
// bug could: the checksum alone would refuse a byte flipped by accident. A flag of 2 was read as
// 0 (a held h_AH dropped) and the run resumed; only the readers' fuzzer, outside ctest, tried it.
// A single grid's flags: h_AH's, the horizon's and the report's after the output counters, and
// the shared h_AH's after the states (format 4; a single grid has no level h_AH flags, which the
// reader's test in tests/evolution/test_evolution.cpp covers with the rest).
TEST_CASE("resume refuses a checkpoint whose flag byte is neither 0 nor 1, naming the flag, and "
          "leaves the run as it was") {
  const fs::path dir = scratch("resume_flag_bytes");
  REQUIRE(run("evolve --id 1log-trumpet --grid uniform --N 64 --rmax 20 --tmax 2 --rahA 0.5 "
              "--rah0 1 --checkpoint-every 1 --out "
              + dir.string())
              .status
          == 0);
  const std::string good = slurp(dir / "checkpoint.bin");
  const std::string magic = "gbssn1d checkpoint 4\n";
  REQUIRE(good.rfind(magic, 0) == 0);
  auto u64_at = [&](std::size_t at) {
    std::uint64_t v = 0;
    std::memcpy(&v, good.data() + at, 8);
    return v;
  };
  const std::size_t t_at = magic.size() + 8 + u64_at(magic.size()) + 8;
  const std::size_t h_AH_at = t_at + 8 + 8 + 8 + 8; // after t, dt and the two output counters
  const std::size_t state_at = h_AH_at + 1 + 8 + 1 + 1 + 8 + 9 * 8; // RHS count, marks, hashes
  const std::size_t finer_at = state_at + 8 + 8 * u64_at(state_at);
  REQUIRE(u64_at(finer_at) == 0); // a single grid: no finer levels
  const std::size_t levels_at = finer_at + 8, n_levels = u64_at(levels_at);
  std::vector<std::pair<std::size_t, std::string>> flags{
      {h_AH_at, "h_AH flag"}, {h_AH_at + 9, "horizon flag"}, {h_AH_at + 10, "report flag"}};
  for (std::size_t l = 0; l < n_levels; ++l)
    flags.emplace_back(levels_at + 8 + 9 * l, "level h_AH flag");
  flags.emplace_back(levels_at + 8 + 9 * n_levels, "shared h_AH flag");
  // the run found its horizon and reported it: flags of both values are among these
  CHECK(good[h_AH_at] == 1);
  CHECK(good[h_AH_at + 9] == 1);
  // each case starts from the run as it ended (a checkpoint wrongly accepted resumes the run)
  const auto ended = folder(dir);
  auto restore = [&](const std::string& checkpoint) {
    for (const auto& e : fs::directory_iterator(dir))
      if (ended.count(e.path().filename().string()) == 0)
        fs::remove_all(e.path());
    for (const auto& [name, bytes] : ended)
      std::ofstream(dir / name, std::ios::binary | std::ios::trunc) << bytes;
    std::ofstream(dir / "checkpoint.bin", std::ios::binary | std::ios::trunc) << checkpoint;
  };
  for (const auto& [at, what] : flags) {
    REQUIRE((good[at] == 0 || good[at] == 1));
    for (const unsigned char value : std::initializer_list<unsigned char>{2, 3, 128, 255}) {
      restore(patched(good, at, &value, 1));
      const auto before = folder(dir);
      const Result r = run("resume " + dir.string() + " --tmax 3");
      INFO(what << " = " << int{value} << ": " << r.err);
      CHECK(r.status == 2);
      CHECK(r.err.find("is corrupt (" + what + ")") != std::string::npos);
      CHECK(r.err.find("DIR") != std::string::npos);
      CHECK(folder(dir) == before);
    }
  }
  // as written it resumes
  restore(good);
  CHECK(run("resume " + dir.string() + " --tmax 3").status == 0);
  fs::remove_all(dir);
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
