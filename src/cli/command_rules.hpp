// The argument rules every subcommand shares (cli.cpp applies the first two to the whole
// command line; the studies the others).
#pragma once

#include <string>
#include <vector>

namespace gbssn1d {

/// -j: at least 1, at most jobs_max (threads and processes beyond that only thrash).
void check_jobs(int jobs);
/// A flag given twice on the command line is refused (a --config file's values may be
/// overridden once by the command line; --sweep is meant to repeat). The short -j is the same
/// flag as --jobs ("-j 2", "-j2").
void refuse_repeated_flags(const std::vector<std::string>& args);
/// Refuses empty values: `--flag=` (which a parser would complete with the next argument, so
/// that the next flag became the value and was lost) and an empty argument (`--flag ''`).
void refuse_empty_values(const std::vector<std::string>& args);
/// The evolve flags given to converge/sweep (`extras`: the flags not the study's own); refuses
/// those the study sets itself (`own`).
std::vector<std::string> pass_through(const std::vector<std::string>& extras,
                                      const std::vector<std::string>& own);

} // namespace gbssn1d
