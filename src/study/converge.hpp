// `gbssn1d converge`: one configuration at three or more resolutions, in parallel, with the
// constraint norms and their orders over time, orders of field differences between
// resolutions, and Richardson-scaled Hamiltonian-constraint profiles.
#pragma once

#include "config/params.hpp"

#include <optional>
#include <string>
#include <vector>

namespace gbssn1d {

struct ConvergeOptions {
  std::vector<int> N; ///< resolutions, increasing (at least 3)
  int jobs = 1;       ///< members run at once
  std::string out;    ///< output directory
  bool force = false; ///< write into an existing non-empty directory
  std::vector<std::string> fields{"alpha", "chi", "K"}; ///< fields whose differences are compared
  std::vector<double> scaled_times; ///< times of the Richardson-scaled H profiles (default tmax)
  double order = 4.0;               ///< order assumed for the scaled profiles
  /// The order the verdict expects (study/verdict.hpp); unset: the members' --fd-order.
  std::optional<double> expect_order;
};

/// The members' parameters: `base` at each N (the grid's map does not depend on N, so every
/// member lives on the same map). Validates all.
std::vector<ResolvedParams> converge_members(const Params& base, const ConvergeOptions& options);

/// Whether the folder `out` holds this very study (an interrupted one, or one to extend): its
/// config.toml is a converge study's (it has the "# converge: N = ..." line only converge
/// writes) of the inputs `base_config` but N, and of the content of the files flags name that
/// `files_text` records (config/input_files.hpp: an edited --rah-hAH-file is another input). False
/// when it has no config.toml; ParamError naming --out when its config.toml is another command's
/// (an evolve run of the same flags is no study) or another study's: without --force such a folder
/// is refused, and nothing in it changed.
bool holds_this_study(const std::string& out, const std::string& base_config,
                      const std::string& files_text);

/// The resolutions of the converge study whose config.toml is in `out`, as its "# converge: N =
/// ..." line lists them ("64,96,128"); "" if there is none.
std::string study_resolutions(const std::string& out);

/// Runs the members and writes DIR/N<n>/ (each member's usual output), DIR/convergence.dat,
/// DIR/scaled_H.dat and DIR/config.toml, and judges the study (study/verdict.hpp): the verdict
/// goes into convergence.dat's header and onto stderr. Returns 0 (completed; converges, or
/// converges until the round-off floor), 3 (a member stopped: non-finite, out of range), 4
/// (completed, but does not converge: the errors do not fall with N), 5 (completed,
/// pre-asymptotic: the errors fall, but below the expected order), or 128 + n (interrupted by
/// signal n).
int run_converge(const Params& base, const ConvergeOptions& options,
                 const std::string& base_config);

} // namespace gbssn1d
