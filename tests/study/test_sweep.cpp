// `sweep` as users run it: failing members, cluster task lines, reruns, signals, progress,
// same runs and spikes; --config passed on by sweep and converge alike.
#include "../cli/cli_support.hpp"
#include "config/config_file.hpp"
#include "config/params.hpp"
#include "io/output.hpp"
#include "io/table.hpp"
#include "study/converge.hpp"
#include "study_support.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;

namespace {

using gbssn1d::testing::completed;
using gbssn1d::testing::run_signalled;
using gbssn1d::testing::run_study;
using gbssn1d::testing::scratch;
using gbssn1d::testing::slurp;
using gbssn1d::testing::summary_rows;

} // namespace

TEST_CASE("sweep: failing members are marked, the others finish, a rerun resumes") {
  const fs::path out = scratch("sweep");
  const std::string sweep =
      "sweep -j 2 --out " + out.string()
      + " --sweep rah-variant=consistent,delta-rhs-from-gd --sweep cfl=0.25,7"
        " --id maximal-trumpet --grid uniform --N 100 --rmax 20 --tmax 30 --dt-series 1"
        " --rahA 0.5 --rah0 0.6";
  std::string err;
  // members that did not complete make the sweep's exit status 3, and it says how many
  REQUIRE(run_study(sweep, &err) == 3);
  CHECK(err.find("members did not complete") != std::string::npos);
  const auto rows = summary_rows(out / "summary.dat");
  REQUIRE(rows.size() == 4);
  CHECK(rows[0].find("consistent 0.25 ok") == 0);
  CHECK(rows[1].find("consistent 7 invalid") == 0);
  CHECK(rows[1].find("--cfl") != std::string::npos);
  CHECK(rows[2].find("delta-rhs-from-gd 0.25 blew-up") == 0);
  CHECK(rows[2].find("non-finite") != std::string::npos);
  CHECK(fs::exists(out / "rah-variant=consistent_cfl=0.25" / "timeseries.dat"));
  { // the summary's figures are those of the member's timeseries.dat
    const auto summary = gbssn1d::read_table(out / "summary.dat");
    const auto series =
        gbssn1d::read_table(out / "rah-variant=consistent_cfl=0.25" / "timeseries.dat");
    double err_max = 0, H_R_max = 0;
    for (const auto& row : series.rows) {
      err_max = std::max(err_max, std::abs(row[*series.column("M_ah_err")]));
      H_R_max = std::max(H_R_max, row[*series.column("H_L2_R")]);
    }
    const auto& first = summary.rows.front();
    CHECK(first[*summary.column("t_end")] == 30.0);
    CHECK(first[*summary.column("M_ah_err_max")] == doctest::Approx(err_max).epsilon(1e-6));
    CHECK(first[*summary.column("H_L2_R_max")] == doctest::Approx(H_R_max).epsilon(1e-6));
    CHECK(err_max > 0.0);
  }

  // a second run skips finished members
  const auto stamp =
      fs::last_write_time(out / "rah-variant=consistent_cfl=0.25" / "timeseries.dat");
  REQUIRE(run_study(sweep, &err) == 3);
  CHECK(err.find("consistent_cfl=0.25 ok") == std::string::npos); // nothing reran
  CHECK(fs::last_write_time(out / "rah-variant=consistent_cfl=0.25" / "timeseries.dat") == stamp);
  // an unfinished member (no status) is rerun
  fs::remove(out / "logs" / "rah-variant=consistent_cfl=0.25.status");
  // ... and so is one whose status file is empty (a write cut short)
  std::ofstream(out / "logs" / "rah-variant=delta-rhs-from-gd_cfl=0.25.status").flush();
  REQUIRE(run_study(sweep, &err) == 3);
  CHECK(err.find("rah-variant=delta-rhs-from-gd_cfl=0.25 blew-up") != std::string::npos);
  CHECK(err.find("rah-variant=consistent_cfl=0.25 ok") != std::string::npos);

  // -j means nothing for task lines (the scheduler runs them) and is refused
  const fs::path tasks = scratch("tasks.txt");
  CHECK(run_study(sweep + " --emit-tasks " + tasks.string(), &err) == 2);
  CHECK(err.find("-j") != std::string::npos);
  CHECK_FALSE(fs::exists(tasks));
  fs::remove_all(out);
}

