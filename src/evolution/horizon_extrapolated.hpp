// The extrapolated mode of the horizon tracker (evolution/horizon_tracker.hpp): boxes, whose
// levels step at their own times, and single grids with --ah-every extrapolated. A search (on
// the box holding the horizon) after each step of the hierarchy; h_AH at any RK stage's time
// from the polynomial through the last (up to) four radii found (error O(dt^4)). A single grid
// searches on the stage states until four radii are kept; subcycled boxes take their first
// steps' h_AH from a pilot run without subcycling.
#pragma once

#include "evolution/horizon_tracker.hpp"

#include <array>
#include <optional>
#include <vector>

namespace gbssn1d {

class ExtrapolatedRadius final : public HorizonTracker {
public:
  using HorizonTracker::HorizonTracker;
  Mode mode() const override { return Mode::extrapolated; }

  std::optional<double> at_evaluation(std::size_t level, const State& u, const Grid& grid, double t,
                                      std::uint64_t evaluation,
                                      std::optional<double> held) override;
  /// Subcycled boxes: the pilot (wants_start_nodes), from t = 0 over the first three steps of
  /// the hierarchy without subcycling, searching after each step of the finest box; its radii
  /// go to seed_start. Deterministic, so a resumed run makes the same. Without a horizon at
  /// each of those steps, or if the pilot fails, nothing is seeded.
  void before_run(double t, double dt, long finest_steps) override;
  void after_step(long n, double t_before, double t) override;
  std::optional<double> radius(double t) override;

  const std::vector<std::array<double, 2>>& history() const override { return history_; }
  void restore(const std::optional<double>& shared,
               const std::vector<std::array<double, 2>>& history) override;

  /// Subcycled boxes: over the first steps of the hierarchy the history holds fewer than four
  /// radii, and the coarse boxes step first, up to a step of the hierarchy ahead of the last
  /// search. That step is capped by the coarse boxes' damping limit and is the same at every N
  /// (0.5 M at eta = 2/M), so the constant, linear and quadratic extrapolations of those steps
  /// put an offset into the gauge that N does not reduce (1.3e-4 in r_AH:
  /// docs/horizon-shift-study.md, Sec. 6.7). Whether the run starts from a pilot.
  bool wants_start_nodes() const;
  /// The pilot's radii (t, h_AH) at every step of the finest box from t = 0 (time-ordered):
  /// while t <= their last time, h_AH(t) is the cubic through the four nodes around t.
  void seed_start(std::vector<std::array<double, 2>> nodes);

private:
  void on_start(double t) override { search_at_step(t); }
  /// Whether an RK stage's h_AH is searched for on the stage state: a single grid until its
  /// history holds four radii.
  bool searches_stages() const;
  /// h_AH at time t from the history.
  std::optional<double> extrapolated_at(double t) const;
  void search_at_step(double t);

  std::vector<std::array<double, 2>> history_;     ///< (t, h_AH) of the last searches
  std::vector<std::array<double, 2>> start_nodes_; ///< seed_start's nodes, empty without a pilot
  /// extrapolated_at's polynomial in Newton's form, and the history it was formed from
  mutable std::vector<std::array<double, 2>> newton_nodes_;
  mutable std::vector<double> newton_coefficients_;
};

} // namespace gbssn1d
