// The command line: `gbssn1d evolve [flags]`, CLI11 with grouped --help and config files.
#pragma once

#include "cli/params.hpp"

#include <string>

namespace gbssn1d {

/// Entry point of the program; returns the exit status.
int run_cli(int argc, char** argv);

/// The effective configuration as a TOML/INI file that `evolve --config` reads back: one
/// `key = value` line per parameter, at full precision.
std::string config_text(const Params& p);

} // namespace gbssn1d