namespace {

/// The summary rows without the wall_s column (the one column two runs of a sweep may differ
/// in), the sweep's folder `out` in the reasons replaced by OUT.
std::vector<std::string> without_wall(const fs::path& summary, const fs::path& out) {
  std::vector<std::string> header;
  {
    std::ifstream in(summary);
    for (std::string line; std::getline(in, line);)
      if (line.rfind("# ", 0) == 0 && line.find(" status ") != std::string::npos) {
        std::istringstream words(line.substr(2));
        for (std::string w; words >> w;)
          header.push_back(w);
      }
  }
  const auto wall = std::find(header.begin(), header.end(), "wall_s") - header.begin();
  std::vector<std::string> rows;
  for (const auto& row : summary_rows(summary)) {
    std::istringstream words(row);
    std::string text, w;
    for (std::ptrdiff_t k = 0; words >> w; ++k)
      if (k != wall)
        text += w + " ";
    for (auto at = text.find(out.string()); at != std::string::npos; at = text.find(out.string()))
      text.replace(at, out.string().size(), "OUT");
    rows.push_back(text);
  }
  return rows;
}

/// Runs each line of `tasks` with a plain shell started in `folder`; their exit statuses.
std::vector<int> run_lines(const fs::path& tasks, const fs::path& folder) {
  std::ifstream in(tasks);
  std::vector<int> status;
  for (std::string line; std::getline(in, line);) {
    const fs::path script = scratch("task.sh");
    std::ofstream(script) << line << "\n";
    const std::string cmd =
        "cd " + folder.string() + " && sh " + script.string() + " >/dev/null 2>&1";
    const int raw = std::system(cmd.c_str());
    status.push_back(WIFEXITED(raw) ? WEXITSTATUS(raw) : -1);
    fs::remove(script);
  }
  return status;
}

} // namespace

