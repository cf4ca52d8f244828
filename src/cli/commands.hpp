// The subcommands behind the command line (cli.cpp parses, these run): evolve and resume
// (evolve_resume.cpp), converge and the argument rules shared by all (study_commands.cpp).
// Each throws ParamError for invalid input and returns the exit status it documents.
#pragma once

#include "config/params.hpp"
#include "study/converge.hpp"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

namespace gbssn1d {

/// `gbssn1d evolve`: one run into p.out (or its configuration printed).
int evolve(const Params& given, bool print_config);
/// `gbssn1d resume DIR [--tmax T]`: a run continued from DIR/checkpoint.bin.
int resume(const std::string& dir_name, std::optional<double> tmax);
/// `gbssn1d converge`: one configuration at several resolutions (lists as given on the line).
int converge(const ConvergeOptions& options, const std::string& N_list, const std::string& factors,
             const std::string& fields, const std::string& times,
             const std::vector<std::string>& evolve_args);

/// -j: at least 1, at most jobs_max (threads and processes beyond that only thrash).
void check_jobs(int jobs);
/// A flag given twice on the command line is refused (a --config file's values may be
/// overridden once by the command line; --sweep is meant to repeat). The short -j is the same
/// flag as --jobs ("-j 2", "-j2").
void refuse_repeated_flags(const std::vector<std::string>& args);
/// Refuses empty values: `--flag=` (which a parser would complete with the next argument, so
/// that the next flag became the value and was lost) and an empty argument (`--flag ''`).
void refuse_empty_values(const std::vector<std::string>& args);
/// The evolve flags given to converge/sweep; refuses those the study sets itself.
std::vector<std::string> pass_through(const CLI::App& cmd, const std::vector<std::string>& own);

} // namespace gbssn1d
