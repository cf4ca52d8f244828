#include "evolution/horizon_tracker.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace gbssn1d {

namespace {

using SearchSchedule = HorizonSearchSettings::Schedule;

HorizonTracker::Mode decide_mode(const EvolutionConfig& config, const mesh::MeshLayout& layout) {
  using Mode = HorizonTracker::Mode;
  const HorizonShiftParams& hs = config.rhs.horizon_shift;
  if (!hs.active())
    return Mode::off;
  if (config.horizon_search.prescribed)
    return Mode::prescribed;
  if (config.horizon_search.every_steps > 0 || config.horizon_search.interval > 0.0)
    return Mode::held;
  if (config.horizon_search.extrapolate
      || (layout.levels() > 1 && config.horizon_search.schedule != SearchSchedule::box_substage))
    return Mode::extrapolated;
  return Mode::substage;
}

} // namespace

HorizonTracker::HorizonTracker(const EvolutionConfig& config, const mesh::MeshLayout& layout,
                               const std::vector<State>& levels, std::vector<GbssnRhs>& rhs)
    : config_(config), layout_(layout), levels_(levels), rhs_(rhs),
      mode_(decide_mode(config, layout)) {}

std::optional<MarginalSurface> HorizonTracker::search(std::size_t l, double seed, double t) const {
  try {
    // r alone (R_areal and the mass NaN): every caller reads r, and the areal radius took
    // half of a search (--ah-every extrapolated, a search per step, was no faster than one per
    // RK stage without the r alone)
    return find_horizon_near(levels_[l], layout_.grid(l), config_.horizon_search.finder, seed, 8,
                             false);
  } catch (const HorizonFinderError& e) {
    throw HorizonFinderError(fmt::format("{} (t = {:.6g})", e.what(), t));
  }
}

std::optional<double> HorizonTracker::at_evaluation(std::size_t level, const State& u,
                                                    const Grid& grid, double t,
                                                    std::uint64_t evaluation,
                                                    std::optional<double> held) {
  const HorizonSearchSettings& s = config_.horizon_search;
  const double seed = held.value_or(config_.rhs.horizon_shift.h);
  switch (mode_) {
  case Mode::off:
    return held;
  case Mode::prescribed:
    return s.prescribed(t); // open loop: the same h_AH(t) at every resolution
  case Mode::substage:
    return s.in_window(t) ? locate(level, u, grid, seed, t) : held;
  case Mode::extrapolated:
    // Outside the window the last radius found, on every box and in the output (radius()):
    // a box's own last value was the extrapolation to its last stage time in the window, a
    // different one on each box, and not the one the output reported
    return s.in_window(t) ? locate(level, u, grid, seed, t) : extrapolated_at(t);
  case Mode::held:
    // midstep-update: the 2nd RK substage (evaluation 4k + 1) of every n-th step
    if (s.schedule == SearchSchedule::midstep_update
        && evaluation % static_cast<std::uint64_t>(4 * s.every_steps) == 1 && s.in_window(t))
      return locate(level, u, grid, seed, t);
    return held;
  }
  return held;
}

std::optional<double> HorizonTracker::locate(std::size_t level, const State& u, const Grid& grid,
                                             double seed, double t) {
  if (mode_ == Mode::extrapolated && !searches_stages())
    return extrapolated_at(t);
  // a single grid, or the study variant box_substage: the box holding the horizon searches on
  // its own stage state, the other boxes read its latest value
  if (layout_.levels() > 1 && level != this->level())
    return shared_;
  std::optional<MarginalSurface> found;
  try {
    // r alone: the areal radius is not interpolated (its 30 divisions were about a sixth of a
    // substage's search)
    found = find_horizon_near(u, grid, config_.horizon_search.finder, seed, 8, false);
  } catch (const HorizonFinderError& e) {
    throw HorizonFinderError(fmt::format("{} (RK substage at t = {:.6g})", e.what(), t));
  }
  if (!found && shared_)
    lost(level, t, *shared_);
  shared_ = found ? std::optional<double>(found->r) : std::nullopt;
  return shared_;
}

bool HorizonTracker::searches_stages() const {
  // A single grid's extrapolation (--ah-every extrapolated) searches on the stage state until
  // the history holds four radii: extrapolating from fewer (a constant, a line, a parabola)
  // errs by O(dt), O(dt^2), O(dt^3) in the first steps, which made h_AH converge at 2nd order
  // to the substage search's (1+log trumpet, stretch to 0.89 M). Boxes extrapolate from the
  // start (a coarse box's stage is ahead of the fine box holding the horizon).
  return mode_ == Mode::substage
         || (mode_ == Mode::extrapolated && layout_.levels() == 1 && history_.size() < 4);
}