TEST_CASE("sweep on a cluster: emitted lines run from any folder, resume, --collect summarises") {
  // a 2 x 2 sweep with one member that blows up and one that is invalid (cfl 7)
  // (the member that finishes runs for about 2 s, long enough to be stopped by a signal)
  const std::string flags = " --sweep rah-variant=consistent,delta-rhs-from-gd --sweep cfl=0.25,7"
                            " --id maximal-trumpet --grid uniform --N 100 --rmax 20 --tmax 1500"
                            " --dt-series 1 --dt-profiles 500 --rahA 0.5 --rah0 0.6"
                            " --checkpoint-every 5";
  const fs::path direct = scratch("sweep_direct"), queued = scratch("sweep_queued");
  REQUIRE(run_study("sweep -j 2 --out " + direct.string() + flags) == 3);
  // the lines, emitted from the scratch folder with a relative --out
  const fs::path tasks = scratch("sweep_tasks.txt");
  const std::string rel = fs::relative(queued, queued.parent_path()).string();
  const std::string in_scratch = "cd " + queued.parent_path().string() + " && ";
  {
    const std::string cmd = in_scratch + GBSSN1D_EXECUTABLE + " sweep --out " + rel + flags
                            + " --emit-tasks " + tasks.string() + " >/dev/null 2>&1";
    REQUIRE(std::system(cmd.c_str()) == 0);
  }
  // before any line ran, --collect reports the members as missing (exit 1) and runs nothing
  CHECK(run_study("sweep --out " + queued.string() + flags + " --collect") == 1);
  CHECK_FALSE(fs::exists(queued / "rah-variant=consistent_cfl=0.25"));
  // only the 2 valid members are emitted; each line runs from another folder (/)
  const auto status = run_lines(tasks, "/");
  REQUIRE(status.size() == 2);
  CHECK(status[0] == 0); // consistent: finished
  CHECK(status[1] == 3); // delta-rhs-from-gd: blew up
  CHECK(fs::exists(queued / "logs" / "rah-variant=consistent_cfl=0.25.log"));
  CHECK(fs::exists(queued / "logs" / "rah-variant=consistent_cfl=0.25.status"));
  // --collect gives the direct sweep's summary (wall time aside), the invalid member marked
  std::string err;
  CHECK(run_study("sweep --out " + queued.string() + flags + " --collect", &err) == 3);
  CHECK(err.find("1 blew-up") != std::string::npos);
  CHECK(err.find("2 invalid") != std::string::npos);
  const auto a = without_wall(direct / "summary.dat", direct),
             b = without_wall(queued / "summary.dat", queued);
  REQUIRE(a.size() == 4);
  CHECK(a == b);
  // a requeued line of a finished member does not run it again
  const fs::path series = queued / "rah-variant=consistent_cfl=0.25" / "timeseries.dat";
  const auto stamp = fs::last_write_time(series);
  CHECK(run_lines(tasks, "/").front() == 0);
  CHECK(fs::last_write_time(series) == stamp);
  // a member stopped by the scheduler (SIGTERM to the task's process group, as on preemption
  // or a time limit) is marked interrupted; its line, requeued, resumes from the checkpoint
  // and ends with the same results
  fs::remove_all(queued / "rah-variant=consistent_cfl=0.25");
  fs::remove(queued / "logs" / "rah-variant=consistent_cfl=0.25.status");
  {
    std::ifstream in(tasks);
    std::string line;
    std::getline(in, line);
    const fs::path script = scratch("task_bg.sh"), pid = scratch("task_bg.pid");
    std::ofstream(script) << line << "\n";
    // in its own session, whose id is its pid: the process group a scheduler signals
    const std::string start = "cd / && setsid sh -c 'echo $$ > " + pid.string() + "; exec sh "
                              + script.string() + "' >/dev/null 2>&1 &";
    REQUIRE(std::system(start.c_str()) == 0);
    auto pid_written = [&] { return fs::exists(pid) && fs::file_size(pid) > 0; };
    for (int k = 0; k < 1000 && !pid_written(); ++k)
      ::usleep(10000);
    REQUIRE(pid_written());
    const fs::path checkpoint = queued / "rah-variant=consistent_cfl=0.25" / "checkpoint.bin";
    for (int k = 0; k < 1000 && !fs::exists(checkpoint); ++k)
      ::usleep(10000);
    REQUIRE(fs::exists(checkpoint));
    pid_t group = 0;
    std::ifstream(pid) >> group;
    REQUIRE(group > 1);
    REQUIRE(::kill(-group, SIGTERM) == 0);
    const fs::path status_file = queued / "logs" / "rah-variant=consistent_cfl=0.25.status";
    for (int k = 0; k < 1000 && !fs::exists(status_file); ++k)
      ::usleep(10000);
    std::ifstream st(status_file);
    std::string status;
    st >> status;
    CHECK(status == "interrupted");
    fs::remove(script);
    fs::remove(pid);
  }
  CHECK(run_lines(tasks, "/").front() == 0);
  {
    std::ifstream log(queued / "logs" / "rah-variant=consistent_cfl=0.25.log");
    std::stringstream text;
    text << log.rdbuf();
    CHECK(text.str().find("resuming") != std::string::npos);
  }
  CHECK(run_study("sweep --out " + queued.string() + flags + " --collect") == 3);
  CHECK(without_wall(queued / "summary.dat", queued) == a);
  // a member line of other flags than the folder's members were run with is refused
  CHECK(run_study("sweep --out " + queued.string() + flags
                      + " --ko-sigma 0.2 --member "
                        "rah-variant=consistent_cfl=0.25",
                  &err)
        == 2);
  CHECK(err.find("other inputs") != std::string::npos);
  CHECK(run_study("sweep --out " + queued.string() + flags + " --member nobody", &err) == 2);
  CHECK(err.find("--member") != std::string::npos);
  fs::remove(tasks);
  fs::remove_all(direct);
  fs::remove_all(queued);
}

TEST_CASE("sweep refuses a --sweep that names no flag") {
  std::string err;
  CHECK(run_study("sweep --out " + scratch("sweep_bad").string() + " --sweep rahAA=1,2", &err)
        == 2);
  CHECK(err.find("--sweep") != std::string::npos);
  CHECK(run_study("sweep --out " + scratch("sweep_bad").string() + " --sweep rahA", &err) == 2);
}

