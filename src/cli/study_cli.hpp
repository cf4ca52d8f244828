// The command line of the two studies, converge and sweep (cli/cli.cpp parses, these define
// their flags and check them before the study runs: study/converge.hpp, study/sweep.hpp).
#pragma once

#include "study/converge.hpp"
#include "study/sweep.hpp"

#include <CLI/CLI.hpp>

#include <string>

namespace gbssn1d {

/// Each study subcommand's options as CLI11 fills them.
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

/// The subcommands and their flags, on `app`.
void add_converge(CLI::App& app, ConvergeArgs& a);
void add_sweep(CLI::App& app, SweepArgs& a);

/// The parsed subcommand, its flags checked, run; its exit status.
int run_converge_command(ConvergeArgs& a);
int run_sweep_command(SweepArgs& a);

} // namespace gbssn1d
