#include "cli/cli.hpp"

#include "core/text.hpp"

#include "cli/command_flags.hpp"
#include "cli/command_rules.hpp"

#include "config/config_file.hpp"
#include "config/params.hpp"
#include "core/console.hpp"
#include "core/registry.hpp"
#include "core/stop_signal.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <variant>

namespace gbssn1d {

namespace {

/// --help or --version printed by CLI11 to standard output, whose failure (a full disk, a closed
/// pipe) is an error, not a success.
int help_or_version(CLI::App& app, const CLI::Error& e) {
  const int status = app.exit(e);
  std::cout.flush();
  if (!std::cout) {
    say("gbssn1d: error: cannot write to standard output\n");
    return 1;
  }
  return status;
}

/// The process made safe before anything is opened or parsed.
void prepare_process(int argc, char** argv) {
  // Standard streams closed by the caller (`2>&-`) are reopened on /dev/null before anything
  // is opened: otherwise the first file opened takes descriptor 0, 1 or 2, and console
  // messages would land inside it (timeseries.dat).
  for (int fd = 0; fd <= 2; ++fd)
    if (::fcntl(fd, F_GETFD) == -1 && errno == EBADF)
      (void)::open("/dev/null", fd == 0 ? O_RDONLY : O_WRONLY); // takes the lowest free: fd
  // A file-size limit then fails the write (EFBIG, reported by the checked flush) instead of
  // killing the process.
  std::signal(SIGXFSZ, SIG_IGN);
  // A closed pipe or terminal gives EPIPE on a write instead of killing the process: console
  // messages are best effort (core/console.hpp), files report their write errors.
  std::signal(SIGPIPE, SIG_IGN);
  // A stop signal is a request from the first instant: before any file is created (a run
  // killed in its first milliseconds left a folder holding only config.toml.tmp).
  install_stop_handlers();
  if (argc > 0 && argv[0] != nullptr && std::string(argv[0]).find('/') != std::string::npos)
    invoked_as() = argv[0];
}

/// The flags whose values came from an evolve --config file, and that file: a refused value
/// then says where it was given, since the user typed no such flag.
struct ConfigOrigins {
  std::map<std::string, std::string> file_of;
  std::string note(const std::string& flag) const {
    const auto it = file_of.find(flag);
    return it == file_of.end() ? std::string()
                               : fmt::format(" (given as '{}' in --config {})", flag.substr(2),
                                             printable(it->second));
  }
  /// The note for the flag CLI11 names in its message `what`.
  std::string note_in(const std::string& what) const {
    for (const auto& [flag, file] : file_of) {
      const auto at = what.find(flag);
      const auto after = at == std::string::npos ? 0 : at + flag.size();
      if (at != std::string::npos
          && (after == what.size()
              || !(std::isalnum(static_cast<unsigned char>(what[after])) || what[after] == '-')))
        return note(flag);
    }
    return std::string();
  }
};

/// Edit distance (Levenshtein) of two flag names.
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j)
    row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

/// What CLI11 could not place, in the order typed (its own message lists them reversed): the
/// first unknown flag, with the command's flags closest to it, or a stray word; a flag before
/// the subcommand is told to come after it.
std::string unexpected_arguments(const CLI::App& app) {
  std::vector<std::string> rest = app.remaining(true);
  std::reverse(rest.begin(), rest.end()); // (CLI11 parsed the reversed vector)
  const auto subcommands = app.get_subcommands();
  const CLI::App* command = subcommands.empty() ? nullptr : subcommands.front();
  const std::string where =
      command ? fmt::format("gbssn1d {}", command->get_name()) : std::string("gbssn1d");
  const auto flag = std::find_if(rest.begin(), rest.end(),
                                 [](const std::string& w) { return w.rfind("--", 0) == 0; });
  if (flag == rest.end())
    return fmt::format("{} does not take '{}' (an argument without a flag; see {} --help)", where,
                       printable(rest.empty() ? std::string() : rest.front()), where);
  const std::vector<std::string> before = app.remaining(false); // not the subcommand's
  if (!command || std::find(before.begin(), before.end(), *flag) != before.end())
    return fmt::format("{} before the subcommand: flags follow it (gbssn1d {} {} ...)",
                       printable(*flag), command ? command->get_name() : "evolve",
                       printable(*flag));
  const std::string name = flag->substr(0, flag->find('='));
  // the command's flags within two edits, closest first, at most three
  std::vector<std::pair<std::size_t, std::string>> near;
  for (const CLI::Option* o : command->get_options())
    for (const std::string& known : o->get_lnames())
      if (const std::size_t d = edit_distance(name.substr(2), known); d <= 2)
        near.emplace_back(d, "--" + known);
  std::stable_sort(near.begin(), near.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> close;
  for (std::size_t k = 0; k < near.size() && k < 3; ++k)
    close.push_back(near[k].second);
  return fmt::format("{} is not a flag of {}{} (see {} --help)", printable(name), where,
                     close.empty() ? std::string()
                                   : fmt::format("; did you mean {}?", fmt::join(close, " or ")),
                     where);
}

int run_command_line(int argc, char** argv) {
  prepare_process(argc, argv);
  CLI::App app{"gbssn1d: spherically symmetric generalized BSSN evolutions of a Schwarzschild "
               "black hole",
               "gbssn1d"};
  app.set_version_flag("--version", std::string("gbssn1d ") + GBSSN1D_VERSION);
  app.footer("Each subcommand's own page lists its flags: gbssn1d evolve --help (grouped, with "
             "its output files and exit statuses), gbssn1d resume --help, gbssn1d converge "
             "--help, gbssn1d sweep --help.");
  app.require_subcommand(1);
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);

  CommandArgs args;
  CommandFlags commands(app, args);
  ConfigOrigins origins;
  try {
    std::vector<std::string> words(argv + 1, argv + argc);
    const std::set<std::string> subcommands{"evolve", "resume", "converge", "sweep"};
    if (!words.empty() && words.front().rfind("-", 0) != 0 && !subcommands.count(words.front()))
      throw ParamError("subcommand", fmt::format("'{}' is not a subcommand: use evolve, resume, "
                                                 "converge or sweep (gbssn1d --help)",
                                                 printable(words.front())));
    refuse_empty_values(words);
    refuse_repeated_flags(words);
    // evolve reads --config here; converge and sweep pass it on to their members, whose own
    // flags may then override the file's values once
    if (!words.empty() && words.front() == "evolve")
      words = expand_config(words, &origins.file_of);
    std::reverse(words.begin(), words.end()); // CLI11 takes a reversed vector of arguments
    app.parse(words);
  } catch (const CLI::CallForHelp& e) {
    return help_or_version(app, e);
  } catch (const CLI::CallForAllHelp& e) {
    return help_or_version(app, e);
  } catch (const CLI::CallForVersion& e) {
    return help_or_version(app, e);
  } catch (const CLI::ExtrasError&) {
    say("gbssn1d: error: {}\n", unexpected_arguments(app));
    return 2;
  } catch (const CLI::ParseError& e) {
    // CLI11's message quotes the value: its control characters escaped, on one line
    const std::string what = one_line(e.what());
    say("gbssn1d: error: {}{}\n", what, origins.note_in(what));
    return 2;
  } catch (const ParamError& e) {
    say("gbssn1d: error: {}{}\n", e.what(), origins.note(e.flag()));
    return 2;
  }

  try {
    switch (commands.finish()) {
    case Subcommand::evolve:
      return run_evolve_command(args.evolve);
    case Subcommand::resume:
      return run_resume_command(args.resume);
    case Subcommand::converge:
      return run_converge_command(args.converge);
    case Subcommand::sweep:
      return run_sweep_command(args.sweep);
    case Subcommand::none:
      break;
    }
  } catch (const ParamError& e) {
    say("gbssn1d: error: {}{}\n", e.what(), origins.note(e.flag()));
    return 2;
  }
  return 0;
}

} // namespace

int run_cli(int argc, char** argv) {
  // The one place where every failure becomes a message and an exit status: nothing
  // escapes as an abort, and no library's text ("filesystem error: ...") reaches the user.
  try {
    return run_command_line(argc, argv);
  } catch (const ParamError& e) {
    say("gbssn1d: error: {}\n", e.what());
    return 2;
  } catch (const std::filesystem::filesystem_error& e) {
    say("gbssn1d: error: {}{}\n",
        e.path1().empty() ? std::string() : printable(e.path1().string()) + ": ",
        e.code().message());
    return 1;
  } catch (const std::bad_alloc&) {
    say("gbssn1d: error: out of memory (a smaller --N, fewer members at once with -j, or "
        "fewer members)\n");
    return 1;
  } catch (const std::exception& e) {
    say("gbssn1d: error: {}\n", e.what());
    return 1;
  } catch (...) {
    say("gbssn1d: error: an unknown failure\n");
    return 1;
  }
}

} // namespace gbssn1d
