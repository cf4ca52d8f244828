// The hostile-input catalogue (tests/cli/hostile_inputs.txt): every row is one command line
// that a user could type, the exit status it must end with, and the text its stderr must hold
// (the flag it names). For every row the real executable runs in a scratch folder, with no
// shell in between, and must
//  - end within the row time limit (a hang fails),
//  - exit with the expected status and name the flag on stderr,
//  - create nothing at {out} when it refuses (exit != 0),
//  - leave the finished run {done} byte for byte as it was (nothing overwritten or cut).
#include "../test_support.hpp"

#include <doctest/doctest.h>

#include <chrono>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <map>
#include <spawn.h>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;

namespace {

using gbssn1d::testing::scratch;

using gbssn1d::testing::slurp;

using gbssn1d::testing::contents;

/// Shell-like words: white space separates, '...' quotes (may be empty: ''), \n in a quoted word
/// is a newline. No expansion of anything else.
std::vector<std::string> words(const std::string& line) {
  std::vector<std::string> out;
  std::string word;
  bool in_word = false, quoted = false;
  for (std::size_t k = 0; k < line.size(); ++k) {
    const char c = line[k];
    if (quoted) {
      if (c == '\'')
        quoted = false;
      else if (c == '\\' && k + 1 < line.size() && line[k + 1] == 'n') {
        word += '\n';
        ++k;
      } else
        word += c;
    } else if (c == '\'') {
      quoted = in_word = true;
    } else if (c == ' ' || c == '\t') {
      if (in_word)
        out.push_back(word);
      word.clear();
      in_word = false;
    } else {
      word += c;
      in_word = true;
    }
  }
  if (in_word)
    out.push_back(word);
  return out;
}

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (std::size_t pos = 0; (pos = s.find(from, pos)) != std::string::npos; pos += to.size())
    s.replace(pos, from.size(), to);
  return s;
}

struct Outcome {
  int status = -1;
  bool timed_out = false;
  std::string err;
};