TEST_CASE("sweep: an invalid member before a valid one is marked invalid and the valid one runs, "
          "a sweep of invalid members only is refused") {
  const fs::path out = scratch("sweep_invalid_first");
  fs::remove_all(out);
  const std::string flags =
      " --id 1log-trumpet --grid uniform --N 32 --rmax 8 --tmax 0.5 --out " + out.string();
  std::string err;
  // cfl 7 is refused by every member with it; 0.25 runs
  CHECK(run_study("sweep --sweep cfl=7,0.25" + flags, &err) == 3);
  INFO(err);
  CHECK(err.find("1 invalid") != std::string::npos);
  CHECK(fs::exists(out / "cfl=0.25" / "timeseries.dat"));
  CHECK_FALSE(fs::exists(out / "cfl=7" / "timeseries.dat"));
  fs::remove_all(out);
  CHECK(run_study("sweep --sweep cfl=7,8" + flags, &err) == 2);
  CHECK(err.find("no member is valid") != std::string::npos);
  CHECK_FALSE(fs::exists(out / "summary.dat"));
  fs::remove_all(out);
}

TEST_CASE("sweep: flags tied on one axis, crossed with resolutions, give fitted orders") {
  const fs::path out = scratch("sweep_tied");
  REQUIRE(run_study("sweep -j 2 --out " + out.string()
                    + " --sweep N=200,400 --sweep rahA,rah0=0:0.89,0.5:0.7 --id 1log-trumpet"
                      " --grid sinh --dr-inner 0.04 --rmax 60 --tmax 3")
          == 0);
  const auto rows = summary_rows(out / "summary.dat");
  REQUIRE(rows.size() == 4);
  CHECK(rows[0].find("200 0 0.89 ok") == 0);
  CHECK(rows[3].find("400 0.5 0.7 ok") == 0);
  CHECK(fs::exists(out / "N=200_rahA=0.5_rah0=0.7" / "horizon.dat"));
  // the fitted order of the final H over N = 200, 400 is near 4 for both rahA
  for (const auto& row : rows) {
    std::istringstream words(row);
    std::vector<std::string> w;
    for (std::string x; words >> x;)
      w.push_back(x);
    const double order = std::stod(w[w.size() - 2]);
    INFO(row);
    CHECK(order == doctest::Approx(4.0).epsilon(0.15));
  }
  std::string err;
  CHECK(run_study("sweep --out " + out.string() + " --sweep rahA,rah0=0:0.89,0.5", &err) == 2);
  CHECK(err.find("joined by ':'") != std::string::npos);
  // the member folders are named in the axes' order: --collect with the axes in another order
  // is refused, naming the order, and summary.dat stays as it was
  const std::string summary = slurp(out / "summary.dat");
  CHECK(run_study("sweep --out " + out.string()
                      + " --sweep rahA,rah0=0:0.89,0.5:0.7 --sweep N=200,400 --id 1log-trumpet"
                        " --grid sinh --dr-inner 0.04 --rmax 60 --tmax 3 --collect",
                  &err)
        == 2);
  CHECK(err.find("in another order: give them as it did, N then rahA,rah0") != std::string::npos);
  CHECK(slurp(out / "summary.dat") == summary);
  fs::remove_all(out);
}

TEST_CASE("sweep: SIGTERM reaches the running members, which stop with a checkpoint") {
  const fs::path out = scratch("sweep_sigterm");
  const int raw = run_signalled(
      "sweep -j 2 --out " + out.string()
          + " --sweep N=3200,3300,3400 --id 1log-trumpet --grid uniform"
            " --rmax 200 --tmax 2000 --dt-profiles 100",
      {.files = {out / "N=3300" / "horizon.dat"}, .signal = "TERM", .poll = 0.1, .settle = 0.5});
  REQUIRE(WIFEXITED(raw));
  CHECK(WEXITSTATUS(raw) == 143);
  const auto rows = summary_rows(out / "summary.dat");
  REQUIRE(rows.size() == 3);
  for (int k = 0; k < 2; ++k) { // the two running members
    INFO(rows[static_cast<std::size_t>(k)]);
    CHECK(rows[static_cast<std::size_t>(k)].find("interrupted") != std::string::npos);
  }
  CHECK(rows[2].find("missing") != std::string::npos); // never started
  for (const char* member : {"N=3200", "N=3300"}) {
    CHECK(fs::exists(out / member / "checkpoint.bin"));
    std::ifstream in(out / member / "timeseries.dat");
    std::string line, last;
    while (std::getline(in, line))
      last = line;
    CHECK(last.find("# end: stopped: interrupted by SIGTERM") == 0);
  }
  fs::remove_all(out);
}

