// converge and sweep folders as a user's shell leaves them: one writer per folder, reruns of
// other inputs, saved samples, links, members whose output is gone, interrupts and kills.
#include "cli_support.hpp"
#include "config/config_file.hpp"
#include "config/folder_lock.hpp"
#include "config/params.hpp"
#include "config/paths.hpp"

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
  REQUIRE((first == 0 || first == 4 || first == 5 || first == 6));
  // members N48 and N64 have checkpoints and samples at the radii of N32's grid
  const int rerun = run("converge --N 40,48,64 --force" + flags + "--out " + a.string()).status;
  REQUIRE((rerun == 0 || rerun == 4 || rerun == 5 || rerun == 6));
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
  REQUIRE((first == 0 || first == 4 || first == 5 || first == 6));
  const std::string before = without_out(a / "convergence.dat");
  const auto flip = [](const fs::path& file) {
    std::string bytes = slurp(file);
    REQUIRE(bytes.size() > 64);
    bytes[bytes.size() / 2] = static_cast<char>(bytes[bytes.size() / 2] ^ 0x5a);
    std::ofstream(file, std::ios::binary) << bytes;
  };
  // its completed record flipped: not used, the member continues from its last checkpoint
  flip(a / "N48" / "converge_completed.bin");
  Result rerun = run(cmd + " --force");
  INFO(rerun.err);
  CHECK(rerun.status == first);
  CHECK(rerun.err.find("member N = 48 is run: its converge_completed.bin is not used (its "
                       "checksum does not match (a flipped or cut byte))")
        != std::string::npos);
  CHECK(rerun.err.find("member N = 48 resumes at t = 2") != std::string::npos);
  CHECK(without_out(a / "convergence.dat") == before);
  // and the samples of that checkpoint flipped too: the member starts afresh
  flip(a / "N48" / "converge_completed.bin");
  flip(a / "N48" / "converge_samples.bin");
  rerun = run(cmd + " --force");
  CHECK(rerun.status == first);
  CHECK(rerun.err.find("member N = 48 starts afresh") != std::string::npos);
  CHECK(rerun.err.find("checksum") != std::string::npos);
  CHECK(without_out(a / "convergence.dat") == before);
  fs::remove_all(a);
}

// A closed terminal (SIGHUP) and a batch scheduler's warning ahead of its time limit (SIGUSR1,
// SIGUSR2) stop a run as SIGTERM does: the step finished, a checkpoint, the end line, 128 + n.

