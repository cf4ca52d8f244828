#include "horizon/apparent_horizon.hpp"

#include "gbssn/rhs.hpp"
#include "grid/interpolation.hpp"

#include <boost/math/tools/roots.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

namespace gbssn1d {

namespace {

constexpr std::size_t stencil = 6; // points of the Lagrange interpolant

} // namespace

std::optional<MarginalSurface> HorizonSearch::horizon() const {
  for (const auto& s : surfaces)
    if (s.outer)
      return s;
  return std::nullopt;
}

namespace {

/// Scans the intervals [k-1, k] for k_lo < k <= k_hi (interior indices), from the outside in,
/// and hands each zero of Theta_+ found to `visit`, which returns true to stop the scan.
/// Theta_+ and the areal radius on the window and its interpolation stencils come from one
/// vectorised loop (diagnostic_rows), not a call per point: the search at every output time
/// scans the whole grid, the one near its seed on every RK substage 29 points. Without
/// `areal_radius`, R_areal and mass are NaN (the RK substages' searches read r alone: the
/// areal radius's interpolation took 30 divisions a search).
template <class Visit>
void scan(const State& u, const Grid& grid, const HorizonFinderParams& params, std::size_t k_lo,
          std::size_t k_hi, bool areal_radius, Visit&& visit) {
  const std::size_t n = grid.n_interior();
  // the scanned points and the interpolation stencils around them: [fill_lo, fill_hi)
  const std::size_t fill_lo = k_lo >= stencil ? k_lo - stencil : 0;
  const std::size_t fill_hi = std::min(n, k_hi + stencil + 1);
  const std::size_t m = fill_hi - fill_lo;
  // (no constraints: their derivatives are left out of the loop; the rows are kept per
  // thread, so that the search on every RK substage allocates nothing)
  thread_local std::vector<double> theta_rows, R_rows;
  theta_rows.resize(m);
  R_rows.resize(m);
  diagnostic_rows(u, grid, {nullptr, nullptr, nullptr, R_rows.data(), theta_rows.data()}, fill_lo,
                  fill_hi);
  const auto theta = [&](std::size_t k) { return theta_rows[k - fill_lo]; };
  // x from fill_lo on, the rows of Theta_+ and R, for the Lagrange interpolant
  const std::span<const double> x =
      std::span<const double>(grid.x()).subspan(grid.first_interior() + fill_lo);
  for (std::size_t k = k_hi; k > k_lo; --k) {
    const std::size_t lo = k - 1;
    if (grid.r()[grid.first_interior() + k] < params.r_min)
      break;
    const double f_lo = theta(lo), f_hi = theta(k);
    if (!std::isfinite(f_lo) || !std::isfinite(f_hi))
      throw HorizonFinderError(
          fmt::format("the horizon finder met a non-finite expansion Theta_+ = {} at r = {:.6g}",
                      std::isfinite(f_lo) ? f_hi : f_lo,
                      grid.r()[grid.first_interior() + (std::isfinite(f_lo) ? k : lo)]));
    if ((f_lo < 0.0) == (f_hi < 0.0) && f_lo != 0.0)
      continue;
    const std::size_t k0 = std::max(lagrange6_start(lo, n), fill_lo);
    for (std::size_t j = k0; j < k0 + stencil; ++j)
      if (!std::isfinite(theta(j)))
        throw HorizonFinderError(
            fmt::format("the horizon finder met a non-finite expansion Theta_+ = {} at r = {:.6g}",
                        theta(j), grid.r()[grid.first_interior() + j]));
    const std::size_t j0 = k0 - fill_lo;                 // the stencil in the rows from fill_lo
    const Lagrange6Newton theta_of_x(x, theta_rows, j0); // lagrange6's, without divisions
    const double x_lo = x[lo - fill_lo], x_hi = x[k - fill_lo];
    double x_root;
    if (f_lo == 0.0) {
      x_root = x_lo;
    } else {
      // tolerance in x equivalent to params.tolerance in r
      // (dr/dx from the grid's row of its inverse: the map's sinh took about 5% of a search)
      const double tol_x = params.tolerance * grid.inv_dr_dx()[grid.first_interior() + lo];
      auto done = [tol_x](double a, double b) { return std::abs(b - a) <= tol_x; };
      std::uintmax_t iterations = 100;
      try {
        const auto [a, b] = boost::math::tools::toms748_solve(
            theta_of_x, x_lo, x_hi, theta_of_x(x_lo), theta_of_x(x_hi), done, iterations);
        x_root = 0.5 * (a + b);
      } catch (const std::exception& e) {
        throw HorizonFinderError(fmt::format(
            "the horizon finder failed between r = {:.6g} and {:.6g}: {}",
            grid.r()[grid.first_interior() + lo], grid.r()[grid.first_interior() + k], e.what()));
      }
      if (!std::isfinite(x_root))
        throw HorizonFinderError(fmt::format(
            "the horizon finder returned a non-finite root between r = {:.6g} and {:.6g}",
            grid.r()[grid.first_interior() + lo], grid.r()[grid.first_interior() + k]));
    }
    MarginalSurface s;
    s.r = grid.map().r(x_root);
    s.R_areal =
        areal_radius ? lagrange6(x, R_rows, j0, x_root) : std::numeric_limits<double>::quiet_NaN();
    s.mass = 0.5 * s.R_areal;
    s.outer = f_lo < 0.0 && f_hi >= 0.0;
    if (visit(s))
      return;
  }
}

/// The scan reaches the interval between the first two interior cells: Theta_+ there takes the
/// derivatives the evolution takes at those cells, whose stencils read the origin's parity ghosts
/// (filled on every state the evolution holds); a sphere through the origin itself (r = 0,
/// between the first cell and its mirror) is not a surface.
constexpr std::size_t k_first = 0;

} // namespace

HorizonSearch find_horizons(const State& u, const Grid& grid, const HorizonFinderParams& params) {
  HorizonSearch result;
  scan(u, grid, params, k_first, grid.n_interior() - 1, true, [&](const MarginalSurface& s) {
    result.surfaces.push_back(s);
    return false;
  });
  return result;
}

std::optional<MarginalSurface> find_horizon_near(const State& u, const Grid& grid,
                                                 const HorizonFinderParams& params, double r_seed,
                                                 std::size_t window, bool areal_radius) {
  const std::size_t n = grid.n_interior();
  const auto& r = grid.r();
  const auto it =
      std::lower_bound(r.begin() + static_cast<std::ptrdiff_t>(grid.first_interior()),
                       r.begin() + static_cast<std::ptrdiff_t>(grid.end_interior()), r_seed);
  const std::size_t k_seed = static_cast<std::size_t>(it - r.begin()) - grid.first_interior();
  const std::size_t k_lo = std::max(k_first, k_seed > window ? k_seed - window : 0);
  const std::size_t k_hi = std::min(n - 1, k_seed + window);
  // the outermost zero with Theta_+ < 0 inside (HorizonSearch::horizon), kept without a list
  std::optional<MarginalSurface> found;
  const auto first_outer = [&found](const MarginalSurface& s) {
    if (s.outer)
      found = s;
    return s.outer;
  };
  if (k_hi > k_lo)
    scan(u, grid, params, k_lo, k_hi, areal_radius, first_outer);
  if (!found)
    scan(u, grid, params, k_first, n - 1, areal_radius, first_outer);
  return found;
}

} // namespace gbssn1d
