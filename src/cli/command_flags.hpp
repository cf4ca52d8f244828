// The subcommands on the CLI11 app (command_flags.cpp): their flags and help pages, and after a
// parse the subcommand given, with its arguments (commands.hpp) complete.
#pragma once

#include "cli/commands.hpp"

namespace CLI {
class App;
class Option;
} // namespace CLI

namespace gbssn1d {

/// The four subcommands' arguments, as a parse fills them.
struct CommandArgs {
  EvolveArgs evolve;
  ResumeArgs resume;
  ConvergeArgs converge;
  SweepArgs sweep;
};

enum class Subcommand { none, evolve, resume, converge, sweep };

/// The subcommands added to an app, filling `args` when it parses.
class CommandFlags {
public:
  CommandFlags(CLI::App& app, CommandArgs& args);
  /// After a successful parse: the subcommand given, its arguments completed (which optional
  /// flags were given; a study's flags for its members).
  Subcommand finish();

private:
  void add_evolve(CLI::App& app, EvolveArgs& a);
  void add_resume(CLI::App& app, ResumeArgs& a);
  void add_converge(CLI::App& app, ConvergeArgs& a);
  void add_sweep(CLI::App& app, SweepArgs& a);

  CommandArgs* args_;
  CLI::App *evolve_ = nullptr, *resume_ = nullptr, *converge_ = nullptr, *sweep_ = nullptr;
  CLI::Option *resume_tmax_ = nullptr, *expect_order_ = nullptr;
  CLI::Option *jobs_ = nullptr, *emit_ = nullptr, *member_ = nullptr, *collect_ = nullptr;
};

} // namespace gbssn1d
