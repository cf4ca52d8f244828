// What a run measures of its current state (evolution/simulation.hpp): its horizons, the
// horizon shift's h_AH, beta_H and Courant number, the derived profiles of each level and of
// their composite, values at radii, and the time series' row.
#include "evolution/simulation.hpp"

#include "gbssn/horizon_shift.hpp"

#include "core/console.hpp"

#include <cmath>
#include <span>

namespace gbssn1d {

std::size_t Simulation::horizon_level() const {
  return tracker_->level();
}

HorizonSearch Simulation::horizons() const {
  return find_all_horizons(layout_, levels_u_, config_.horizon_search.finder, t_);
}

std::optional<double> Simulation::horizon_radius() {
  return tracker_->radius(t_);
}

std::vector<double> Simulation::horizon_shift() {
  const std::optional<double> h_AH = horizon_radius();
  std::vector<std::vector<double>> beta_H(layout_.levels());
  std::vector<std::span<const double>> arrays;
  for (std::size_t l = 0; l < layout_.levels(); ++l) {
    horizon_shift_profile(levels_u_[l], layout_.grid(l), config_.rhs.horizon_shift, h_AH, beta_H[l],
                          t_);
    arrays.emplace_back(beta_H[l]);
  }
  return composite_.gather(arrays);
}

std::optional<Simulation::ShiftCourant> Simulation::horizon_shift_courant() const {
  const HorizonShiftParams& hs = config_.rhs.horizon_shift;
  if (!hs.active())
    return std::nullopt;
  std::optional<double> h_AH;
  if (config_.horizon_search.prescribed)
    h_AH = config_.horizon_search.prescribed(t_);
  else if (const auto found = horizons().horizon())
    h_AH = found->r;
  if (!h_AH)
    return std::nullopt;
  ShiftCourant worst{0.0, 0.0, 0.0, *h_AH};
  std::vector<double> beta_H;
  for (std::size_t l = 0; l < layout_.levels(); ++l) {
    const Grid& g = layout_.grid(l);
    horizon_shift_profile(levels_u_[l], g, hs, h_AH, beta_H, t_);
    const double dt = config_.stepping.cfl * g.min_spacing();
    for (std::size_t i = g.first_interior(); i < g.end_interior(); ++i) {
      const double number = std::abs(beta_H[i]) * dt / g.dr()[i];
      if (!(number <= worst.number)) // (a NaN too)
        worst = {number, g.r()[i], beta_H[i], *h_AH};
    }
  }
  return worst;
}

std::vector<DerivedProfiles> Simulation::level_profiles() const {
  return gbssn1d::level_profiles(layout_, levels_u_);
}

DerivedProfiles Simulation::composite_profiles(const std::vector<DerivedProfiles>& levels) const {
  return gbssn1d::composite_profiles(layout_, composite_, levels);
}

double Simulation::at_radius(Var v, double r) const {
  return value_at_radius(layout_, levels_u_, v, r);
}

double Simulation::H_at_radius(const std::vector<DerivedProfiles>& levels, double r) const {
  return gbssn1d::H_at_radius(layout_, levels, r);
}

void Simulation::report_horizon(const std::optional<MarginalSurface>& h) {
  if (reported_ && h.has_value() == had_horizon_)
    return;
  if (h)
    say("gbssn1d{}: apparent horizon at t = {:.6g}: r = {:.6g}, M_AH = {:.10g}\n", label, t_, h->r,
        h->mass);
  else
    say("gbssn1d{}: no apparent horizon found at t = {:.6g}\n", label, t_);
  had_horizon_ = h.has_value();
  reported_ = true;
}

SeriesRow Simulation::series_row(const DerivedProfiles& d) {
  return series_row(d, horizons());
}

SeriesRow Simulation::series_row(const DerivedProfiles& d, const HorizonSearch& found) {
  return diagnostics_.row(levels_u_, t_, d, found, horizon_radius(), composite_);
}

} // namespace gbssn1d
