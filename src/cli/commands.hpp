// The subcommands behind the command line, one file each (cli.cpp parses and dispatches):
// evolve_command.cpp, resume_command.cpp, converge_command.cpp, sweep_command.cpp. Each
// defines its flags on the CLI11 app (add_*) and runs the parsed command (run_*_command);
// each throws ParamError for invalid input and returns the exit status its --help documents.
#pragma once

#include "config/params.hpp"
#include "study/converge.hpp"
#include "study/sweep.hpp"

#include <CLI/CLI.hpp>

#include <string>

namespace gbssn1d {

/// Each subcommand's options as CLI11 fills them.
struct EvolveArgs {
  Params params;
  bool print_config = false;
  std::string config_file; // expanded before parsing (expand_config); listed here for --help
  CLI::App* cmd = nullptr;
};
struct ResumeArgs {
  std::string dir;
  double tmax = 0.0;
  CLI::Option* tmax_opt = nullptr;
  CLI::App* cmd = nullptr;
};
struct ConvergeArgs {
  ConvergeOptions options;
  std::string N_list, factors, fields = "alpha,chi,K", scaled_times;
  double expect_order = 0.0;
  CLI::Option* expect_order_opt = nullptr;
  CLI::App* cmd = nullptr;
};
struct SweepArgs {
  SweepOptions options;
  CLI::Option *jobs = nullptr, *emit = nullptr, *member = nullptr, *collect = nullptr;
  CLI::App* cmd = nullptr;
};

/// `gbssn1d evolve`: one run into --out (or its configuration printed).
void add_evolve(CLI::App& app, EvolveArgs& a);
int run_evolve_command(const EvolveArgs& a);
/// `gbssn1d resume DIR [--tmax T]`: a run continued from DIR/checkpoint.bin.
void add_resume(CLI::App& app, ResumeArgs& a);
int run_resume_command(const ResumeArgs& a);
/// `gbssn1d converge`: one configuration at several resolutions.
void add_converge(CLI::App& app, ConvergeArgs& a);
int run_converge_command(ConvergeArgs& a);
/// `gbssn1d sweep`: a grid of runs over flag values.
void add_sweep(CLI::App& app, SweepArgs& a);
int run_sweep_command(SweepArgs& a);

} // namespace gbssn1d
