// The command line: `gbssn1d evolve|resume|converge|sweep [flags]`, CLI11 with grouped --help.
#pragma once

namespace gbssn1d {

/// Entry point of the program; returns the exit status.
int run_cli(int argc, char** argv);

} // namespace gbssn1d
