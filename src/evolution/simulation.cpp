#include "evolution/simulation.hpp"

#include "core/console.hpp"
#include "core/stop_signal.hpp"
#include "initial_data/initial_data.hpp"
#include "mesh/level_steps.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <unistd.h>
#include <utility>

namespace gbssn1d {

Interrupted::Interrupted(int signal_, double t_)
    : std::runtime_error(fmt::format("interrupted by {} at t = {:.6g}", signal_name(signal_), t_)),
      signal(signal_), t(t_) {}

Simulation::Simulation(const EvolutionConfig& config)
    : config_(config), layout_(make_layout(config)), composite_(layout_),
      rhs_(make_level_rhs(config_, layout_,
                          [this](std::size_t l, const State& u, const Grid& g, double t,
                                 std::uint64_t evaluation, std::optional<double> held) {
                            return tracker_->at_evaluation(l, u, g, t, evaluation, held);
                          })),
      diagnostics_(config_, layout_),
      levels_u_(initial_levels(layout_, config.initial_data,
                               Fields(config.rhs.formulation, config.rhs.matter))),
      tracker_(make_horizon_tracker(config_, layout_, levels_u_, rhs_)),
      schedule_(make_schedule(config, mesh::hierarchy_dt(layout_, config.stepping))),
      stepper_(layout_, level_functors(rhs_), config.stepping), clock_(config_, schedule_.dt),
      dense_(layout_, config_.chi_floor, schedule_.dt) {
  stepper_.after_step = [this](std::size_t l, State& u) {
    apply_chi_floor(u, layout_.grid(l), config_.chi_floor);
  };
  for (std::size_t k = 0; k < composite_.size(); ++k)
    composite_levels_.push_back(composite_.level(k));
  stepper_.on_level_step = [this](std::size_t l, double t0, double dt, const State& u0,
                                  const std::array<const State*, 4>& k) {
    dense_.fill(l, t0, dt, u0, k);
  };
  // every level's boundary data from its parent, and the coarse levels restricted from the fine
  // ones (a single grid: its origin ghosts only)
  stepper_.initialise(levels_u_, 0.0);
  // e.g. the backward step of quadratic time interpolation, made twice if run() makes it again
  for (const auto& r : rhs_)
    initial_evaluations_.push_back(r.evaluations() * (reinitialises() ? 2 : 1));
}

bool Simulation::reinitialises() const {
  return layout_.levels() > 1 && config_.rhs.horizon_shift.active()
         && config_.stepping.time == mesh::TimeInterpolation::quadratic;
}

std::uint64_t Simulation::evaluations() const {
  std::uint64_t n = 0;
  for (const auto& r : rhs_)
    n += r.evaluations();
  return n;
}

std::uint64_t Simulation::point_evaluations() const {
  std::uint64_t n = 0;
  for (std::size_t l = 0; l < layout_.levels(); ++l)
    n += rhs_[l].evaluations() * layout_.grid(l).n_interior();
  return n;
}

std::string Simulation::run_facts() const {
  std::string facts =
      fmt::format("dt = {:.17g}\nsteps = {}\ndr-min = {:.17g}\n", schedule_.dt, schedule_.n_steps,
                  layout_.grid(layout_.levels() - 1).min_spacing());
  if (layout_.levels() > 1)
    for (std::size_t l = 0; l < layout_.levels(); ++l)
      facts +=
          fmt::format("level {} = r <= {:.17g}, dr = {:.17g}, dt = {:.17g}\n", l, layout_.extent(l),
                      layout_.spacing(l), stepper_.level_dt(l, schedule_.dt));
  // with matter, the data's ADM mass (vacuum data's is M, a flag)
  if (state().matter() != Matter::none)
    facts += fmt::format("M-ADM = {:.17g}\n", adm_mass(config_.initial_data, state().fields()));
  return facts;
}

void Simulation::set_skip_covered(bool skip) {
  skip_covered_ = skip;
  set_first_cells();
}

void Simulation::set_first_cells() {
  const bool shift = config_.rhs.horizon_shift.active();
  for (std::size_t l = 0; l < layout_.levels(); ++l) {
    rhs_[l].set_first_cell(
        skip_covered_ && !(shift && l == tracker_->level()) ? stepper_.first_needed_cell(l) : 0);
    stepper_.set_first_cell(l, rhs_[l].first_cell()); // the stage sums skip the same cells
  }
}

void Simulation::step(double dt) {
  set_first_cells();
  stepper_.step(levels_u_, t_, dt); // RK4, then the chi floor (stepper_.after_step)
  t_ += dt;
}

void Simulation::step(double dt, const State& dudt) {
  set_first_cells();
  stepper_.step(levels_u_, t_, dt, dudt);
  t_ += dt;
}

void Simulation::check_finite() const {
  check_physical_range(layout_, levels_u_, t_, alpha_min, alpha_max);
}

void Simulation::write_output(Output* out, bool series, bool profiles) {
  if (out && (series || profiles)) {
    const std::vector<DerivedProfiles> levels_d = level_profiles();
    const DerivedProfiles d = composite_profiles(levels_d);
    if (series) {
      const HorizonSearch found = horizons();
      report_horizon(found.horizon());
      out->write_series(series_row(d, found));
      out->write_horizons(t_, found);
    }
    if (profiles) {
      composite_.gather_state(levels_u_, u_composite_);
      out->write_profiles(t_, u_composite_, composite_.grid(), d, horizon_shift(),
                          composite_levels_);
    }
  }
  if (series && on_series)
    on_series(*this);
}

void Simulation::write_due(Output* out, bool have_dense) {
  // Every output time in (t_prev, t_]: on the step itself, or between the steps from each
  // level's RK4 dense output over its own (sub)step (dense_; one level: the single grid). The
  // diagnostics read the levels' states and t_, so the interpolated states stand in for them
  // while they are written.
  while (const auto due = clock_.due_by(t_)) {
    if (std::abs(due->t - t_) <= 1e-9 * schedule_.dt || !have_dense) {
      write_output(out, due->series, due->profiles);
    } else {
      std::vector<State>& between = dense_.at(due->t);
      std::swap(levels_u_, between);
      stepper_.fill_ghosts(levels_u_); // the fine boundaries from their parents
      const double t_step = std::exchange(t_, due->t);
      write_output(out, due->series, due->profiles);
      t_ = t_step;
      std::swap(levels_u_, between);
    }
    if (!clock_.advance(*due))
      return;
  }
}

void Simulation::save_checkpoint(Output* out, const std::optional<double>& h_AH_before_rhs) {
  if (!out)
    return;
  const Checkpoint c = checkpoint(*out, h_AH_before_rhs);
  write_checkpoint(out->dir() / "checkpoint.bin", c);
  if (on_checkpoint)
    on_checkpoint(c);
}

void Simulation::run(Output* out) {
  const Schedule& s = schedule_;
  const double t_end = config_.tmax;
  tracker_->before_run(t_, schedule_.dt, stepper_.steps(layout_.levels() - 1));
  if (!resumed_) {
    check_finite();
    tracker_->start(t_);
    // The stepper was initialised before the horizon was found: quadratic time interpolation's
    // earlier time levels (one RK4 step backwards) are made again with the horizon shift that
    // the evolution will use (without it they lack beta_H, an O(dt) inconsistency at every fine
    // boundary in the first step that the Gamma-driver keeps)
    if (reinitialises())
      stepper_.initialise(levels_u_, t_);
    write_output(out, true, true);
  }
  if (step_ >= s.n_steps)
    return;
  // Checkpoints at full steps (never after the shortened last one, so that a resumed run with
  // a later tmax steps exactly as an uninterrupted one).
  double next_checkpoint = checkpoint_after(config_.checkpoint_every, t_);
  ProgressLine progress(show_progress && ::isatty(STDERR_FILENO), t_, t_end);
  tracker_->mark_before_rhs();
  dudt_now_.fit(levels_u_[0]);
  set_first_cells();
  rhs_[0](levels_u_[0], dudt_now_, t_); // RK4's first stage of the first step
  for (long n = step_ + 1; n <= s.n_steps; ++n) {
    const bool last = n == s.n_steps;
    // the output times inside this step, filled by the levels' dense output as they step
    const double t_next = last ? t_end : static_cast<double>(n) * s.dt;
    const bool dense = clock_.before(t_next);
    if (dense)
      dense_.prepare(clock_.times_inside(t_, t_next));
    const double t_before = t_;
    step(t_next - t_, dudt_now_);
    t_ = t_next; // no accumulated round-off in t
    step_ = n;
    check_finite();
    tracker_->after_step(n, t_before, t_);
    if (on_step)
      on_step(*tracker_);
    // what a checkpoint records of the RHS before this evaluation (resume repeats it)
    const std::optional<double> h_AH_before_rhs = rhs_[0].horizon_radius();
    tracker_->mark_before_rhs();
    evaluations_before_rhs_ = rhs_[0].evaluations();
    if (!last) {
      set_first_cells();
      rhs_[0](levels_u_[0], dudt_now_, t_); // the next step's first stage
    }
    write_due(out, dense);
    if (!last && t_ >= next_checkpoint - 1e-9 * s.dt) {
      save_checkpoint(out, h_AH_before_rhs);
      next_checkpoint = checkpoint_after(config_.checkpoint_every, t_);
    }
    if (const int signal = stop_signal(); signal != 0 && !last) {
      save_checkpoint(out, h_AH_before_rhs); // the run can be resumed from here
      throw Interrupted(signal, t_);
    }
    if (n % 64 == 0 || last)
      progress.update(t_, last);
  }
}

} // namespace gbssn1d
