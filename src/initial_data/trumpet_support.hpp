// What both trumpet solutions (trumpet_solutions.cpp, maximal_trumpet.cpp) share: the checks of
// their arguments and a bracketed root-finder. Internal to src/initial_data.
#pragma once

#include <boost/math/tools/roots.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

namespace gbssn1d::trumpet {

inline void require_valid_mass(double M, const char* who) {
  if (!(M > 0.0) || !std::isfinite(M))
    throw std::invalid_argument(std::string(who) + ": the mass M must be positive and finite");
}

inline void require_valid_radius(double r, const char* who) {
  if (!(r > 0.0) || !std::isfinite(r))
    throw std::invalid_argument(std::string(who)
                                + ": the isotropic radius r must be positive and finite");
}

/// Solves g(x) = 0 for x in [lo, hi] with TOMS 748, to a relative bracket width of a few
/// ulp; g must change sign on the bracket.
template <class Function>
inline double solve_bracketed(Function g, double lo, double hi, double g_lo, double g_hi) {
  if (g_lo == 0.0)
    return lo;
  if (g_hi == 0.0)
    return hi;
  std::uintmax_t max_iter = 200;
  const auto [a, b] = boost::math::tools::toms748_solve(
      g, lo, hi, g_lo, g_hi,
      boost::math::tools::eps_tolerance<double>(std::numeric_limits<double>::digits - 1), max_iter);
  return 0.5 * (a + b);
}

} // namespace gbssn1d::trumpet
