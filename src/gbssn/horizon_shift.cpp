#include "gbssn/horizon_shift.hpp"

#include "core/registry.hpp"
#include "gbssn/full_shift.hpp"

#include <cmath>

namespace gbssn1d {

std::vector<double> profile_on(const Grid& grid, const HorizonShiftParams& params) {
  std::vector<double> f(grid.n_total());
  for (std::size_t i = 0; i < f.size(); ++i)
    f[i] = shift_profile(params.profile, grid.r()[i] / params.width) // odd
           * outer_taper(std::abs(grid.r()[i]) / params.r_cut, params.taper);
  return f;
}

namespace {

/// One loop per normal, so that each vectorises; out of line, so that
/// `bench/loop_mix.py --check-vectorised` finds each (vectorised, and without the divider).
/// Writes beta_H, or with `full` beta_GD + beta_H alone (the right-hand side reads no more).
template <ShiftNormal normal, bool full>
[[gnu::noinline]] void fill_horizon_shift(std::size_t n, const double* f, const double* chi,
                                          const double* a, double amplitude, double chi_smooth,
                                          double* out, const double* beta_GD) {
  for (std::size_t i = 0; i < n; ++i) {
    const double beta_H = f[i] * amplitude * shift_normal(normal, chi[i], a[i], chi_smooth);
    if constexpr (full)
      out[i] = beta_GD[i] + beta_H;
    else
      out[i] = beta_H; // s^r even
  }
}

template <bool full>
void fill_for(ShiftNormal normal, std::size_t n, const double* f, const double* chi,
              const double* a, double amplitude, double chi_smooth, double* out,
              const double* beta_GD) {
  switch (normal) { // dispatched once per call
  case ShiftNormal::conformal:
    return fill_horizon_shift<ShiftNormal::conformal, full>(n, f, chi, a, amplitude, chi_smooth,
                                                            out, beta_GD);
  case ShiftNormal::smooth:
    return fill_horizon_shift<ShiftNormal::smooth, full>(n, f, chi, a, amplitude, chi_smooth, out,
                                                         beta_GD);
  case ShiftNormal::unit:
  default:
    return fill_horizon_shift<ShiftNormal::unit, full>(n, f, chi, a, amplitude, chi_smooth, out,
                                                       beta_GD);
  }
}

} // namespace

void horizon_shift_on(ShiftNormal normal, std::size_t n, const double* f, const double* chi,
                      const double* a, double amplitude, double chi_smooth, double* beta_H) {
  fill_for<false>(normal, n, f, chi, a, amplitude, chi_smooth, beta_H, nullptr);
}

void full_shift_on(ShiftNormal normal, std::size_t n, const double* f, const double* chi,
                   const double* a, double amplitude, double chi_smooth, const double* beta_GD,
                   double* beta_full) {
  fill_for<true>(normal, n, f, chi, a, amplitude, chi_smooth, beta_full, beta_GD);
}

void horizon_shift_profile(const State& u, const Grid& grid, const HorizonShiftParams& params,
                           std::optional<double> h_AH, std::vector<double>& beta_H, double t) {
  beta_H.assign(grid.n_total(), 0.0);
  if (!h_AH || params.A == 0.0)
    return;
  const double amplitude = params.strength(t) * (*h_AH - params.h);
  horizon_shift_on(params.normal, grid.n_total(), profile_on(grid, params).data(),
                   field(u, grid, Var::chi).data(), field(u, grid, Var::a).data(), amplitude,
                   params.chi_smooth, beta_H.data());
}

} // namespace gbssn1d
