#include "diagnostics/constraints.hpp"

#include "gbssn/rhs.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gbssn1d {

DerivedProfiles derived_profiles(const State& u, const Grid& grid) {
  DerivedProfiles out;
  const std::size_t n = grid.n_interior();
  out.H.resize(n);
  out.M_r.resize(n);
  out.G_r.resize(n);
  out.R_areal.resize(n);
  out.Theta_plus.resize(n);
  out.m_ms.resize(n);
  if (traits(u.formulation()).evolves(Var::Theta)) {
    const auto theta = field(u, grid, Var::Theta).subspan(grid.first_interior(), n);
    out.Theta.assign(theta.begin(), theta.end());
  }
  if (u.matter() != Matter::none)
    out.flux.resize(n);
  diagnostic_rows(u, grid,
                  {out.H.data(), out.M_r.data(), out.G_r.data(), out.R_areal.data(),
                   out.Theta_plus.data(), out.m_ms.data(),
                   out.flux.empty() ? nullptr : out.flux.data()});
  return out;
}

double l2_norm(std::span<const double> values, const Grid& grid, double rmin, double rmax) {
  double sum = 0.0, width = 0.0;
  for (std::size_t k = 0; k < values.size(); ++k) {
    const std::size_t i = grid.first_interior() + k;
    const double r = grid.r()[i];
    if (r < rmin || r > rmax)
      continue;
    sum += values[k] * values[k] * grid.dr()[i];
    width += grid.dr()[i];
  }
  return width > 0.0 ? std::sqrt(sum / width) : std::numeric_limits<double>::quiet_NaN();
}

std::size_t outer_sheet_begin(std::span<const double> R_areal) {
  const std::size_t n = R_areal.size();
  // the outer sheet: outside the outermost minimum of the areal radius (a wormhole's throat;
  // the innermost point of a trumpet), found walking in from the outer boundary, so that the
  // other sheet's points with the same R do not count. Not the global minimum: where chi sits
  // on its floor in the innermost cells of a collapsing wormhole, R = r sqrt(b / chi) dips
  // below the throat's there at spacings finer than about M/90, and the points between that
  // dip and the throat (on the other sheet, near the puncture) would count.
  std::size_t throat = n > 0 ? n - 1 : 0;
  while (throat > 0 && R_areal[throat - 1] <= R_areal[throat])
    --throat;
  return throat;
}

double l2_norm_areal(std::span<const double> values, std::span<const double> R_areal, double Rmin,
                     double Rmax) {
  const std::size_t n = values.size();
  const std::size_t throat = outer_sheet_begin(R_areal.first(n));
  double sum = 0.0, width = 0.0;
  for (std::size_t k = throat; k < n; ++k) {
    if (!(R_areal[k] >= Rmin && R_areal[k] <= Rmax))
      continue;
    // |dR| of the cell: half the distance between its neighbours' areal radii
    const std::size_t lo = k > 0 ? k - 1 : k, hi = k + 1 < n ? k + 1 : k;
    const double dR = std::abs(R_areal[hi] - R_areal[lo]) / static_cast<double>(hi - lo);
    sum += values[k] * values[k] * dR;
    width += dR;
  }
  return width > 0.0 ? std::sqrt(sum / width) : std::numeric_limits<double>::quiet_NaN();
}

double l2_norm_interior(std::span<const double> values, std::span<const double> R_areal,
                        const Grid& grid, double Rmax) {
  double sum = 0.0, width = 0.0;
  for (std::size_t k = 0; k < values.size() && R_areal[k] <= Rmax; ++k) {
    const double dr = grid.dr()[grid.first_interior() + k];
    sum += values[k] * values[k] * dr;
    width += dr;
  }
  return width > 0.0 ? std::sqrt(sum / width) : std::numeric_limits<double>::quiet_NaN();
}

double central_value(std::span<const double> f, const Grid& grid) {
  const std::size_t i1 = grid.first_interior(), i2 = i1 + 1;
  const double r1 = grid.r()[i1], r2 = grid.r()[i2];
  return (r2 * r2 * f[i1] - r1 * r1 * f[i2]) / (r2 * r2 - r1 * r1);
}

} // namespace gbssn1d