/// Runs the executable with `args` in `cwd` (stdout to `out_file`), killed after `limit`.
Outcome run(const std::vector<std::string>& args, const fs::path& cwd, const fs::path& out_file,
            std::chrono::seconds limit) {
  const fs::path err_file = cwd / ".stderr";
  std::vector<std::string> all{GBSSN1D_EXECUTABLE};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all)
    argv.push_back(a.data());
  argv.push_back(nullptr);
  // posix_spawn, not fork: a sanitized test process's copy would cost more than the run
  posix_spawn_file_actions_t actions;
  posix_spawnattr_t attributes;
  ::posix_spawn_file_actions_init(&actions);
  ::posix_spawnattr_init(&attributes);
  ::posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP); // its own group (killed whole)
  ::posix_spawnattr_setpgroup(&attributes, 0);
  ::posix_spawn_file_actions_addchdir_np(&actions, cwd.c_str());
  ::posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  ::posix_spawn_file_actions_addopen(&actions, 1, out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
  ::posix_spawn_file_actions_addopen(&actions, 2, err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
  pid_t pid = -1;
  const int spawned = ::posix_spawn(&pid, argv[0], &actions, &attributes, argv.data(), environ);
  ::posix_spawn_file_actions_destroy(&actions);
  ::posix_spawnattr_destroy(&attributes);
  REQUIRE_MESSAGE(spawned == 0, "cannot start " << argv[0] << ": " << std::strerror(spawned));
  Outcome o;
  const auto deadline = std::chrono::steady_clock::now() + limit;
  int raw = 0;
  while (::waitpid(pid, &raw, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(-pid, SIGKILL);
      ::waitpid(pid, &raw, 0);
      o.timed_out = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  o.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  o.err = slurp(err_file);
  return o;
}

} // namespace

TEST_CASE("hostile inputs: each refused cleanly, naming its flag, nothing written or damaged") {
  const fs::path dir = scratch("hostile", true);
  const fs::path done = dir / "done";
  // a finished run that every row may aim at and none may damage (with a checkpoint)
  {
    const Outcome o = run({"evolve", "--N", "64", "--tmax", "1", "--dt-series", "0.25",
                           "--checkpoint-every", "0.5", "--out", done.string()},
                          dir, dir / ".stdout", std::chrono::seconds(60));
    REQUIRE(o.status == 0);
  }
  const auto done_before = contents(done);

  std::ifstream table(fs::path(GBSSN1D_SOURCE_DIR) / "tests/cli/hostile_inputs.txt");
  REQUIRE(table);
  int rows = 0;
  for (std::string line; std::getline(table, line);) {
    if (line.empty() || line[0] == '#')
      continue;
    if (line.rfind("@file ", 0) == 0) { // @file NAME 'content with \n'
      const auto w = words(line.substr(6));
      REQUIRE(w.size() == 2);
      std::ofstream(dir / w[0]) << w[1];
      continue;
    }
    if (line.rfind("@dir ", 0) == 0) { // @dir NAME: a folder in the place of NAME's file
      std::error_code none;            // (NAME need not exist)
      fs::remove(dir / line.substr(5), none);
      REQUIRE(fs::create_directory(dir / line.substr(5)));
      continue;
    }
    if (line.rfind("@fifo ", 0) == 0) { // @fifo NAME: a named pipe nobody writes to
      REQUIRE(::mkfifo((dir / line.substr(6)).c_str(), 0644) == 0);
      continue;
    }
    if (line.rfind("@symlink ", 0) == 0) { // @symlink NAME TARGET, in the place of NAME's file
      const auto w = words(line.substr(9));
      REQUIRE(w.size() == 2);
      std::error_code none; // (NAME need not exist)
      fs::remove(dir / w[0], none);
      fs::create_symlink(w[1], dir / w[0]);
      continue;
    }
    const auto bar1 = line.find(" | "), bar2 = line.find(" | ", bar1 + 3);
    REQUIRE_MESSAGE(bar2 != std::string::npos, "malformed row: " << line);
    const int expected = std::stoi(line.substr(0, bar1));
    const std::string flag = line.substr(bar1 + 3, bar2 - bar1 - 3);
    const fs::path out = dir / ("out" + std::to_string(rows));
    std::string args_text = line.substr(bar2 + 3);
    args_text = replace_all(args_text, "{out}", out.string());
    args_text = replace_all(args_text, "{done}", done.string());
    args_text = replace_all(args_text, "{dir}", dir.string());
    // a name over the system's 255 bytes, and a path over its 4095 (of 100-byte names)
    args_text = replace_all(args_text, "{name300}", std::string(300, 'n'));
    std::string long_path;
    for (int k = 0; k < 50; ++k)
      long_path += std::string(100, 'p') + "/";
    args_text = replace_all(args_text, "{path5000}", long_path + "x");
    std::vector<std::string> args;
    fs::path stdout_file = dir / ".stdout";
    for (const auto& w : words(args_text)) {
      if (w.size() > 1 && w[0] == '>')
        stdout_file = w.substr(1);
      else
        args.push_back(w);
    }
    ++rows;
    const Outcome o = run(args, dir, stdout_file, std::chrono::seconds(20));
    INFO("row: " << line << "\nexit " << o.status << ", stderr: " << o.err);
    CHECK_FALSE(o.timed_out);
    CHECK(o.status == expected);
    CHECK(o.err.find(flag) != std::string::npos);
    if (expected != 0)
      CHECK_FALSE(fs::exists(out));
    for (const char* internal : {"std::", "filesystem error", "terminate called", "what()"})
      CHECK(o.err.find(internal) == std::string::npos); // no leaked internals
    CHECK(contents(done) == done_before);
  }
  MESSAGE(rows << " hostile inputs");
  CHECK(rows >= 100);
  fs::remove_all(dir);
}
