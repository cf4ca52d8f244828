// A run with --rah-hAH-file keeps the file as it read it (OUT/rah-hAH-file.dat), and a resume
// continues with that copy only: without it (deleted, replaced by a folder, unreadable content)
// the folder is refused as other non-resumable folders are (exit 2, nothing changed), naming the
// copy, instead of continuing with whatever the flag's path holds now.
#include "../test_support.hpp"

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

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

struct Result {
  int status;
  std::string err;
};

Result run(const std::string& args) {
  const fs::path err = scratch("hAH_copy_stderr");
  const std::string cmd =
      std::string(GBSSN1D_EXECUTABLE) + " " + args + " >/dev/null 2>" + err.string();
  const int raw = std::system(cmd.c_str());
  Result r{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(err)};
  fs::remove(err);
  return r;
}

/// Every regular file below `dir` with its bytes.
std::map<std::string, std::string> contents(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file())
      files[fs::relative(e.path(), dir).string()] = slurp(e.path());
  return files;
}

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
  refused("line 2: '0,9' in column r_ah is not a number");
  // the copy put back: the run continues, with it
  std::ofstream(copy, std::ios::binary | std::ios::trunc) << kept;
  const Result r = run("resume " + out.string() + " --tmax 2");
  INFO(r.err);
  CHECK(r.status == 0);
  CHECK(r.err.find("continues with the copy it took then") != std::string::npos);
  fs::remove_all(out);
  fs::remove(file);
}
