#include "evolution/simulation.hpp"

#include "core/console.hpp"
#include "core/stop_signal.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <unistd.h>
#include <utility>

namespace gbssn1d {

NonFiniteError::NonFiniteError(double t_, double r_, const std::string& var_)
    : std::runtime_error(fmt::format(
        "the evolution became non-finite at t = {:.6g}, r = {:.6g} in {}", t_, r_, var_)),
      t(t_), r(r_), var(var_) {}

NonFiniteError::NonFiniteError(double t_, double r_, const std::string& var_, double value,
                               const std::string& why)
    : std::runtime_error(fmt::format("the evolution left the physical range at t = {:.6g}, "
                                     "r = {:.6g}: {} = {:.6g} ({})",
                                     t_, r_, var_, value, why)),
      t(t_), r(r_), var(var_) {}

Interrupted::Interrupted(int signal_, double t_)
    : std::runtime_error(fmt::format("interrupted by {} at t = {:.6g}", signal_name(signal_), t_)),
      signal(signal_), t(t_) {}

Schedule make_schedule(const EvolutionConfig& config, const Grid& grid) {
  Schedule s;
  s.dt = time_step(config.cfl, grid);
  s.n_steps = static_cast<long>(std::ceil(config.tmax / s.dt - 1e-9));
  return s;
}

void hermite_interpolate(const State& u0, const State& f0, const State& u1, const State& f1,
                         double dt, double theta, State& out) {
  const double s = theta, s2 = s * s, s3 = s2 * s;
  const double h00 = 2.0 * s3 - 3.0 * s2 + 1.0, h01 = -2.0 * s3 + 3.0 * s2;
  const double h10 = (s3 - 2.0 * s2 + s) * dt, h11 = (s3 - s2) * dt;
  out.resize(u0.size());
  for (std::size_t i = 0; i < u0.size(); ++i)
    out[i] = h00 * u0[i] + h10 * f0[i] + h01 * u1[i] + h11 * f1[i];
}

namespace {

/// The configuration's RHS with the horizon finder as its locator (substage searches).
RhsParams rhs_params_with_finder(const EvolutionConfig& config) {
  RhsParams r = config.rhs;
  const HorizonFinderParams finder = config.horizon_search.finder;
  r.horizon_shift.locate = [finder](const State& u, const Grid& grid, double seed,
                                    double t) -> std::optional<double> {
    try {
      const auto found = find_horizon_near(u, grid, finder, seed);
      return found ? std::optional<double>(found->r) : std::nullopt;
    } catch (const HorizonFinderError& e) {
      throw HorizonFinderError(fmt::format("{} (RK substage at t = {:.6g})", e.what(), t));
    }
  };
  return r;
}

} // namespace

Simulation::Simulation(const EvolutionConfig& config)
    : config_(config), layout_(make_grid(config.grid).map(), config.grid.N, 1),
      rhs_(layout_.grid(0), rhs_params_with_finder(config)),
      diagnostic_rhs_(rhs_), levels_u_{initial_data(layout_.grid(0), config.initial_data)},
      schedule_(make_schedule(config, layout_.grid(0))),
      stepper_(layout_, {[this](const State& u, State& dudt, double t) { rhs_(u, dudt, t); }},
               mesh::StepperOptions{.cfl = config.cfl}) {
  stepper_.after_step = [this](std::size_t, State& u) {
    apply_chi_floor(u, grid(), config_.chi_floor);
  };
}

template <class Search>
auto Simulation::with_time(Search search) const {
  try {
    return search();
  } catch (const HorizonFinderError& e) {
    throw HorizonFinderError(fmt::format("{} (t = {:.6g})", e.what(), t_));
  }
}

HorizonSearch Simulation::horizons() const {
  return with_time([&] { return find_horizons(u_, grid(), config_.horizon_search.finder); });
}

std::optional<double> Simulation::horizon_radius() {
  const auto& hs = rhs_.params().horizon_shift;
  if (!hs.active())
    return std::nullopt;
  if (hs.prescribed())
    return hs.prescribed_h_AH(t_);
  if (config_.horizon_search.every_steps == 0 && config_.horizon_search.in_window(t_)) {
    const auto found = with_time([&] {
      return find_horizon_near(u_, grid(), config_.horizon_search.finder,
                               rhs_.horizon_radius().value_or(hs.h));
    });
    return found ? std::optional<double>(found->r) : std::nullopt;
  }
  return rhs_.horizon_radius();
}

std::vector<double> Simulation::horizon_shift() {
  std::vector<double> beta_H;
  horizon_shift_profile(u_, grid(), rhs_.params().horizon_shift, horizon_radius(), beta_H, t_);
  return beta_H;
}

void Simulation::update_held_horizon() {
  const auto& hs = rhs_.params().horizon_shift;
  if (!hs.active() || hs.prescribed() || config_.horizon_search.every_steps == 0
      || !config_.horizon_search.in_window(t_)
      || hs.variant == HorizonShiftParams::Variant::midstep_update) // searched inside the RHS
    return;
  const auto found = with_time([&] {
    return find_horizon_near(u_, grid(), config_.horizon_search.finder,
                             rhs_.horizon_radius().value_or(hs.h));
  });
  // Without a horizon the held value is dropped: beta_H = 0 until one is found.
  rhs_.set_horizon_radius(found ? std::optional<double>(found->r) : std::nullopt);
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
  const Grid& g = grid();
  const double inf = std::numeric_limits<double>::infinity();
  SeriesRow row;
  row.t = t_;
  row.alpha_center = central_value(field(u_, g, Var::alpha), g);
  row.H_L2 = l2_norm(d.H, g, 0.0, inf);
  const NormWindows& w = config_.norms;
  row.H_L2_ext = l2_norm(d.H, g, w.rmin, w.rmax);
  row.M_L2 = l2_norm(d.M_r, g, 0.0, inf);
  row.M_L2_ext = l2_norm(d.M_r, g, w.rmin, w.rmax);
  row.G_L2 = l2_norm(d.G_r, g, 0.0, inf);
  row.G_L2_ext = l2_norm(d.G_r, g, w.rmin, w.rmax);
  row.H_L2_R = l2_norm_areal(d.H, d.R_areal, w.Rmin, w.Rmax);
  row.M_L2_R = l2_norm_areal(d.M_r, d.R_areal, w.Rmin, w.Rmax);
  row.H_L2_int = l2_norm_interior(d.H, d.R_areal, g, w.Rint);
  diagnostic_rhs_.set_horizon_radius(rhs_.horizon_radius());
  // The midstep-update variant times its searches by the RHS's evaluation count: reset so that
  // the diagnostic evaluation never searches on a schedule of its own (which would make
  // d_t alpha depend on how many outputs came before, and a resumed run differ).
  diagnostic_rhs_.set_evaluations(0);
  diagnostic_rhs_(u_, dudt_, t_);
  const auto dt_alpha = field(std::as_const(dudt_), g, Var::alpha);
  const auto horizon = found.horizon();
  row.r_ah = horizon ? horizon->r : std::numeric_limits<double>::quiet_NaN();
  row.M_ah = horizon ? horizon->mass : std::numeric_limits<double>::quiet_NaN();
  row.M_ah_err = row.M_ah - config_.initial_data.M;
  row.dtalpha_max_ext = 0.0;
  for (std::size_t i = g.first_interior(); i < g.end_interior(); ++i)
    if (g.r()[i] >= config_.norms.rmin && g.r()[i] <= config_.norms.rmax)
      row.dtalpha_max_ext = std::max(row.dtalpha_max_ext, std::abs(dt_alpha[i]));
  return row;
}

std::string Simulation::run_facts() const {
  return fmt::format("dt = {:.17g}\nsteps = {}\ndr-min = {:.17g}\n", schedule_.dt,
                     schedule_.n_steps, grid().min_spacing());
}

void Simulation::step(double dt) {
  stepper_.step(levels_u_, t_, dt); // RK4, then the chi floor (stepper_.after_step)
  t_ += dt;
}

void Simulation::step(double dt, const State& dudt) {
  stepper_.step(levels_u_, t_, dt, dudt);
  t_ += dt;
}

void apply_chi_floor(State& u, const Grid& grid, double chi_floor) {
  if (chi_floor <= 0.0)
    return;
  for (double& chi : field(u, grid, Var::chi))
    chi = std::max(chi, chi_floor);
}

void Simulation::check_finite() const {
  const Grid& g = grid();
  for (std::size_t i = g.first_interior(); i < g.n_total(); ++i)
    for (const auto& entry : registry)
      if (!std::isfinite(field(u_, g, entry.var)[i]))
        throw NonFiniteError(t_, g.r()[i], std::string(entry.name));
  const auto chi = field(u_, g, Var::chi), alpha = field(u_, g, Var::alpha);
  for (std::size_t i = g.first_interior(); i < g.end_interior(); ++i) {
    if (!(chi[i] > 0.0))
      throw NonFiniteError(t_, g.r()[i], "chi", chi[i], "must be > 0; see --chi-floor");
    if (alpha[i] < alpha_min || alpha[i] > alpha_max)
      throw NonFiniteError(t_, g.r()[i], "alpha", alpha[i],
                           fmt::format("must lie in [{}, {}]", alpha_min, alpha_max));
  }
}

void Simulation::restore(const Checkpoint& c) {
  if (c.u.size() != u_.size())
    throw CheckpointError(
        fmt::format("the checkpoint has {} values, this grid {}", c.u.size(), u_.size()));
  if (c.dt != schedule_.dt)
    throw CheckpointError(
        fmt::format("the checkpoint's step {} is not this run's {}", c.dt, schedule_.dt));
  if (c.step < 0 || c.step > schedule_.n_steps)
    throw CheckpointError(fmt::format(
        "the checkpoint at step {} lies outside this run's steps 0 ... {} (--tmax = {})", c.step,
        schedule_.n_steps, config_.tmax));
  // Every counter must be the one the run itself would hold at this step (run() sets
  // t = n dt, writes the outputs at k dt_series <= t, and evaluates the RHS four times a step).
  if (c.t != static_cast<double>(c.step) * schedule_.dt)
    throw CheckpointError(fmt::format("the checkpoint's time {} is not step {} x dt = {}", c.t,
                                      c.step, static_cast<double>(c.step) * schedule_.dt));
  const double tol = 1e-9 * schedule_.dt;
  auto next_output = [&](double cadence) { // the first k with k cadence > t (as run() counts)
    auto k = static_cast<std::int64_t>(std::floor((c.t + tol) / cadence)) + 1;
    if (k > 1 && static_cast<double>(k - 1) * cadence > c.t + tol)
      --k;
    if (static_cast<double>(k) * cadence <= c.t + tol)
      ++k;
    return k;
  };
  if (c.k_series != next_output(config_.dt_series)
      || c.k_profiles != next_output(config_.dt_profiles))
    throw CheckpointError(fmt::format(
        "the checkpoint's output counters ({}, {}) are not those of t = {} ({}, {})", c.k_series,
        c.k_profiles, c.t, next_output(config_.dt_series), next_output(config_.dt_profiles)));
  if (c.evaluations != 4 * static_cast<std::uint64_t>(c.step))
    throw CheckpointError(
        fmt::format("the checkpoint's RHS count {} is not 4 x step {}", c.evaluations, c.step));
  if (c.h_AH && !(std::isfinite(*c.h_AH) && *c.h_AH > 0.0))
    throw CheckpointError(
        fmt::format("the checkpoint's horizon radius {} is not a radius", *c.h_AH));
  u_ = c.u;
  t_ = c.t;
  step_ = c.step;
  k_series_ = c.k_series;
  k_profiles_ = c.k_profiles;
  rhs_.set_horizon_radius(c.h_AH);
  rhs_.set_evaluations(c.evaluations);
  had_horizon_ = c.had_horizon;
  reported_ = c.reported;
  resumed_ = true;
}

Checkpoint Simulation::checkpoint(Output& out, const std::optional<double>& h_AH_before_rhs) const {
  Checkpoint c;
  c.config = checkpoint_config;
  c.step = step_;
  c.t = t_;
  c.dt = schedule_.dt;
  c.k_series = k_series_;
  c.k_profiles = k_profiles_;
  c.h_AH = h_AH_before_rhs;
  c.had_horizon = had_horizon_;
  c.reported = reported_;
  c.evaluations = evaluations_before_rhs_;
  c.marks = out.marks();
  c.u = u_;
  return c;
}

void Simulation::run(Output* out) {
  const Schedule& s = schedule_;
  const double t_end = config_.tmax;
  // Output times: k dt_series, k dt_profiles and tmax, each written once (to round-off).
  long& k_series = k_series_;
  long& k_profiles = k_profiles_;
  auto next_series = [&] {
    return std::min(static_cast<double>(k_series) * config_.dt_series, t_end);
  };
  auto next_profiles = [&] {
    return std::min(static_cast<double>(k_profiles) * config_.dt_profiles, t_end);
  };
  auto write = [&](bool series, bool profiles) {
    if (out && (series || profiles)) {
      const DerivedProfiles d = derived_profiles(u_, grid());
      if (series) {
        const HorizonSearch found = horizons();
        report_horizon(found.horizon());
        out->write_series(series_row(d, found));
        out->write_horizons(t_, found);
      }
      if (profiles)
        out->write_profiles(t_, u_, grid(), d, horizon_shift());
    }
    if (series && on_series)
      on_series(*this);
  };
  // Writes every output time in (t_prev, t_]: on the step itself, or between the steps from
  // the Hermite interpolant of (u_prev_, dudt_prev_) and (u_, dudt_now_). The diagnostics read
  // u_ and t_, so the interpolated state stands in for them while it is written.
  auto write_due = [&](double t_prev, bool have_dense) {
    const double tol = 1e-9 * s.dt;
    while (true) {
      const double t_out = std::min(next_series(), next_profiles());
      if (t_out > t_ + tol)
        return;
      const bool series = std::abs(next_series() - t_out) <= tol;
      const bool profiles = std::abs(next_profiles() - t_out) <= tol;
      if (std::abs(t_out - t_) <= tol || !have_dense) {
        write(series, profiles);
      } else {
        hermite_interpolate(u_prev_, dudt_prev_, u_, dudt_now_, t_ - t_prev,
                            (t_out - t_prev) / (t_ - t_prev), u_out_);
        std::swap(u_, u_out_);
        const double t_step = std::exchange(t_, t_out);
        write(series, profiles);
        t_ = t_step;
        std::swap(u_, u_out_);
      }
      const bool at_end = t_out >= t_end - tol;
      if (series)
        ++k_series;
      if (profiles)
        ++k_profiles;
      if (at_end)
        return;
    }
  };

  if (!resumed_) {
    check_finite();
    update_held_horizon();
    write(true, true);
  }
  if (step_ >= s.n_steps)
    return;
  // Checkpoints at full steps (never after the shortened last one, so that a resumed run with
  // a later tmax steps exactly as an uninterrupted one).
  const double every = config_.checkpoint_every;
  // the first multiple of `every` after t (arithmetic, never a loop: it cannot stall)
  auto checkpoint_after = [every](double t) {
    return every > 0.0 ? (std::floor(t / every + 1e-9) + 1.0) * every
                       : std::numeric_limits<double>::infinity();
  };
  double next_checkpoint = checkpoint_after(t_);
  auto save = [&](const std::optional<double>& h_AH) {
    if (!out)
      return;
    const Checkpoint c = checkpoint(*out, h_AH);
    write_checkpoint(out->dir() / "checkpoint.bin", c);
    if (on_checkpoint)
      on_checkpoint(c);
  };
  const auto start = std::chrono::steady_clock::now();
  auto last_report = start;
  const bool progress = show_progress && ::isatty(STDERR_FILENO);
  dudt_now_.resize(u_.size());
  rhs_(u_, dudt_now_, t_); // RK4's first stage of the first step
  for (long n = step_ + 1; n <= s.n_steps; ++n) {
    const bool last = n == s.n_steps;
    const double t_prev = t_;
    // Keep the step's start for output between the steps (cheap copies, only when needed).
    const double t_next = last ? t_end : static_cast<double>(n) * s.dt;
    const bool dense = std::min(next_series(), next_profiles()) < t_next - 1e-9 * s.dt;
    if (dense) {
      u_prev_ = u_;
      dudt_prev_ = dudt_now_;
    }
    step(t_next - t_, dudt_now_);
    t_ = t_next; // no accumulated round-off in t
    step_ = n;
    check_finite();
    if (const long every = config_.horizon_search.every_steps; every > 0 && n % every == 0)
      update_held_horizon();
    // what a checkpoint records of the RHS before this evaluation (resume repeats it)
    const std::optional<double> h_AH_before_rhs = rhs_.horizon_radius();
    evaluations_before_rhs_ = rhs_.evaluations();
    if (!last || dense)
      rhs_(u_, dudt_now_, t_); // the next step's first stage, and d_t u for the interpolant
    write_due(t_prev, dense);
    if (!last && t_ >= next_checkpoint - 1e-9 * s.dt) {
      save(h_AH_before_rhs);
      next_checkpoint = checkpoint_after(t_);
    }
    if (const int signal = stop_signal(); signal != 0 && !last) {
      save(h_AH_before_rhs); // the run can be resumed from here
      throw Interrupted(signal, t_);
    }
    if (progress && (n % 64 == 0 || last)) {
      const auto now = std::chrono::steady_clock::now();
      if (last || now - last_report > std::chrono::milliseconds(500)) {
        last_report = now;
        const double wall = std::chrono::duration<double>(now - start).count();
        const double speed = t_ / std::max(wall, 1e-9); // simulated M per wall second
        say("\r  t = {:.2f} / {:g} M   {:.1f} M/s   {:.0f} s left   ", t_, t_end, speed,
            (t_end - t_) / std::max(speed, 1e-300));
        if (last)
          say("\n");
      }
    }
  }
}

} // namespace gbssn1d
