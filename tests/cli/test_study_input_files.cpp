// Studies and the files their flags name (--rah-hAH-file): a sweep records the content's hash
// with each member's inputs, so that a rerun, a task line (--member) or --collect after the file
// was edited is refused as any other changed input is; a converge member keeps a copy as evolve
// does, and the study records the content's hash.
#include "cli_support.hpp"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <sys/wait.h>

namespace fs = std::filesystem;
using namespace gbssn1d::testing;

namespace {

/// A horizon history of columns t, r_ah: r_ah grows by `slope` per unit time.
void write_history(const fs::path& f, double slope, int rows = 9) {
  std::ofstream out(f);
  out << "# t r_ah\n";
  for (int k = 0; k < rows; ++k)
    out << 0.5 * k << " " << 0.8304 + slope * 0.5 * k << "\n";
}

/// Every regular file below `dir` with its content.
std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> all;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file())
      all[fs::relative(e.path(), dir).string()] = slurp(e.path());
  return all;
}

} // namespace

TEST_CASE(
    "sweep: a rerun, a task line or --collect after --rah-hAH-file's content changed is "
    "refused as other inputs, naming the member and the file's content, and nothing changes") {
  const fs::path dir = scratch("sweep_hAH_content"), file = scratch("sweep_hAH_content.dat");
  write_history(file, 0.002);
  const std::string sweep = "sweep --progress-every 0 --sweep N=32,40 --id 1log-trumpet --grid "
                            "uniform --rmax 20 --rahA 0.5 --rah0 0.89 --tmax 1 --rah-hAH-file "
                            + file.string() + " --out " + dir.string();
  REQUIRE(run(sweep).status == 0);
  CHECK(slurp(dir / "logs" / "N=32.inputs").find("# rah-hAH-file.dat fnv1a = ")
        != std::string::npos);
  const Result same = run(sweep);
  INFO(same.err);
  CHECK(same.status == 0); // the same content: the finished members are kept
  const auto before = snapshot(dir);
  write_history(file, 0.003); // the r_ah column edited, the path the same
  for (const char* extra : {"", " --member N=32", " --collect"}) {
    const Result r = run(sweep + extra);
    INFO(extra << ": " << r.err);
    CHECK(r.status == 2);
    CHECK(r.err.find("holds members run with other inputs") != std::string::npos);
    CHECK(r.err.find("N=32 (rah-hAH-file content: fnv1a ") != std::string::npos);
    CHECK(snapshot(dir) == before);
  }
  fs::remove_all(dir);
  fs::remove(file);
}

TEST_CASE("converge: each member keeps --rah-hAH-file as the study read it and resumes alone "
          "from it, and a rerun after the file's content changed is refused as other inputs") {
  const fs::path out = scratch("converge_hAH_content"), file = scratch("converge_hAH.dat");
  write_history(file, 0.002, 81); // t up to 40
  const std::string args = " converge --N 200,250,300 -j 3 --grid uniform --rmax 30 --id "
                           "1log-trumpet --rahA 0.5 --rah0 0.89 --tmax 30 --checkpoint-every "
                           "0.5 --rah-hAH-file "
                           + file.string() + " --out " + out.string();
  // stopped (SIGTERM) once every member has written a checkpoint
  const int raw = run_signalled(
      args.substr(1), {.files = {out / "N200" / "checkpoint.bin", out / "N250" / "checkpoint.bin",
                                 out / "N300" / "checkpoint.bin"},
                       .signal = "TERM",
                       .poll = 0.02});
  REQUIRE(WIFEXITED(raw));
  REQUIRE(WEXITSTATUS(raw) == 128 + 15);
  const std::string read = slurp(file);
  for (const char* member : {"N200", "N250", "N300"})
    CHECK(slurp(out / member / "rah-hAH-file.dat") == read);
  CHECK(slurp(out / "config.toml").find("# rah-hAH-file.dat fnv1a = ") != std::string::npos);
  const auto before = snapshot(out);
  write_history(file, 0.003, 81); // the r_ah column edited, the path the same
  const Result changed = run(args.substr(1));
  INFO(changed.err);
  CHECK(changed.status == 2);
  CHECK(changed.err.find("holds a converge study of other inputs (rah-hAH-file content: fnv1a ")
        != std::string::npos);
  CHECK(snapshot(out) == before);
  // a member continues alone from its checkpoint, with its copy (not the edited file)
  const Result alone = run("resume " + (out / "N200").string());
  INFO(alone.err);
  CHECK(alone.status == 0);
  CHECK(alone.err.find("it continues with the copy it took then") != std::string::npos);
  fs::remove_all(out);
  fs::remove(file);
}