void HorizonTracker::lost(std::size_t l, double t, double last) const {
  const Grid& grid = layout_.grid(l);
  throw HorizonLostError(fmt::format(
      "the apparent horizon was lost at t = {:.6g} (last found at r_AH = {:.6g}, {:.3g} cells of "
      "dr = {:.3g} from the origin{}): none is left on the grid, and the horizon shift beta_H "
      "would switch off with it",
      t, last, last / grid.min_spacing(), grid.min_spacing(),
      layout_.levels() > 1 ? fmt::format(", level {}", l) : std::string()));
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

bool HorizonTracker::wants_start_nodes() const {
  return mode_ == Mode::extrapolated && layout_.levels() > 1 && config_.stepping.subcycling;
}

void HorizonTracker::seed_start(std::vector<std::array<double, 2>> nodes) {
  start_nodes_ = nodes.size() >= 4 ? std::move(nodes) : std::vector<std::array<double, 2>>{};
}

std::optional<double> HorizonTracker::extrapolated_at(double t) const {
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

void HorizonTracker::search_at_step(double t) {
  if (mode_ != Mode::extrapolated || !config_.horizon_search.in_window(t))
    return;
  const auto found = search(level(), extrapolated_at(t).value_or(config_.rhs.horizon_shift.h), t);
  if (!found && !history_.empty())
    lost(level(), t, history_.back()[1]);
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

void HorizonTracker::update_held(double t) {
  if (mode_ != Mode::held || !config_.horizon_search.in_window(t)
      || config_.horizon_search.schedule
             == SearchSchedule::midstep_update) // searched inside the RHS
    return;
  const std::size_t l = level();
  const auto found = search(l, rhs_[l].horizon_radius().value_or(config_.rhs.horizon_shift.h), t);
  if (!found && rhs_[l].horizon_radius())
    lost(l, t, *rhs_[l].horizon_radius());
  // Before a horizon is first found none is held: beta_H = 0 until one is. Every level holds the
  // same value.
  shared_ = found ? std::optional<double>(found->r) : std::nullopt;
  for (auto& rhs : rhs_)
    rhs.set_horizon_radius(shared_);
}

void HorizonTracker::start(double t) {
  update_held(t);
  search_at_step(t);
  if (layout_.levels() > 1 && config_.horizon_search.schedule == SearchSchedule::box_substage) {
    // every box starts from the radius found on the box holding the horizon
    const auto found = search(level(), config_.rhs.horizon_shift.h, t);
    shared_ = found ? std::optional<double>(found->r) : std::nullopt;
  }
}

bool HorizonTracker::held_search_due(long n, double t_before, double t) const {
  const HorizonSearchSettings& s = config_.horizon_search;
  if (s.interval > 0.0) {
    // the first step ending at or past a multiple of T (within round-off of the step's times,
    // which are n dt: 3 x (1/3) must reach 1)
    const auto multiples = [&](double time) { return std::floor(time / s.interval + 1e-9); };
    return multiples(t) > multiples(t_before);
  }
  return s.every_steps > 0 && n % s.every_steps == 0;
}

void HorizonTracker::after_step(long n, double t_before, double t) {
  if (held_search_due(n, t_before, t))
    update_held(t);
  search_at_step(t);
}

std::size_t HorizonTracker::level() const {
  if (layout_.levels() == 1)
    return 0;
  const double r = shared_.value_or(standard_horizon_radius * config_.initial_data.M);
  return layout_.finest_level_covering(r, RefinementSettings::horizon_margin_cells);
}

std::optional<double> HorizonTracker::radius(double t) {
  const auto& hs = config_.rhs.horizon_shift;
  switch (mode_) {
  case Mode::off:
    return std::nullopt;
  case Mode::prescribed:
    return config_.horizon_search.prescribed(t);
  case Mode::extrapolated:
    if (!searches_stages() || !config_.horizon_search.in_window(t))
      return extrapolated_at(t);
    [[fallthrough]]; // the first steps of a single grid: as the RHS, a search on the state
  case Mode::substage:
    if (config_.horizon_search.in_window(t)) {
      const std::size_t l = level();
      const auto found = search(l, rhs_[l].horizon_radius().value_or(hs.h), t);
      return found ? std::optional<double>(found->r) : std::nullopt;
    }
    break;
  case Mode::held:
    break;
  }
  return rhs_[level()].horizon_radius();
}

void HorizonTracker::restore(const std::optional<double>& shared,
                             const std::vector<std::array<double, 2>>& history) {
  shared_ = shared;
  history_ = history;
}

} // namespace gbssn1d
