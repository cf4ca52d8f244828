// How a run ends, as a user meets it: completed or stopped, signals, failed writes, closed
// streams, a folder removed under it, the resume hint and the progress line.
#include "cli_support.hpp"
#include "config/config_file.hpp"
#include "config/folder_lock.hpp"
#include "config/params.hpp"
#include "evolution/checkpoint.hpp"

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
using namespace gbssn1d::testing;

namespace {
using gbssn1d::ParamError;
using gbssn1d::read_config_text;
using gbssn1d::toml_string;
} // namespace

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
  const int raw =
      run_signalled("evolve --id 1log-trumpet --grid uniform --N 3200 --rmax 200"
                    " --tmax 2000 --dt-profiles 1 --out "
                        + out.string(),
                    {.files = {out / "horizon.dat"}, .signal = "TERM", .poll = 0.1, .settle = 0.5});
  REQUIRE(WIFEXITED(raw));
  CHECK(WEXITSTATUS(raw) == 143);
  const std::string text = slurp(out / "timeseries.dat");
  CHECK(text.substr(text.rfind("# end:")).find("# end: stopped: interrupted by SIGTERM at t = ")
        == 0);
  CHECK(fs::exists(out / "checkpoint.bin")); // written on the signal: `resume` continues
  // every profile row is whole: 19 columns (the last: the level, 0 on a single grid)
  std::ifstream profiles(out / "profiles.dat");
  int rows = 0;
  for (std::string line; std::getline(profiles, line);) {
    if (line.empty() || line[0] == '#')
      continue;
    std::istringstream words(line);
    int n = 0;
    for (std::string w; words >> w;)
      ++n;
    CHECK(n == 19);
    ++rows;
  }
  CHECK(rows >= 3200);
  CHECK(rows % 3200 == 0);
  // resumed to the checkpoint's own time (its exact double): no step left, the run completes
  // there (the checkpoint's step is this run's last, not outside its steps)
  const double t_stop = gbssn1d::read_checkpoint(out / "checkpoint.bin").t;
  const auto at = run(fmt::format("resume {} --tmax {:.17g}", out.string(), t_stop));
  INFO(at.err);
  CHECK(at.status == 0);
  const std::string resumed = slurp(out / "timeseries.dat");
  CHECK(resumed.substr(resumed.rfind("# end:"))
        == fmt::format("# end: completed at t = {}\n", t_stop));
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
    const int raw = run_signalled(
        "evolve --id 1log-trumpet --grid uniform --N 3200 --rmax 200"
        " --tmax 2000 --out "
            + out.string(),
        {.files = {out / "horizon.dat"}, .signal = name, .poll = 0.05, .settle = 0.2});
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

TEST_CASE("resume of a folder its user cannot write is refused up front: exit 2 naming DIR, "
          "nothing changed (it failed late, exit 1, at its config.toml)") {
  const fs::path out = scratch("resume_unwritable");
  REQUIRE(run("evolve --id 1log-trumpet --grid uniform --N 64 --rmax 16 --tmax 2 "
              "--checkpoint-every 1 --out "
              + out.string())
              .status
          == 0);
  std::map<std::string, std::string> before;
  for (const auto& e : fs::directory_iterator(out))
    before[e.path().filename().string()] = slurp(e.path());
  // root writes anywhere: the resume then runs as nobody (the folder stays root's, 0755), its
  // lock file open to others (as a user's own lock file is open to them in a folder they
  // cannot write: the case that failed late)
  std::string as_user;
  if (::geteuid() == 0) {
    fs::permissions(out / ".gbssn1d.lock", fs::perms::others_read | fs::perms::others_write,
                    fs::perm_options::add);
    as_user = "setpriv --reuid=65534 --regid=65534 --clear-groups ";
    if (std::system((as_user + GBSSN1D_EXECUTABLE + " --version >/dev/null 2>&1").c_str()) != 0) {
      MESSAGE("skipped: running as root, and the program cannot be run as nobody (no setpriv, "
              "or a folder on its path closed to others)");
      fs::remove_all(out);
      return;
    }
  } else {
    fs::permissions(out, fs::perms::owner_write, fs::perm_options::remove);
  }
  const fs::path err = out.string() + ".err";
  const int raw = std::system(
      (as_user + GBSSN1D_EXECUTABLE + " resume " + out.string() + " --tmax 4 2>" + err.string())
          .c_str());
  fs::permissions(out, fs::perms::owner_write, fs::perm_options::add);
  REQUIRE(WIFEXITED(raw));
  const std::string message = slurp(err);
  INFO(message);
  CHECK(WEXITSTATUS(raw) == 2);
  CHECK(message.find("DIR = " + out.string() + " is invalid: is not writable")
        != std::string::npos);
  for (const auto& [name, text] : before) {
    CAPTURE(name);
    CHECK(slurp(out / name) == text);
  }
  fs::remove_all(out);
  fs::remove(err);
}

TEST_CASE("resume of a completed run to its own tmax does nothing and changes no file, and a "
          "resumed run does not report its start's horizon again") {
  const fs::path out = scratch("resume_complete_same_tmax");
  const auto first =
      run("evolve --id 1log-trumpet --N 64 --tmax 1 --checkpoint-every 0.5 --out " + out.string());
  REQUIRE(first.status == 0);
  CHECK(first.err.find("apparent horizon at t = 0:") != std::string::npos);
  std::map<std::string, std::string> before;
  for (const auto& e : fs::directory_iterator(out))
    before[e.path().filename().string()] = slurp(e.path());
  // --tmax equal to the run's end: nothing to do (it ran again and rewrote every file)
  const auto same = run("resume " + out.string() + " --tmax 1");
  INFO(same.err);
  CHECK(same.status == 0);
  CHECK(same.err.find("is complete at t = 1; nothing to do") != std::string::npos);
  for (const auto& [name, text] : before) {
    CAPTURE(name);
    CHECK(slurp(out / name) == text);
  }
  // continued to a later tmax: the horizon reported at the start is not reported again
  const auto later = run("resume " + out.string() + " --tmax 2");
  INFO(later.err);
  CHECK(later.status == 0);
  CHECK(later.err.find("apparent horizon at t =") == std::string::npos);
  fs::remove_all(out);
}

TEST_CASE("resume --tmax equal to the checkpoint's time is not before it") {
  // uniform 16 M at N = 64: dt = 1/8 exactly, so the checkpoint lies at t = 0.5 itself
  const fs::path out = scratch("resume_tmax_at_checkpoint");
  REQUIRE(run("evolve --id 1log-trumpet --grid uniform --rmax 16 --N 64 --tmax 1 "
              "--checkpoint-every 0.5 --out "
              + out.string())
              .status
          == 0);
  const auto at = run("resume " + out.string() + " --tmax 0.5");
  INFO(at.err);
  CHECK(at.status == 0);
  CHECK(at.err.find("is before the checkpoint") == std::string::npos);
  const auto before = run("resume " + out.string() + " --tmax 0.49");
  CHECK(before.status == 2);
  CHECK(before.err.find("--tmax = 0.49 is invalid: is before the checkpoint at t = 0.5")
        != std::string::npos);
  fs::remove_all(out);
}
