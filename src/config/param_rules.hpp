// The rules behind the evolve parameters, shared by their defaults, warnings, validation and
// conversion (params.cpp, param_warnings.cpp, validate.cpp, param_convert.cpp): the limits,
// and the check of a choice against its table (the tables: config/choices.hpp).
#pragma once

#include "config/params.hpp"
#include "evolution/evolution_config.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>

namespace gbssn1d {

/// Largest CFL factor accepted: RK4 with 4th-order centred differences is stable for
/// c dt/dr < 2.06; the fastest characteristic speeds are the 1+log gauge speed sqrt(2) plus
/// the shift, so 1 keeps a margin. (dt = cfl * smallest spacing.)
inline constexpr double cfl_max = 1.0;
/// Smallest CFL factor accepted: below it a run only accumulates round-off in t (and a value
/// such as 4.9e-324 would otherwise be reported as too many steps for --tmax).
inline constexpr double cfl_min = 1e-4;
/// The smallest cell accepted, relative to rmax: below it double precision cannot tell the
/// cell's faces apart well enough for 4th-order differences.
inline constexpr double min_spacing_over_rmax = 1e-10;
/// The horizon's radius must be found well within one cell: at most this fraction of the
/// smallest cell width (a loose tolerance returns a point of the bracket, not the root).
inline constexpr double ah_tol_over_spacing_max = 1e-3;
/// RK4 stability limit of the Gamma-driver damping term, eta dt < 2.78 (Schnetter 2010).
inline constexpr double eta_dt_max = 2.78;
/// Largest grid accepted: 9 fields on about 6 state-sized buffers (state, RK4 stages, output).
inline constexpr int N_max = 10'000'000;
/// Most time steps accepted in one run (a typo in --tmax or --dt-series, not a real run).
inline constexpr double steps_max = 1e9;
inline constexpr double rows_max = 1e7;
inline constexpr double rmax_over_M_max = 1e6; ///< rows of timeseries.dat (at most about 3 GB)

/// Most levels accepted: with 30 the finest box is 1e-9 of the outer one.
inline constexpr int levels_max = 30;

/// The value `name` stands for; ParamError naming `flag` and the accepted names otherwise.
template <class E>
E choice(const std::string& flag, const std::string& name, const Choices<E>& choices) {
  std::string list;
  for (const auto& [n, value] : choices) {
    if (n == name)
      return value;
    list += (list.empty() ? "" : ", ") + std::string(n);
  }
  throw ParamError(flag, name, "must be one of " + list);
}

/// Refuses (ParamError naming `flag` and the accepted names, as choice()) a choice that names
/// none of its table's.
template <class E, const Choices<E>& table>
void require_choice(const std::string& flag, const Choice<E, table>& c) {
  if (!c.known())
    (void)choice(flag, c.name(), table);
}

inline std::string num(double v) {
  return fmt::format("{}", v);
}

inline void require_finite(const std::string& flag, double v) {
  if (!std::isfinite(v))
    throw ParamError(flag, num(v), "must be a finite number");
}

inline void require_positive(const std::string& flag, double v) {
  require_finite(flag, v);
  if (!(v > 0.0))
    throw ParamError(flag, num(v), "must be > 0");
}

/// The grid and refinement part of the evolution's configuration of validated parameters:
/// what make_layout() (evolution/levels.hpp) and the stepper read.
EvolutionConfig mesh_config(const ResolvedParams& p);

} // namespace gbssn1d
