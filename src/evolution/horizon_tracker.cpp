#include "evolution/horizon_tracker.hpp"

#include "evolution/horizon_extrapolated.hpp"

#include <cmath>

namespace gbssn1d {

using SearchSchedule = HorizonSearchSettings::Schedule;

const std::vector<std::array<double, 2>>& HorizonTracker::history() const {
  static const std::vector<std::array<double, 2>> none;
  return none;
}

void HorizonTracker::restore(const std::optional<double>& shared,
                             const std::vector<std::array<double, 2>>& /*history*/) {
  shared_ = shared;
}

void HorizonTracker::start(double t) {
  on_start(t);
  if (probe_.levels() > 1 && config_.horizon_search.schedule == SearchSchedule::box_substage) {
    // every box starts from the radius found on the box holding the horizon
    const auto found = probe_.search(level(), config_.rhs.horizon_shift.h, t);
    shared_ = found ? std::optional<double>(found->r) : std::nullopt;
  }
}

std::optional<double> HorizonTracker::locate(std::size_t level, const State& u, const Grid& grid,
                                             double seed, double t) {
  // a single grid, or the study variant box_substage: the box holding the horizon searches on
  // its own stage state, the other boxes read its latest value
  if (probe_.levels() > 1 && level != this->level())
    return shared_;
  const std::optional<MarginalSurface> found = probe_.search_stage(u, grid, seed, t);
  if (!found && shared_)
    probe_.lost(level, t, *shared_);
  shared_ = found ? std::optional<double>(found->r) : std::nullopt;
  return shared_;
}

std::optional<double> HorizonTracker::search_now(double t) const {
  const std::size_t l = level();
  const auto found =
      probe_.search(l, rhs_[l].horizon_radius().value_or(config_.rhs.horizon_shift.h), t);
  return found ? std::optional<double>(found->r) : std::nullopt;
}

namespace {

/// No horizon shift (rahA = 0): h_AH is never needed.
class NoHorizonShift final : public HorizonTracker {
public:
  using HorizonTracker::HorizonTracker;
  Mode mode() const override { return Mode::off; }
  std::optional<double> at_evaluation(std::size_t, const State&, const Grid&, double, std::uint64_t,
                                      std::optional<double> held) override {
    return held;
  }
  std::optional<double> radius(double) override { return std::nullopt; }
};

/// Open loop: h_AH(t) from a file at every stage (the same at every resolution), no searches.
class PrescribedRadius final : public HorizonTracker {
public:
  using HorizonTracker::HorizonTracker;
  Mode mode() const override { return Mode::prescribed; }
  std::optional<double> at_evaluation(std::size_t, const State&, const Grid&, double t,
                                      std::uint64_t, std::optional<double>) override {
    return config_.horizon_search.prescribed(t);
  }
  std::optional<double> radius(double t) override { return config_.horizon_search.prescribed(t); }
};

/// A search every n steps, or after the first step at or past each multiple of an interval T,
/// the radius held on every level in between; the midstep-update variant searches inside the
/// RHS instead, on the 2nd RK substage of every n-th step.
class HeldRadius final : public HorizonTracker {
public:
  using HorizonTracker::HorizonTracker;
  Mode mode() const override { return Mode::held; }

  std::optional<double> at_evaluation(std::size_t level, const State& u, const Grid& grid, double t,
                                      std::uint64_t evaluation,
                                      std::optional<double> held) override {
    const HorizonSearchSettings& s = config_.horizon_search;
    // midstep-update: the 2nd RK substage (evaluation 4k + 1) of every n-th step
    if (s.schedule == SearchSchedule::midstep_update
        && evaluation % static_cast<std::uint64_t>(4 * s.every_steps) == 1 && s.in_window(t))
      return locate(level, u, grid, held.value_or(config_.rhs.horizon_shift.h), t);
    return held;
  }
  void after_step(long n, double t_before, double t) override {
    if (search_due(n, t_before, t))
      update(t);
  }
  std::optional<double> radius(double) override { return rhs_[level()].horizon_radius(); }

private:
  void on_start(double t) override { update(t); }

  /// Whether a search follows step n (from t_before to t): every n-th step, or the first step at
  /// or past a multiple of the interval. From the times alone, so that a resumed run searches
  /// where an uninterrupted one does.
  bool search_due(long n, double t_before, double t) const {
    const HorizonSearchSettings& s = config_.horizon_search;
    if (s.interval > 0.0) {
      // the first step ending at or past a multiple of T (within round-off of the step's times,
      // which are n dt: 3 x (1/3) must reach 1)
      const auto multiples = [&](double time) { return std::floor(time / s.interval + 1e-9); };
      return multiples(t) > multiples(t_before);
    }
    return s.every_steps > 0 && n % s.every_steps == 0;
  }

  void update(double t) {
    if (!config_.horizon_search.in_window(t)
        || config_.horizon_search.schedule
               == SearchSchedule::midstep_update) // searched inside the RHS
      return;
    const std::size_t l = level();
    const auto found =
        probe_.search(l, rhs_[l].horizon_radius().value_or(config_.rhs.horizon_shift.h), t);
    if (!found && rhs_[l].horizon_radius())
      probe_.lost(l, t, *rhs_[l].horizon_radius());
    // Before a horizon is first found none is held: beta_H = 0 until one is. Every level holds
    // the same value.
    shared_ = found ? std::optional<double>(found->r) : std::nullopt;
    for (auto& rhs : rhs_)
      rhs.set_horizon_radius(shared_);
  }
};

/// A single grid, or boxes with the box-substage variant: the RHS of the level holding the
/// horizon searches on every RK stage's state (in the search window), the others read it.
class StageSearch final : public HorizonTracker {
public:
  using HorizonTracker::HorizonTracker;
  Mode mode() const override { return Mode::substage; }
  std::optional<double> at_evaluation(std::size_t level, const State& u, const Grid& grid, double t,
                                      std::uint64_t, std::optional<double> held) override {
    return config_.horizon_search.in_window(t)
               ? locate(level, u, grid, held.value_or(config_.rhs.horizon_shift.h), t)
               : held;
  }
  std::optional<double> radius(double t) override {
    if (config_.horizon_search.in_window(t))
      return search_now(t);
    return rhs_[level()].horizon_radius();
  }
};

} // namespace

std::unique_ptr<HorizonTracker> make_horizon_tracker(const EvolutionConfig& config,
                                                     const mesh::MeshLayout& layout,
                                                     const std::vector<State>& levels,
                                                     std::vector<GbssnRhs>& rhs) {
  const HorizonSearchSettings& s = config.horizon_search;
  if (!config.rhs.horizon_shift.active())
    return std::make_unique<NoHorizonShift>(config, layout, levels, rhs);
  if (s.prescribed)
    return std::make_unique<PrescribedRadius>(config, layout, levels, rhs);
  if (s.every_steps > 0 || s.interval > 0.0)
    return std::make_unique<HeldRadius>(config, layout, levels, rhs);
  if (s.extrapolate || (layout.levels() > 1 && s.schedule != SearchSchedule::box_substage))
    return std::make_unique<ExtrapolatedRadius>(config, layout, levels, rhs);
  return std::make_unique<StageSearch>(config, layout, levels, rhs);
}

} // namespace gbssn1d
