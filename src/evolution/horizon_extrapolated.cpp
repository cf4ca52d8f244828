#include "evolution/horizon_extrapolated.hpp"

#include "evolution/simulation.hpp"

#include <algorithm>
#include <exception>
#include <utility>

namespace gbssn1d {

std::optional<double> ExtrapolatedRadius::at_evaluation(std::size_t level, const State& u,
                                                        const Grid& grid, double t,
                                                        std::uint64_t /*evaluation*/,
                                                        std::optional<double> held) {
  // Outside the window the last radius found, on every box and in the output (radius()):
  // a box's own last value was the extrapolation to its last stage time in the window, a
  // different one on each box, and not the one the output reported
  if (!config_.horizon_search.in_window(t) || !searches_stages())
    return extrapolated_at(t);
  return locate(level, u, grid, held.value_or(config_.rhs.horizon_shift.h), t);
}

bool ExtrapolatedRadius::searches_stages() const {
  // A single grid's extrapolation (--ah-every extrapolated) searches on the stage state until
  // the history holds four radii: extrapolating from fewer (a constant, a line, a parabola)
  // errs by O(dt), O(dt^2), O(dt^3) in the first steps, which made h_AH converge at 2nd order
  // to the substage search's (1+log trumpet, stretch to 0.89 M). Boxes extrapolate from the
  // start (a coarse box's stage is ahead of the fine box holding the horizon).
  return probe_.levels() == 1 && history_.size() < 4;
}

std::optional<double> ExtrapolatedRadius::radius(double t) {
  if (!searches_stages() || !config_.horizon_search.in_window(t))
    return extrapolated_at(t);
  return search_now(t); // the first steps of a single grid: as the RHS, a search on the state
}

void ExtrapolatedRadius::restore(const std::optional<double>& shared,
                                 const std::vector<std::array<double, 2>>& history) {
  HorizonTracker::restore(shared, history);
  history_ = history;
}

void ExtrapolatedRadius::after_step(long /*n*/, double /*t_before*/, double t) {
  search_at_step(t);
}

void ExtrapolatedRadius::search_at_step(double t) {
  if (!config_.horizon_search.in_window(t))
    return;
  const auto found =
      probe_.search(level(), extrapolated_at(t).value_or(config_.rhs.horizon_shift.h), t);
  if (!found && !history_.empty())
    probe_.lost(level(), t, history_.back()[1]);
  if (!found) { // none yet: beta_H = 0 until a horizon is found
    history_.clear();
  } else {
    if (!history_.empty() && history_.back()[0] == t)
      history_.pop_back(); // found again at the same time (a resumed run's first step)
    history_.push_back(std::array<double, 2>{t, found->r});
    if (history_.size() > 4)
      history_.erase(history_.begin());
  }
  shared_ = found ? std::optional<double>(found->r) : std::nullopt;
}

namespace {

/// The cubic through the four nodes around t (the first or last four at the ends), at t, in
/// Lagrange's form; `nodes` time-ordered, at least four.
double local_cubic(const std::vector<std::array<double, 2>>& nodes, double t) {
  const auto after =
      std::upper_bound(nodes.begin(), nodes.end(), t,
                       [](double x, const std::array<double, 2>& n) { return x < n[0]; });
  const std::ptrdiff_t last_start = static_cast<std::ptrdiff_t>(nodes.size()) - 4;
  const std::ptrdiff_t first =
      std::clamp<std::ptrdiff_t>((after - nodes.begin()) - 2, 0, last_start);
  double sum = 0.0;
  for (std::ptrdiff_t j = first; j < first + 4; ++j) {
    double weight = 1.0;
    for (std::ptrdiff_t m = first; m < first + 4; ++m)
      if (m != j)
        weight *= (t - nodes[static_cast<std::size_t>(m)][0])
                  / (nodes[static_cast<std::size_t>(j)][0] - nodes[static_cast<std::size_t>(m)][0]);
    sum += weight * nodes[static_cast<std::size_t>(j)][1];
  }
  return sum;
}

} // namespace

bool ExtrapolatedRadius::wants_start_nodes() const {
  return probe_.levels() > 1 && config_.stepping.subcycling;
}

void ExtrapolatedRadius::seed_start(std::vector<std::array<double, 2>> nodes) {
  start_nodes_ = nodes.size() >= 4 ? std::move(nodes) : std::vector<std::array<double, 2>>{};
}

void ExtrapolatedRadius::before_run(double t, double dt, long finest_steps) {
  const double t_pilot = std::min(config_.tmax, 3.0 * dt);
  if (!wants_start_nodes() || !(t < t_pilot) || finest_steps == 1)
    return;
  EvolutionConfig c = config_;
  c.stepping.subcycling = false;
  c.tmax = t_pilot;
  std::vector<std::array<double, 2>> nodes;
  try {
    Simulation pilot(c);
    pilot.on_step = [&nodes](const HorizonTracker& tracker) {
      for (const auto& node : tracker.history()) // the radii not yet taken, t = 0 first
        if (nodes.empty() || node[0] > nodes.back()[0])
          nodes.push_back(node);
    };
    pilot.run(nullptr);
  } catch (const Interrupted&) {
    throw;
  } catch (const std::exception&) { // the run itself meets whatever stopped the pilot
    return;
  }
  // every step of the finest box, from t = 0 on
  const double dt_fine = dt / static_cast<double>(finest_steps);
  if (nodes.empty() || nodes.front()[0] != 0.0 || nodes.back()[0] < t_pilot * (1.0 - 1e-12)
      || static_cast<double>(nodes.size()) < t_pilot / dt_fine)
    return;
  seed_start(std::move(nodes));
}

std::optional<double> ExtrapolatedRadius::extrapolated_at(double t) const {
  const auto& h = history_;
  if (h.empty())
    return std::nullopt;
  if (!config_.horizon_search.in_window(t)) // no searches: the last radius is held
    return h.back()[1];
  if (!start_nodes_.empty() && t <= start_nodes_.back()[0]) // the pilot's steps
    return local_cubic(start_nodes_, t);
  // The polynomial through the last (up to four) radii, at t: in Newton's form, its divided
  // differences formed once per history (every box evaluates it at every RK substage, and the
  // Lagrange form took 12 divisions a call, about 2% of a box run with the shift)
  if (newton_nodes_ != h) {
    newton_nodes_ = h;
    newton_coefficients_.resize(h.size());
    for (std::size_t j = 0; j < h.size(); ++j)
      newton_coefficients_[j] = h[j][1];
    for (std::size_t level = 1; level < h.size(); ++level)
      for (std::size_t j = h.size() - 1; j >= level; --j)
        newton_coefficients_[j] =
            (newton_coefficients_[j] - newton_coefficients_[j - 1]) / (h[j][0] - h[j - level][0]);
  }
  double sum = newton_coefficients_[h.size() - 1];
  for (std::size_t j = h.size() - 1; j-- > 0;)
    sum = newton_coefficients_[j] + (t - h[j][0]) * sum;
  return sum;
}

} // namespace gbssn1d
