#include "study/orders.hpp"

#include <boost/math/tools/roots.hpp>

#include <cmath>
#include <limits>

namespace gbssn1d {

double order_two_level(double E1, double E2, double N1, double N2) {
  return std::log(E1 / E2) / std::log(N2 / N1);
}

double three_level_ratio(double p, double N1, double N2, double N3) {
  return (std::pow(N1, -p) - std::pow(N2, -p)) / (std::pow(N2, -p) - std::pow(N3, -p));
}

double order_three_level(double d12, double d23, double N1, double N2, double N3) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double ratio = d12 / d23;
  if (!(std::isfinite(ratio) && ratio > 0.0))
    return nan;
  // The ratio increases monotonically with p; bracket in (0, 30].
  auto g = [&](double p) { return std::log(three_level_ratio(p, N1, N2, N3) / ratio); };
  const double lo = 1e-6, hi = 30.0;
  const double g_lo = g(lo), g_hi = g(hi);
  if (!(g_lo <= 0.0 && g_hi >= 0.0))
    return nan;
  std::uintmax_t iterations = 200;
  const auto [a, b] = boost::math::tools::toms748_solve(
      g, lo, hi, g_lo, g_hi, boost::math::tools::eps_tolerance<double>(50), iterations);
  return 0.5 * (a + b);
}

double order_fitted(const std::vector<double>& N, const std::vector<double>& E) {
  const std::size_t n = N.size();
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double x = -std::log(N[k]), y = std::log(E[k]);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  return (static_cast<double>(n) * sxy - sx * sy) / (static_cast<double>(n) * sxx - sx * sx);
}

} // namespace gbssn1d
