// The subcommands behind the command line, one file each: evolve_command.cpp,
// resume_command.cpp, converge_command.cpp, sweep_command.cpp. Each runs its parsed arguments
// (run_*_command: their flags and help pages are in command_flags.cpp; cli.cpp parses and
// dispatches), throws ParamError for invalid input and returns the exit status its --help
// documents.
#pragma once

#include "config/params.hpp"
#include "study/converge.hpp"
#include "study/sweep.hpp"

#include <string>
#include <vector>

namespace gbssn1d {

/// Each subcommand's arguments as the parse leaves them (command_flags.cpp).
struct EvolveArgs {
  Params params;
  bool print_config = false;
  std::string config_file; // expanded before parsing (expand_config); listed here for --help
};
struct ResumeArgs {
  std::string dir;
  double tmax = 0.0;
  bool tmax_given = false;
};
struct ConvergeArgs {
  ConvergeOptions options;
  std::string N_list, factors, fields = "alpha,chi,K", scaled_times;
  double expect_order = 0.0;
  bool expect_order_given = false;
  std::vector<std::string> extras; ///< the flags not converge's own (its members' evolve flags)
};
struct SweepArgs {
  SweepOptions options;
  bool jobs_given = false, emit_given = false, member_given = false, collect_given = false;
  std::vector<std::string> extras; ///< the flags not sweep's own (its members' evolve flags)
};

/// `gbssn1d evolve`: one run into --out (or its configuration printed).
int run_evolve_command(const EvolveArgs& a);
/// `gbssn1d resume DIR [--tmax T]`: a run continued from DIR/checkpoint.bin.
int run_resume_command(const ResumeArgs& a);
/// `gbssn1d converge`: one configuration at several resolutions.
int run_converge_command(ConvergeArgs& a);
/// `gbssn1d sweep`: a grid of runs over flag values.
int run_sweep_command(SweepArgs& a);

} // namespace gbssn1d
