// A run with --rah-hAH-file keeps the file as it read it (OUT/rah-hAH-file.dat), and a resume
// continues with that copy only: without it (deleted, replaced by a folder or a symbolic link)
// or with a copy changed since the run read it (its hash, recorded in the checkpoint, differs:
// other valid data or unreadable content) the folder is refused as other non-resumable folders
// are (exit 2, nothing changed), naming the copy, instead of continuing with other data.
#include "cli_support.hpp"
#include "evolution/checkpoint.hpp"

#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace fs = std::filesystem;

namespace {

using gbssn1d::testing::scratch;

using gbssn1d::testing::slurp;

using gbssn1d::testing::contents;
using gbssn1d::testing::Result;
using gbssn1d::testing::run;

void write_history(const fs::path& f, double slope) {
  std::ofstream out(f);
  out << "# t r_ah\n";
  for (int k = 0; k <= 8; ++k)
    out << 0.5 * k << " " << 0.8304 + slope * 0.5 * k << "\n";
}

} // namespace

TEST_CASE("resume refuses a folder whose copy of --rah-hAH-file is gone, naming the copy") {
  const fs::path out = scratch("hAH_copy_run"), file = scratch("hAH_copy_file.dat");
  write_history(file, 0.002);
  REQUIRE(run("evolve --id 1log-trumpet --grid uniform --N 60 --rmax 20 --rahA 0.5 --rah0 0.89 "
              "--dt-series 0.25 --checkpoint-every 0.5 --tmax 1 --rah-hAH-file "
              + file.string() + " --out " + out.string())
              .status
          == 0);
  const fs::path copy = out / "rah-hAH-file.dat";
  REQUIRE(slurp(copy) == slurp(file));
  const std::string kept = slurp(copy);
  write_history(file, 0.05); // the flag's path holds other data now
  fs::remove(copy);
  auto refused = [&](const std::string& why) {
    const auto before = contents(out);
    const Result r = run("resume " + out.string() + " --tmax 2");
    INFO(r.err);
    CHECK(r.status == 2);
    CHECK(r.err.find("error: ") != std::string::npos);
    CHECK(r.err.find(copy.string()) != std::string::npos);
    CHECK(r.err.find(why) != std::string::npos);
    CHECK(contents(out) == before); // nothing changed
  };
  refused("DIR = " + out.string() + " is invalid: its copy of --rah-hAH-file, " + copy.string()
          + ", is missing");
  fs::create_directory(copy); // not a file
  refused("is not a regular file");
  fs::remove(copy);
  std::ofstream(copy) << "# t r_ah\n0 0,9\n"; // damaged
  refused("has changed since the run read it");
  write_history(copy, 0.003); // other valid data: one value edited ...
  refused("has changed since the run read it");
  std::ofstream(copy, std::ios::binary | std::ios::trunc) << kept.substr(0, kept.rfind("3.5 "));
  refused("has changed since the run read it"); // ... or cut at a row
  const fs::path same = scratch("hAH_copy_same.dat");
  std::ofstream(same, std::ios::binary) << kept;
  fs::remove(copy);
  fs::create_symlink(same, copy); // a link, even to the very bytes the run read
  refused("is a symbolic link");
  fs::remove(copy);
  fs::remove(same);
  // the copy put back: the run continues, with it
  std::ofstream(copy, std::ios::binary | std::ios::trunc) << kept;
  const Result r = run("resume " + out.string() + " --tmax 2");
  INFO(r.err);
  CHECK(r.status == 0);
  CHECK(r.err.find("continues with the copy it took then") != std::string::npos);
  CHECK(r.err.find("records no hash") == std::string::npos);
  fs::remove_all(out);
  fs::remove(file);
}

TEST_CASE("resume of a checkpoint that records no hash of the --rah-hAH-file copy (an earlier "
          "version's) takes the copy as it is, with a warning, and records its hash from then on") {
  const fs::path out = scratch("hAH_copy_old"), file = scratch("hAH_copy_old_file.dat");
  write_history(file, 0.002);
  REQUIRE(run("evolve --id 1log-trumpet --grid uniform --N 60 --rmax 20 --rahA 0.5 --rah0 0.89 "
              "--dt-series 0.25 --checkpoint-every 0.5 --tmax 1 --rah-hAH-file "
              + file.string() + " --out " + out.string())
              .status
          == 0);
  const std::string hash_line = "# rah-hAH-file.dat fnv1a = ";
  // the checkpoint as an earlier version wrote it: its configuration without the hash line
  {
    gbssn1d::Checkpoint c = gbssn1d::read_checkpoint(out / "checkpoint.bin");
    const auto at = c.config.find(hash_line);
    REQUIRE(at != std::string::npos);
    c.config.erase(at, c.config.find('\n', at) + 1 - at);
    gbssn1d::write_checkpoint(out / "checkpoint.bin", c);
  }
  const fs::path copy = out / "rah-hAH-file.dat";
  const std::string kept = slurp(copy);
  std::ofstream(copy) << "# t r_ah\n0 0,9\n"; // damaged: what the reader refuses still is
  Result r = run("resume " + out.string() + " --tmax 2");
  CHECK(r.status == 2);
  CHECK(r.err.find("line 2: '0,9' in column r_ah is not a number") != std::string::npos);
  std::ofstream(copy, std::ios::binary | std::ios::trunc) << kept;
  r = run("resume " + out.string() + " --tmax 2");
  INFO(r.err);
  CHECK(r.status == 0);
  CHECK(r.err.find("warning: the checkpoint in " + out.string() + " records no hash of "
                   + copy.string())
        != std::string::npos);
  // the resumed run's checkpoints record it: a copy changed now is refused
  CHECK(gbssn1d::read_checkpoint(out / "checkpoint.bin").config.find(hash_line)
        != std::string::npos);
  std::ofstream(copy, std::ios::binary | std::ios::app) << "4.5 0.9\n";
  r = run("resume " + out.string() + " --tmax 3");
  CHECK(r.status == 2);
  CHECK(r.err.find("has changed since the run read it") != std::string::npos);
  fs::remove_all(out);
  fs::remove(file);
}