TEST_CASE("sweep and converge pass --config on: members' own flags override the file once") {
  const fs::path cfg = scratch("study.toml"), sweep_out = scratch("cfg_sweep"),
                 conv_out = scratch("cfg_conv");
  std::ofstream(cfg) << "id = \"1log-trumpet\"\ngrid = \"uniform\"\nN = 120\nrmax = 20\ntmax = 1\n";
  std::string err;
  REQUIRE(run_study("sweep --out " + sweep_out.string() + " --config " + cfg.string()
                        + " --sweep N=100,140",
                    &err)
          == 0);
  const auto rows = summary_rows(sweep_out / "summary.dat");
  REQUIRE(rows.size() == 2);
  CHECK(rows[0].find("100 ok") == 0);
  CHECK(rows[1].find("140 ok") == 0);
  std::ifstream member_cfg(sweep_out / "N=140" / "config.toml");
  const std::string text((std::istreambuf_iterator<char>(member_cfg)), {});
  CHECK(text.find("\nN = 140\n") != std::string::npos);
  CHECK(text.find("id = \"1log-trumpet\"") != std::string::npos);
  REQUIRE(completed(run_study(
      "converge --N 100,140,180 --out " + conv_out.string() + " --config " + cfg.string(), &err)));
  CHECK(fs::exists(conv_out / "N180" / "timeseries.dat"));
  fs::remove_all(sweep_out);
  fs::remove_all(conv_out);
  fs::remove(cfg);
}

TEST_CASE("sweep: progress lines while members run, k of n as they finish, resumed counts") {
  const fs::path out = scratch("sweep_progress");
  const std::string members =
      " --sweep N=1600,2000 --id 1log-trumpet --grid uniform --rmax 100 --tmax 30";
  std::string err;
  // each member takes about 0.6 s here, so a line every 0.1 s shows them running
  REQUIRE(run_study("sweep -j 2 --progress-every 0.1 --out " + out.string() + members, &err) == 0);
  INFO(err);
  CHECK(err.find("gbssn1d sweep: 0 of 2 members done, 2 running (longest: N=")
        != std::string::npos);
  CHECK(err.find("] N=1600 ok") != std::string::npos);
  CHECK(err.find("[2/2]") != std::string::npos);
  // --progress-every 0: no progress lines; a rerun has nothing left to run
  REQUIRE(run_study("sweep -j 2 --progress-every 0 --out " + out.string() + members, &err) == 0);
  CHECK(err.find("members done") == std::string::npos);
  CHECK(err.find("[") == std::string::npos);
  CHECK(run_study("sweep --progress-every -1 --out " + out.string() + members, &err) == 2);
  CHECK(err.find("--progress-every = -1 is invalid") != std::string::npos);
  fs::remove_all(out);
}

// -j is the number of members run at once: with -j 3 every member starts before the first one
// ends; with -j 1 each starts only after the one before it has ended.

TEST_CASE("sweep: members that are the same run (rahA = 0, other rah0) are said to be") {
  const fs::path out = scratch("sweep_same");
  std::string err;
  REQUIRE(
      run_study("sweep -j 2 --out " + out.string()
                    + " --sweep rahA=0,0.5 --sweep rah0=0.6,1.2 --id 1log-trumpet --grid uniform"
                      " --N 60 --rmax 20 --tmax 1",
                &err)
      == 0);
  CHECK(err.find("rahA=0_rah0=0.6 = rahA=0_rah0=1.2 are the same run (rah0 does nothing there)")
        != std::string::npos);
  CHECK(err.find("rahA=0.5_rah0=0.6 =") == std::string::npos); // those two differ
  std::ifstream in(out / "summary.dat");
  std::stringstream text;
  text << in.rdbuf();
  CHECK(text.str().find("# rahA=0_rah0=0.6 = rahA=0_rah0=1.2 are the same run (rah0 does nothing "
                        "there)")
        != std::string::npos);
  // and each member's own log warns that its --rah0 does nothing
  std::ifstream log(out / "logs" / "rahA=0_rah0=0.6.log");
  std::stringstream log_text;
  log_text << log.rdbuf();
  CHECK(log_text.str().find("--rah0 0.6 does nothing with --rahA 0") != std::string::npos);
  fs::remove_all(out);
}

