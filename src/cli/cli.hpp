// The command line: `gbssn1d evolve [flags]`, CLI11 with grouped --help and config files.
#pragma once

#include "cli/params.hpp"

#include <string>
#include <vector>

namespace gbssn1d {

/// Entry point of the program; returns the exit status.
int run_cli(int argc, char** argv);

/// The effective configuration as a TOML/INI file that `evolve --config` reads back: one
/// `key = value` line per parameter, at full precision.
std::string config_text(const Params& p);

/// Parameters from evolve flags (`--config` files expanded), e.g. a sweep member's arguments.
/// Throws ParamError or CLI::ParseError. Does not resolve defaults or validate.
Params parse_evolve_args(const std::vector<std::string>& args);

/// Whether `name` (without "--") is an evolve flag.
bool is_parameter_name(const std::string& name);

} // namespace gbssn1d
