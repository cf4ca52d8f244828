// Convergence orders (equations document, Sec. 15), for any resolutions N1 < N2 < N3 (not
// only factors of 2, and right for cell-centred grids, where only the spacing ratio enters).
#pragma once

#include <vector>

namespace gbssn1d {

/// Order from two resolutions of a quantity whose exact value is zero (a constraint norm):
/// p = ln(E1/E2) / ln(N2/N1).
double order_two_level(double E1, double E2, double N1, double N2);

/// Order from three resolutions of a quantity with unknown exact value: the p solving
/// (u1 - u2)/(u2 - u3) = (N1^-p - N2^-p)/(N2^-p - N3^-p). Pass the differences
/// d12 = |u1 - u2|, d23 = |u2 - u3| (or norms of field differences). NaN when no p in
/// (0, 30] fits.
double order_three_level(double d12, double d23, double N1, double N2, double N3);

/// The ratio (N1^-p - N2^-p)/(N2^-p - N3^-p) that order_three_level inverts.
double three_level_ratio(double p, double N1, double N2, double N3);

/// Least-squares slope of ln E against ln(1/N): the order fitted over several resolutions.
double order_fitted(const std::vector<double>& N, const std::vector<double>& E);

} // namespace gbssn1d