TEST_CASE("sweep: a member whose constraints spike far above its neighbours' is flagged, alone") {
  // B driven without the second derivatives of beta_H: H about 3000 times the others'
  const fs::path out = scratch("sweep_spike");
  std::string err;
  REQUIRE(run_study(
              "sweep -j 2 --out " + out.string()
                  + " --sweep rah-variant=consistent,no-shift-second-derivatives,driver-full-shift"
                    " --id maximal-trumpet --grid uniform --N 100 --rmax 20 --tmax 10"
                    " --dt-series 1 --rahA 0.5 --rah0 0.6",
              &err)
          == 0);
  INFO(err);
  CHECK(err.find("gbssn1d sweep: spike: rah-variant=no-shift-second-derivatives has max H_L2_R")
        != std::string::npos);
  CHECK(err.find("spike: rah-variant=consistent") == std::string::npos);
  CHECK(err.find("spike: rah-variant=driver-full-shift") == std::string::npos);
  const auto rows = summary_rows(out / "summary.dat");
  REQUIRE(rows.size() == 3);
  CHECK(rows[0].find("consistent ok - ") == 0);
  CHECK(rows[1].find("no-shift-second-derivatives ok spike ") == 0);
  CHECK(rows[1].find("along_rah-variant") != std::string::npos);
  CHECK(rows[2].find("driver-full-shift ok - ") == 0);
  // the flag column is read by name, as the plot scripts read it
  const auto summary = gbssn1d::read_table(out / "summary.dat");
  CHECK(summary.column("flag") == *summary.column("status") + 1);
  // each member's warnings reach the terminal once, naming the members that gave them
  CHECK(err.find("gbssn1d sweep: warning from 3 member(s) (rah-variant=consistent, "
                 "rah-variant=no-shift-second-derivatives, rah-variant=driver-full-shift): "
                 "--tmax 10 lets the outer boundary")
        != std::string::npos);
  const auto first = err.find("lets the outer boundary");
  CHECK(err.find("lets the outer boundary", first + 1) == std::string::npos);
  fs::remove_all(out);
}

namespace {

/// The pid of a running `gbssn1d evolve` whose command line holds `text`, or 0.
pid_t evolve_process_with(const std::string& text) {
  for (const auto& e : fs::directory_iterator("/proc")) {
    const std::string name = e.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos)
      continue;
    std::string cmdline = slurp(e.path() / "cmdline");
    std::replace(cmdline.begin(), cmdline.end(), '\0', ' ');
    if (cmdline.find(" evolve ") != std::string::npos && cmdline.find(text) != std::string::npos)
      return static_cast<pid_t>(std::stol(name));
  }
  return 0;
}

std::string recorded_status(const fs::path& status_file) {
  std::ifstream in(status_file);
  std::string status;
  in >> status;
  return status;
}

} // namespace