TEST_CASE("converge interrupted: exit 130, and its files and message say they are partial") {
  const fs::path out = scratch("converge_sigint");
  const int raw = run_signalled("converge --N 800,1000,1200 -j 3 --grid uniform --rmax 100"
                                " --id 1log-trumpet --tmax 200 --out "
                                    + out.string(),
                                {.files = {out / "N1200" / "horizon.dat"},
                                 .signal = "INT",
                                 .poll = 0.05,
                                 .settle = 0.3,
                                 .err = out.string() + ".err"});
  REQUIRE(WIFEXITED(raw));
  CHECK(WEXITSTATUS(raw) == 130);
  const std::string err = slurp(out.string() + ".err");
  CHECK(err.find("interrupted by SIGINT") != std::string::npos);
  CHECK(err.find("done;") == std::string::npos);
  // the scaled profiles' time (tmax) lies beyond the common rows because the study was
  // interrupted, and the note says so (it blamed --dt-series: "is no output time")
  if (err.find("interrupted by SIGINT at t = 0 ") == std::string::npos) {
    CHECK(err.find("note: the scaled profiles' time, tmax = 200 lies beyond the common times, "
                   "which end at t = ")
          != std::string::npos);
    CHECK(err.find("(the study was interrupted; rerun it to complete)") != std::string::npos);
  }
  CHECK(err.find("is no output time") == std::string::npos);
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
  CHECK((again.status == 0 || again.status == 4 || again.status == 5 || again.status == 6));
  CHECK(again.err.find("the others continue from their last checkpoints") != std::string::npos);
  CHECK(again.err.find("resumes at t =") != std::string::npos);
  const std::string text = slurp(out / "convergence.dat");
  CHECK(text.substr(text.rfind("# end:")).find("# end: completed at t = 200") == 0);
  fs::remove_all(out);
  fs::remove(out.string() + ".err");
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
    // a run that has not yet written its first checkpoint: the writer is named, not the
    // missing checkpoint (the lock is taken before the checkpoint is looked for)
    fs::rename(out / "checkpoint.bin", out / "checkpoint.held");
    const Result early = run("resume " + out.string() + " --tmax 2");
    INFO(early.err);
    CHECK(early.status == 2);
    CHECK(early.err.find("being written by another gbssn1d process") != std::string::npos);
    CHECK(early.err.find("no checkpoint.bin") == std::string::npos);
    fs::rename(out / "checkpoint.held", out / "checkpoint.bin");
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
  // before the members start). Each member's file is waited for: the members run in parallel,
  // and on a busy machine (CI, 2 cores, the tests run 3 at a time) N400 had none yet when
  // N600 had one.
  const int raw = run_signalled(
      args.substr(1), {.files = {out / "N400" / "checkpoint.bin", out / "N500" / "checkpoint.bin",
                                 out / "N600" / "checkpoint.bin"},
                       .signal = "KILL",
                       .poll = 0.02});
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
  CHECK((again.status == 0 || again.status == 4 || again.status == 5 || again.status == 6));
  CHECK(again.err.find("the others continue from their last checkpoints") != std::string::npos);
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
  const int raw = run_signalled(
      "converge --N 400,500,600 -j 1 --grid uniform --rmax 50 --tmax 60 --out " + out.string(),
      {.files = {out / "N400" / "horizon.dat"},
       .signal = "INT",
       .poll = 0.01,
       .err = out.string() + ".err"});
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

TEST_CASE("converge interrupted after a member completed: the rerun takes that member's records "
          "from its folder instead of running it again, and a member folder another command "
          "wrote since runs again, the study's numbers an uninterrupted study's") {
  const fs::path out = scratch("converge_keep_completed"), fresh = scratch("converge_keep_fresh");
  const std::string flags =
      " converge --N 400,600,800 -j 1 --grid uniform --rmax 50 --tmax 300 --dt-series 2 --out ";
  // interrupted as soon as N = 400 has completed (its record written), N = 600 running; the
  // wait ends too if the study ends first (a study whose members all stop), which then fails
  // the exit status's check instead of waiting forever
  const std::string cmd = "sh -c '" + std::string(GBSSN1D_EXECUTABLE) + flags + out.string() + " 2>"
                          + out.string() + ".err & p=$!; while [ ! -e " + out.string()
                          + "/N400/converge_completed.bin ] && kill -0 $p 2>/dev/null; do sleep "
                            "0.01; done; kill -INT $p; wait $p; exit $?'";
  const int raw = std::system(cmd.c_str());
  REQUIRE(WIFEXITED(raw));
  INFO(slurp(out.string() + ".err"));
  REQUIRE(WEXITSTATUS(raw) == 130);
  const std::string n400 = slurp(out / "N400" / "timeseries.dat");
  const Result rerun = run(flags.substr(1) + out.string());
  INFO(rerun.err);
  CHECK(rerun.err.find("member N = 400 completed earlier: its records are taken from its "
                       "converge_completed.bin")
        != std::string::npos);
  CHECK(rerun.err.find("member N = 400 started") == std::string::npos); // not run again
  CHECK(slurp(out / "N400" / "timeseries.dat") == n400);
  const Result whole = run(flags.substr(1) + fresh.string());
  REQUIRE((whole.status == 0 || whole.status == 4 || whole.status == 5 || whole.status == 6));
  CHECK(rerun.status == whole.status);
  CHECK(without_out(out / "convergence.dat") == without_out(fresh / "convergence.dat"));
  // another command's run in a member's folder (allowed once the study has ended): the member
  // runs again, saying why, and the study's numbers are again its own
  REQUIRE(run("evolve --N 600 --grid uniform --rmax 50 --tmax 300 --ko-sigma 0.2 --force --out "
              + (out / "N600").string())
              .status
          == 0);
  const Result again = run(flags.substr(1) + out.string());
  INFO(again.err);
  CHECK(again.err.find("member N = 600 is run: its converge_completed.bin is not used (its output "
                       "files changed since it completed: another command wrote its folder)")
        != std::string::npos);
  CHECK(again.err.find("member N = 800 completed earlier") != std::string::npos);
  CHECK(without_out(out / "convergence.dat") == without_out(fresh / "convergence.dat"));
  fs::remove_all(out);
  fs::remove_all(fresh);
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

// --force replaces a run's files with new ones; it never writes into the old ones, so that their
// other names (a backup made with `cp -al` or `rsync --link-dest`) keep the earlier run; and the
// earlier run's checkpoint goes, so that `resume` does not offer a run the folder no longer holds.
TEST_CASE("--force leaves hard-linked copies of the earlier run as they were, and drops its "
          "checkpoint") {
  const fs::path out = scratch("forced_hardlinks"), backup = scratch("forced_hardlinks_backup");
  REQUIRE(
      run("evolve --id 1log-trumpet --N 80 --tmax 1 --checkpoint-every 0.5 --out " + out.string())
          .status
      == 0);
  REQUIRE(fs::exists(out / "checkpoint.bin"));
  fs::create_directories(backup);
  std::map<std::string, std::string> before;
  for (const auto& entry : fs::directory_iterator(out)) {
    const std::string name = entry.path().filename().string();
    fs::create_hard_link(entry.path(), backup / name);
    before[name] = slurp(entry.path());
  }
  const Result r =
      run("evolve --id 1log-trumpet --N 80 --tmax 0.5 --rahA 0.5 --force --out " + out.string());
  INFO(r.err);
  REQUIRE(r.status == 0);
  for (const auto& [name, text] : before) {
    CAPTURE(name);
    CHECK(slurp(backup / name) == text); // the backup: the earlier run, byte for byte
  }
  CHECK(slurp(out / "timeseries.dat") != before["timeseries.dat"]);
  CHECK(slurp(out / "config.toml").find("rahA = 0.5") != std::string::npos);
  CHECK_FALSE(fs::exists(out / "checkpoint.bin")); // the earlier run's checkpoint is gone
  const Result resumed = run("resume " + out.string());
  CHECK(resumed.status == 2);
  CHECK(resumed.err.find("has no checkpoint.bin") != std::string::npos);
  fs::remove_all(out);
  fs::remove_all(backup);
}

// A completed converge study rerun with the same inputs says what happens: each member keeps its
// records (converge_completed.bin) and says so; a member whose record is gone, with no
// checkpoint, runs again and says why.
TEST_CASE("converge rerun after completion: completed members keep their records, one without "
          "its record or a checkpoint says it runs again") {
  const fs::path out = scratch("converge_rerun_done");
  const std::string cmd = "converge --N 40,50,60 --id 1log-trumpet --grid uniform --rmax 20 "
                          "--tmax 1 --out "
                          + out.string();
  REQUIRE(run(cmd).status != 2);
  const std::string before = without_out(out / "convergence.dat");
  fs::remove(out / "N50" / "converge_completed.bin");
  const Result again = run(cmd);
  INFO(again.err);
  CHECK(again.status != 2);
  CHECK(again.err.find("a member without one runs again") != std::string::npos);
  CHECK(again.err.find("member N = 40 completed earlier") != std::string::npos);
  CHECK(again.err.find("member N = 60 completed earlier") != std::string::npos);
  CHECK(again.err.find("member N = 50 starts afresh: it has no checkpoint") != std::string::npos);
  CHECK(without_out(out / "convergence.dat") == before);
  fs::remove_all(out);
}

TEST_CASE(
    "sweep: a member folder that is a symbolic link is refused, naming it, and what it "
    "points at is left alone, and a member folder replaced by a run of other inputs is refused "
    "by its own config.toml, whatever its status file says") {
  const fs::path dir = scratch("sweep_member_link"), other = scratch("sweep_member_other");
  const std::string flags = "--id 1log-trumpet --grid uniform --rmax 20 --tmax 1 ";
  const std::string sweep =
      "sweep --progress-every 0 --sweep N=32,40 " + flags + "--out " + dir.string();
  REQUIRE(run(sweep).status == 0);
  REQUIRE(run("evolve --N 32 " + flags + "--out " + other.string()).status == 0);
  const std::string status = slurp(dir / "logs" / "N=32.status");
  auto snapshot = [](const fs::path& d) {
    std::map<std::string, std::string> all;
    for (const auto& e : fs::recursive_directory_iterator(d))
      if (e.is_regular_file())
        all[fs::relative(e.path(), d).string()] = slurp(e.path());
    return all;
  };
  const auto other_before = snapshot(other);
  fs::remove_all(dir / "N=32");
  fs::create_directory_symlink(other, dir / "N=32");
  fs::remove(dir / "logs" / "N=32.status");
  for (const char* extra : {"", " --member N=32", " --collect"}) {
    const Result r = run(sweep + extra);
    INFO(extra << ": " << r.err);
    CHECK(r.status == 2);
    CHECK(r.err.find("holds a symbolic link, N=32") != std::string::npos);
    CHECK(snapshot(other) == other_before);
    CHECK_FALSE(fs::exists(dir / "logs" / "N=32.status"));
  }
  // the folder replaced by a finished run of other inputs, its status kept
  fs::remove(dir / "N=32");
  REQUIRE(run("evolve --N 32 --cfl 0.25 " + flags + "--out " + (dir / "N=32").string()).status
          == 0);
  std::ofstream(dir / "logs" / "N=32.status") << status;
  const auto before = snapshot(dir);
  for (const char* extra : {"", " --member N=32", " --collect"}) {
    const Result r = run(sweep + extra);
    INFO(extra << ": " << r.err);
    CHECK(r.status == 2);
    CHECK(r.err.find("N=32 (cfl: 0.25 -> ") != std::string::npos);
    CHECK(r.err.find("in its folder's config.toml") != std::string::npos);
    CHECK(snapshot(dir) == before);
  }
  fs::remove_all(dir);
  fs::remove_all(other);
}

TEST_CASE("converge into a folder of the same study with another N list says so, and names the "
          "earlier members it leaves beside the new ones") {
  const fs::path out = scratch("converge_other_N");
  const std::string cmd = "converge --id 1log-trumpet --grid uniform --rmax 20 --tmax 1 --out "
                          + out.string() + " --N ";
  REQUIRE(run(cmd + "40,50,60").status != 2);
  const Result again = run(cmd + "40,50,70");
  INFO(again.err);
  CHECK(again.status != 2);
  CHECK(again.err.find("(same inputs but N: 40,50,70 where it ran N = 40,50,60)")
        != std::string::npos);
  CHECK(again.err.find("holds 1 member folder of an earlier study that this one (N = 40,50,70) "
                       "does not list (N60): left as it is")
        != std::string::npos);
  CHECK(fs::exists(out / "N70" / "config.toml"));
  // the same list again: nothing to say about N
  const Result same = run(cmd + "40,50,70");
  INFO(same.err);
  CHECK(same.err.find("(same inputs):") != std::string::npos);
  fs::remove_all(out);
}
