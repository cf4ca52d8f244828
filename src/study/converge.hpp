// `gbssn1d converge`: one configuration at three or more resolutions, in parallel, with the
// constraint norms and their orders over time, orders of field differences between
// resolutions, and Richardson-scaled Hamiltonian-constraint profiles.
#pragma once

#include "config/params.hpp"

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
};

/// The members' parameters: `base` at each N (the grid's map does not depend on N, so every
/// member lives on the same map). Validates all.
std::vector<Params> converge_members(const Params& base, const ConvergeOptions& options);

/// Runs the members and writes DIR/N<n>/ (each member's usual output), DIR/convergence.dat,
/// DIR/scaled_H.dat and DIR/config.toml. Returns 0, or 3 if a member went non-finite.
int run_converge(const Params& base, const ConvergeOptions& options,
                 const std::string& base_config);

} // namespace gbssn1d