TEST_CASE("sweep: a failed or killed member runs again from its checkpoint, a blown-up one does "
          "not, and one process at a time runs a member") {
  // one member runs for a few seconds with checkpoints, the other blows up
  const std::string flags = " --sweep rah-variant=consistent,delta-rhs-from-gd"
                            " --id maximal-trumpet --grid uniform --N 100 --rmax 20 --tmax 1500"
                            " --dt-series 1 --dt-profiles 500 --rahA 0.5 --rah0 0.6"
                            " --checkpoint-every 5";
  const fs::path out = scratch("sweep_killed");
  const std::string good = "rah-variant=consistent", bad = "rah-variant=delta-rhs-from-gd";
  // the sweep in the background; its good member's evolve is killed on its own (SIGKILL, as
  // the kernel's out-of-memory killer does) once it has written a checkpoint
  const fs::path done_flag = scratch("sweep_killed_rc");
  const std::string cmd = "(" + std::string(GBSSN1D_EXECUTABLE) + " sweep -j 2 --out "
                          + out.string() + flags + " >/dev/null 2>&1; echo $? > "
                          + done_flag.string() + ") &";
  REQUIRE(std::system(cmd.c_str()) == 0);
  const fs::path checkpoint = out / good / "checkpoint.bin";
  for (int k = 0; k < 2000 && !fs::exists(checkpoint); ++k)
    ::usleep(10000);
  REQUIRE(fs::exists(checkpoint));
  const pid_t child = evolve_process_with((out / good).string());
  REQUIRE(child > 0);
  REQUIRE(::kill(child, SIGKILL) == 0);
  for (int k = 0; k < 3000 && !(fs::exists(done_flag) && fs::file_size(done_flag) > 0); ++k)
    ::usleep(10000);
  REQUIRE(fs::exists(done_flag));
  CHECK(slurp(done_flag) == "3\n"); // a member failed
  CHECK(recorded_status(out / "logs" / (good + ".status")) == "failed");
  CHECK(slurp(out / "logs" / (good + ".status")).find("killed_by") != std::string::npos);
  CHECK(recorded_status(out / "logs" / (bad + ".status")) == "blew-up");
  double wall_before = 0.0;
  {
    std::ifstream in(out / "logs" / (good + ".status"));
    std::string status;
    in >> status >> wall_before;
  }
  const auto bad_stamp = fs::last_write_time(out / bad / "timeseries.dat");

  // while a process holds a member's lock, its line is refused and runs nothing
  {
    const fs::path lock = out / "logs" / (good + ".lock");
    const int fd = ::open(lock.c_str(), O_WRONLY | O_CREAT, 0644);
    REQUIRE(fd >= 0);
    REQUIRE(::flock(fd, LOCK_EX | LOCK_NB) == 0);
    std::string err;
    CHECK(run_study("sweep --out " + out.string() + flags + " --member " + good, &err) == 2);
    CHECK(err.find("another process runs this member") != std::string::npos);
    CHECK(recorded_status(out / "logs" / (good + ".status")) == "failed");
    ::close(fd);
  }

  // the rerun runs the failed member again, resuming from its checkpoint, and leaves the
  // blown-up one alone (rerunning it would blow up again)
  CHECK(run_study("sweep -j 2 --out " + out.string() + flags) == 3);
  CHECK(recorded_status(out / "logs" / (good + ".status")) == "ok");
  CHECK(slurp(out / "logs" / (good + ".log")).find("resuming") != std::string::npos);
  CHECK(fs::last_write_time(out / bad / "timeseries.dat") == bad_stamp);
  double wall_after = 0.0;
  {
    std::ifstream in(out / "logs" / (good + ".status"));
    std::string status;
    in >> status >> wall_after;
  }
  CHECK(wall_after > wall_before); // the member's total over both attempts
  // the finished member is not run a third time
  const auto good_stamp = fs::last_write_time(out / good / "timeseries.dat");
  CHECK(run_study("sweep -j 2 --out " + out.string() + flags) == 3);
  CHECK(fs::last_write_time(out / good / "timeseries.dat") == good_stamp);
  fs::remove(done_flag);
  fs::remove_all(out);
}

// A sweep rerun into its folder with other values lists only its own members in summary.dat;
// the earlier sweep's members it does not list are named on stderr and left as they are.
TEST_CASE("sweep: a rerun with other values names the earlier members it leaves out") {
  const fs::path out = scratch("sweep_other_values");
  fs::remove_all(out);
  const std::string flags =
      " --id 1log-trumpet --grid uniform --N 32 --rmax 8 --tmax 0.5 --out " + out.string();
  std::string err;
  REQUIRE(run_study("sweep --sweep rahA=0.25,0.5" + flags, &err) == 0);
  const std::string kept = slurp(out / "rahA=0.25" / "timeseries.dat");
  CHECK(run_study("sweep --sweep rahA=0.5,1" + flags, &err) == 0);
  INFO(err);
  CHECK(err.find("holds 1 member folder of an earlier sweep that this one does not list "
                 "(rahA=0.25): left as they are, and not in summary.dat")
        != std::string::npos);
  CHECK(slurp(out / "rahA=0.25" / "timeseries.dat") == kept);
  // no row of summary.dat is the left-out member (its first column is rahA; other columns,
  // such as the wall time, may print 0.25 by chance)
  {
    std::istringstream rows(slurp(out / "summary.dat"));
    std::vector<std::string> members;
    for (std::string line; std::getline(rows, line);) {
      if (line.empty() || line[0] == '#')
        continue;
      members.push_back(line.substr(0, line.find(' ')));
    }
    CHECK(members == std::vector<std::string>{"0.5", "1"});
  }
  // the same values again: nothing to say
  CHECK(run_study("sweep --sweep rahA=0.25,0.5,1" + flags, &err) == 0);
  CHECK(err.find("does not list") == std::string::npos);
  fs::remove_all(out);
}
