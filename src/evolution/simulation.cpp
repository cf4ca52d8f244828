#include "evolution/simulation.hpp"

#include "core/console.hpp"
#include "core/stop_signal.hpp"
#include "grid/interpolation.hpp"

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

Schedule make_schedule(const EvolutionConfig& config, double dt) {
  Schedule s;
  s.dt = dt;
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

mesh::MeshLayout make_layout(const EvolutionConfig& config) {
  if (config.refinement.levels > 1)
    return mesh::MeshLayout(config.grid.rmax, config.grid.N, config.refinement.levels,
                            config.grid.fd_order);
  return mesh::MeshLayout(make_grid(config.grid).map(), config.grid.N, 1, config.grid.fd_order);
}

mesh::StepperOptions stepper_options(const EvolutionConfig& config) {
  return mesh::StepperOptions{.time = config.refinement.time,
                              .subcycling = config.refinement.subcycling,
                              .cfl = config.cfl,
                              .dt_max = config.refinement.dt_max};
}

namespace {

/// One RHS per level; its substage searches go to `locate(level, u, grid, seed, t)`.
using Locate =
    std::function<std::optional<double>(std::size_t, const State&, const Grid&, double, double)>;
std::vector<GbssnRhs> level_rhs(const EvolutionConfig& config, const mesh::MeshLayout& layout,
                                const Locate& locate) {
  std::vector<GbssnRhs> rhs;
  for (std::size_t l = 0; l < layout.levels(); ++l) {
    RhsParams r = config.rhs;
    r.horizon_shift.locate = [l, locate](const State& u, const Grid& grid, double seed, double t) {
      return locate(l, u, grid, seed, t);
    };
    rhs.emplace_back(layout.grid(l), r);
  }
  return rhs;
}

/// Diagnostic copies: they never search (their h_AH is set from Simulation::horizon_radius()).
std::vector<GbssnRhs> diagnostic_copies(const EvolutionConfig& config,
                                        const mesh::MeshLayout& layout) {
  std::vector<GbssnRhs> rhs;
  RhsParams r = config.rhs;
  r.horizon_shift.search_every_substage = false;
  r.horizon_shift.locate = nullptr;
  using V = HorizonShiftParams::Variant;
  if (r.horizon_shift.variant == V::midstep_update || r.horizon_shift.variant == V::box_substage)
    r.horizon_shift.variant = V::consistent; // they differ in searches only
  for (std::size_t l = 0; l < layout.levels(); ++l)
    rhs.emplace_back(layout.grid(l), r);
  return rhs;
}

std::vector<State> initial_levels(const mesh::MeshLayout& layout, const InitialDataParams& id) {
  std::vector<State> u;
  for (std::size_t l = 0; l < layout.levels(); ++l)
    u.push_back(initial_data(layout.grid(l), id));
  return u;
}

std::vector<mesh::LevelRhs> level_functors(std::vector<GbssnRhs>& rhs) {
  std::vector<mesh::LevelRhs> f;
  for (auto& r : rhs)
    f.emplace_back([&r](const State& u, State& dudt, double t) { r(u, dudt, t); });
  return f;
}

} // namespace

Simulation::Simulation(const EvolutionConfig& config)
    : config_(config), layout_(make_layout(config)), composite_(layout_),
      rhs_(level_rhs(config_, layout_,
                     [this](std::size_t l, const State& u, const Grid& g, double seed, double t) {
                       return locate(l, u, g, seed, t);
                     })),
      diagnostic_rhs_(diagnostic_copies(config_, layout_)), dudt_(layout_.levels()),
      levels_u_(initial_levels(layout_, config.initial_data)),
      schedule_(make_schedule(config, mesh::hierarchy_dt(layout_, stepper_options(config)))),
      stepper_(layout_, level_functors(rhs_), stepper_options(config)) {
  stepper_.after_step = [this](std::size_t l, State& u) {
    apply_chi_floor(u, layout_.grid(l), config_.chi_floor);
  };
  for (std::size_t k = 0; k < composite_.size(); ++k)
    composite_levels_.push_back(composite_.level(k));
  if (layout_.levels() > 1)
    stepper_.on_level_step = [this](std::size_t l, double t0, double dt, const State& u0,
                                    const std::array<const State*, 4>& k) {
      fill_pending(l, t0, dt, u0, k);
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
         && config_.refinement.time == mesh::TimeInterpolation::quadratic;
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

template <class Search>
auto Simulation::with_time(Search search) const {
  try {
    return search();
  } catch (const HorizonFinderError& e) {
    throw HorizonFinderError(fmt::format("{} (t = {:.6g})", e.what(), t_));
  }
}

bool Simulation::extrapolated_horizon() const {
  const auto& hs = config_.rhs.horizon_shift;
  return layout_.levels() > 1 && hs.active() && !hs.prescribed()
         && config_.horizon_search.every_steps == 0
         && hs.variant != HorizonShiftParams::Variant::box_substage;
}

std::optional<double> Simulation::locate(std::size_t level, const State& u, const Grid& grid,
                                         double seed, double t) {
  if (extrapolated_horizon())
    return horizon_radius_at(t);
  // a single grid, or the study variant box_substage: the box holding the horizon searches on
  // its own stage state, the other boxes read its latest value
  if (layout_.levels() > 1 && level != horizon_level())
    return shared_h_AH_;
  try {
    const auto found = find_horizon_near(u, grid, config_.horizon_search.finder, seed);
    shared_h_AH_ = found ? std::optional<double>(found->r) : std::nullopt;
    return shared_h_AH_;
  } catch (const HorizonFinderError& e) {
    throw HorizonFinderError(fmt::format("{} (RK substage at t = {:.6g})", e.what(), t));
  }
}

std::optional<double> Simulation::horizon_radius_at(double t) const {
  const auto& h = h_AH_history_;
  if (h.empty())
    return std::nullopt;
  if (!config_.horizon_search.in_window(t)) // no searches: the last radius is held
    return h.back()[1];
  // the Lagrange polynomial through the last (up to four) radii, at t
  double sum = 0.0;
  for (std::size_t j = 0; j < h.size(); ++j) {
    double w = 1.0;
    for (std::size_t m = 0; m < h.size(); ++m)
      if (m != j)
        w *= (t - h[m][0]) / (h[j][0] - h[m][0]);
    sum += w * h[j][1];
  }
  return sum;
}

void Simulation::search_at_step() {
  if (!extrapolated_horizon() || !config_.horizon_search.in_window(t_))
    return;
  const auto& hs = config_.rhs.horizon_shift;
  const std::size_t l = horizon_level();
  const auto found = with_time([&] {
    return find_horizon_near(levels_u_[l], layout_.grid(l), config_.horizon_search.finder,
                             horizon_radius_at(t_).value_or(hs.h));
  });
  if (!found) { // beta_H = 0 until a horizon is found again
    h_AH_history_.clear();
  } else {
    if (!h_AH_history_.empty() && h_AH_history_.back()[0] == t_)
      h_AH_history_.pop_back(); // found again at the same time (a resumed run's first step)
    h_AH_history_.push_back(std::array<double, 2>{t_, found->r});
    if (h_AH_history_.size() > 4)
      h_AH_history_.erase(h_AH_history_.begin());
  }
  shared_h_AH_ = found ? std::optional<double>(found->r) : std::nullopt;
}

std::size_t Simulation::horizon_level() const {
  if (layout_.levels() == 1)
    return 0;
  const double r = shared_h_AH_.value_or(standard_horizon_radius * config_.initial_data.M);
  return layout_.finest_level_covering(r, RefinementSettings::horizon_margin_cells);
}

HorizonSearch Simulation::horizons() const {
  const HorizonFinderParams& finder = config_.horizon_search.finder;
  if (layout_.levels() == 1)
    return with_time([&] { return find_horizons(levels_u_[0], grid(), finder); });
  // each level searches the part of the composite it supplies: r beyond its child's extent
  HorizonSearch all;
  for (std::size_t l = 0; l < layout_.levels(); ++l) {
    HorizonFinderParams p = finder;
    if (l + 1 < layout_.levels())
      p.r_min = std::max(p.r_min, layout_.extent(l + 1));
    HorizonSearch found =
        with_time([&] { return find_horizons(levels_u_[l], layout_.grid(l), p); });
    for (auto& s : found.surfaces) {
      s.level = l;
      all.surfaces.push_back(s);
    }
  }
  std::sort(all.surfaces.begin(), all.surfaces.end(),
            [](const MarginalSurface& a, const MarginalSurface& b) { return a.r > b.r; });
  return all;
}

std::optional<double> Simulation::horizon_radius() {
  const auto& hs = config_.rhs.horizon_shift;
  if (!hs.active())
    return std::nullopt;
  if (hs.prescribed())
    return hs.prescribed_h_AH(t_);
  if (extrapolated_horizon())
    return horizon_radius_at(t_);
  const std::size_t l = horizon_level();
  if (config_.horizon_search.every_steps == 0 && config_.horizon_search.in_window(t_)) {
    const auto found = with_time([&] {
      return find_horizon_near(levels_u_[l], layout_.grid(l), config_.horizon_search.finder,
                               rhs_[l].horizon_radius().value_or(hs.h));
    });
    return found ? std::optional<double>(found->r) : std::nullopt;
  }
  return rhs_[l].horizon_radius();
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

void Simulation::update_held_horizon() {
  const auto& hs = config_.rhs.horizon_shift;
  if (!hs.active() || hs.prescribed() || config_.horizon_search.every_steps == 0
      || !config_.horizon_search.in_window(t_)
      || hs.variant == HorizonShiftParams::Variant::midstep_update) // searched inside the RHS
    return;
  const std::size_t l = horizon_level();
  const auto found = with_time([&] {
    return find_horizon_near(levels_u_[l], layout_.grid(l), config_.horizon_search.finder,
                             rhs_[l].horizon_radius().value_or(hs.h));
  });
  // Without a horizon the held value is dropped: beta_H = 0 until one is found. Every level
  // holds the same value.
  shared_h_AH_ = found ? std::optional<double>(found->r) : std::nullopt;
  for (auto& rhs : rhs_)
    rhs.set_horizon_radius(shared_h_AH_);
}

std::vector<DerivedProfiles> Simulation::level_profiles() const {
  std::vector<DerivedProfiles> d;
  for (std::size_t l = 0; l < layout_.levels(); ++l)
    d.push_back(derived_profiles(levels_u_[l], layout_.grid(l)));
  return d;
}

DerivedProfiles Simulation::composite_profiles(const std::vector<DerivedProfiles>& levels) const {
  if (layout_.levels() == 1)
    return levels.front();
  auto gather = [&](std::vector<double> DerivedProfiles::*member) {
    std::vector<std::span<const double>> arrays;
    for (const auto& d : levels)
      arrays.emplace_back(d.*member);
    return composite_.gather_interior(arrays);
  };
  DerivedProfiles c;
  c.H = gather(&DerivedProfiles::H);
  c.M_r = gather(&DerivedProfiles::M_r);
  c.G_r = gather(&DerivedProfiles::G_r);
  c.R_areal = gather(&DerivedProfiles::R_areal);
  c.Theta_plus = gather(&DerivedProfiles::Theta_plus);
  return c;
}

namespace {
/// Samples at radius r are interpolated on the finest level on which r lies this many cells
/// inside the edge: the 6-point stencil (k - 2 ... k + 3) then reads interior cells only.
constexpr double sample_margin_cells = 4.0;
} // namespace

double Simulation::at_radius(Var v, double r) const {
  const std::size_t l = layout_.finest_level_covering(r, sample_margin_cells);
  return interpolate_at_radius(layout_.grid(l), field(levels_u_[l], layout_.grid(l), v), r);
}

double Simulation::H_at_radius(const std::vector<DerivedProfiles>& levels, double r) const {
  const std::size_t l = layout_.finest_level_covering(r, sample_margin_cells);
  const Grid& g = layout_.grid(l);
  // the interior values with their nearest neighbours continued into the ghosts
  std::vector<double> f(g.n_total());
  const auto& H = levels.at(l).H;
  for (std::size_t i = 0; i < g.n_total(); ++i) {
    const std::size_t k = std::clamp(i, g.first_interior(), g.end_interior() - 1);
    f[i] = H[k - g.first_interior()];
  }
  return interpolate_at_radius(g, f, r);
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
  const Grid& g = composite_.grid();
  const std::size_t finest = layout_.levels() - 1;
  const double inf = std::numeric_limits<double>::infinity();
  SeriesRow row;
  row.t = t_;
  row.alpha_center = central_value(field(levels_u_[finest], layout_.grid(finest), Var::alpha),
                                   layout_.grid(finest));
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
  // d_t alpha on every level with the h_AH the evolution would use now
  const std::optional<double> h_AH = horizon_radius();
  std::vector<std::span<const double>> dt_alpha_levels;
  for (std::size_t l = 0; l < layout_.levels(); ++l) {
    diagnostic_rhs_[l].set_horizon_radius(h_AH);
    diagnostic_rhs_[l](levels_u_[l], dudt_[l], t_);
    dt_alpha_levels.push_back(field(std::as_const(dudt_[l]), layout_.grid(l), Var::alpha));
  }
  const std::vector<double> dt_alpha = composite_.gather(dt_alpha_levels);
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
  std::string facts =
      fmt::format("dt = {:.17g}\nsteps = {}\ndr-min = {:.17g}\n", schedule_.dt, schedule_.n_steps,
                  layout_.grid(layout_.levels() - 1).min_spacing());
  if (layout_.levels() > 1)
    for (std::size_t l = 0; l < layout_.levels(); ++l)
      facts +=
          fmt::format("level {} = r <= {:.17g}, dr = {:.17g}, dt = {:.17g}\n", l, layout_.extent(l),
                      layout_.spacing(l), stepper_.level_dt(l, schedule_.dt));
  return facts;
}

void Simulation::step(double dt) {
  stepper_.step(levels_u_, t_, dt); // RK4, then the chi floor (stepper_.after_step)
  t_ += dt;
}

void Simulation::step(double dt, const State& dudt) {
  stepper_.step(levels_u_, t_, dt, dudt);
  t_ += dt;
}

void Simulation::prepare_pending(double t0, double t1) {
  pending_.clear();
  const double tol = 1e-9 * schedule_.dt;
  auto add = [&](double cadence, long k) {
    for (;; ++k) {
      const double t = static_cast<double>(k) * cadence;
      if (t >= t1 - tol || t >= config_.tmax - tol)
        return;
      if (t <= t0 + tol)
        continue;
      const bool known = std::any_of(pending_.begin(), pending_.end(), [&](const PendingOutput& p) {
        return std::abs(p.t - t) <= tol;
      });
      if (!known)
        pending_.push_back({t, {}, std::vector<bool>(layout_.levels(), false)});
    }
  };
  add(config_.dt_series, k_series_);
  add(config_.dt_profiles, k_profiles_);
  std::sort(pending_.begin(), pending_.end(),
            [](const PendingOutput& a, const PendingOutput& b) { return a.t < b.t; });
  for (auto& p : pending_)
    p.u.resize(layout_.levels());
}

void Simulation::fill_pending(std::size_t level, double t0, double dt, const State& u0,
                              const std::array<const State*, 4>& k) {
  const double tol = 1e-9 * schedule_.dt;
  for (auto& p : pending_) {
    if (p.filled[level] || p.t <= t0 + tol * 0.5 || p.t > t0 + dt + tol)
      continue;
    const double theta = std::min((p.t - t0) / dt, 1.0);
    const mesh::StageWeights w = mesh::dense_output_weights(theta, dt);
    State& out = p.u[level];
    out.resize(u0.size());
    for (std::size_t i = 0; i < u0.size(); ++i)
      out[i] = w[0] * u0[i] + w[1] * (*k[0])[i] + w[2] * (*k[1])[i] + w[3] * (*k[2])[i]
               + w[4] * (*k[3])[i];
    apply_chi_floor(out, layout_.grid(level), config_.chi_floor);
    p.filled[level] = true;
  }
}

void apply_chi_floor(State& u, const Grid& grid, double chi_floor) {
  if (chi_floor <= 0.0)
    return;
  for (double& chi : field(u, grid, Var::chi))
    chi = std::max(chi, chi_floor);
}

void Simulation::check_finite() const {
  for (std::size_t l = 0; l < layout_.levels(); ++l) {
    const Grid& g = layout_.grid(l);
    const State& u = levels_u_[l];
    const std::string where = layout_.levels() > 1 ? fmt::format(" (box {})", l) : "";
    for (std::size_t i = g.first_interior(); i < g.n_total(); ++i)
      for (const auto& entry : registry)
        if (!std::isfinite(field(u, g, entry.var)[i]))
          throw NonFiniteError(t_, g.r()[i], std::string(entry.name) + where);
    const auto chi = field(u, g, Var::chi), alpha = field(u, g, Var::alpha);
    for (std::size_t i = g.first_interior(); i < g.end_interior(); ++i) {
      if (!(chi[i] > 0.0))
        throw NonFiniteError(t_, g.r()[i], "chi" + where, chi[i], "must be > 0; see --chi-floor");
      if (alpha[i] < alpha_min || alpha[i] > alpha_max)
        throw NonFiniteError(t_, g.r()[i], "alpha" + where, alpha[i],
                             fmt::format("must lie in [{}, {}]", alpha_min, alpha_max));
    }
  }
}

namespace {

/// Ghosts per side before the finite-difference order became a choice (checkpoint formats 2
/// and 3 of earlier versions).
constexpr std::size_t legacy_ghosts = 3;

/// `u` re-laid out from legacy_ghosts to Grid::n_ghost ghosts per side, if it has the legacy
/// size for `grid`: the interior and the old outer ghosts are kept, the origin ghosts refilled
/// by parity, the new outermost ghosts copied from the last old one. At 4th order nothing reads
/// them but their own boundary condition, so the run continues as it would have.
void widen_legacy_ghosts(State& u, const Grid& grid) {
  const std::size_t n = grid.n_interior(), old_total = n + 2 * legacy_ghosts;
  if (u.size() != n_vars * old_total || grid.n_total() == old_total)
    return;
  State w(n_vars * grid.n_total(), 0.0);
  for (std::size_t v = 0; v < n_vars; ++v) {
    const double* from = u.data() + v * old_total;
    double* to = w.data() + v * grid.n_total();
    for (std::size_t k = 0; k < n + legacy_ghosts; ++k) // interior and the old outer ghosts
      to[grid.first_interior() + k] = from[legacy_ghosts + k];
    for (std::size_t k = n + legacy_ghosts; k < n + Grid::n_ghost; ++k)
      to[grid.first_interior() + k] = from[legacy_ghosts + n + legacy_ghosts - 1];
  }
  fill_origin_ghosts(w, grid);
  u = std::move(w);
}

} // namespace

void Simulation::restore(const Checkpoint& checkpoint) {
  const std::size_t n_levels = layout_.levels();
  Checkpoint c = checkpoint;
  if (c.finer.size() + 1 == n_levels) {
    widen_legacy_ghosts(c.u, layout_.grid(0));
    for (std::size_t l = 1; l < n_levels; ++l)
      widen_legacy_ghosts(c.finer[l - 1], layout_.grid(l));
    for (std::size_t l = 0; l < c.history.size() && l < n_levels; ++l)
      for (auto& h : c.history[l])
        widen_legacy_ghosts(h.u, layout_.grid(l));
  }
  if (c.finer.size() + 1 != n_levels)
    throw CheckpointError(
        fmt::format("the checkpoint has {} levels, this grid {}", c.finer.size() + 1, n_levels));
  for (std::size_t l = 0; l < n_levels; ++l) {
    const State& u = l == 0 ? c.u : c.finer[l - 1];
    if (u.size() != levels_u_[l].size())
      throw CheckpointError(fmt::format("the checkpoint has {} values{}, this grid {}", u.size(),
                                        n_levels > 1 ? fmt::format(" on level {}", l) : "",
                                        levels_u_[l].size()));
  }
  if (n_levels > 1) {
    if (c.level_h_AH.size() != n_levels || c.history.size() != n_levels)
      throw CheckpointError("the checkpoint's levels are incomplete");
    for (std::size_t l = 0; l < n_levels; ++l) {
      // quadratic interpolation keeps two earlier time levels of every level but the finest
      const std::size_t expected =
          config_.refinement.time == mesh::TimeInterpolation::quadratic && l + 1 < n_levels ? 2 : 0;
      if (c.history[l].size() != expected)
        throw CheckpointError(fmt::format("the checkpoint holds {} time levels of level {}, this "
                                          "run keeps {}",
                                          c.history[l].size(), l, expected));
      for (const auto& h : c.history[l])
        if (h.u.size() != levels_u_[l].size() || !(h.t < c.t))
          throw CheckpointError(fmt::format(
              "the checkpoint's time level t = {} of level {} is not this run's", h.t, l));
      if (c.level_h_AH[l] && !(std::isfinite(*c.level_h_AH[l]) && *c.level_h_AH[l] > 0.0))
        throw CheckpointError(fmt::format("the checkpoint's horizon radius {} of level {} is "
                                          "not a radius",
                                          *c.level_h_AH[l], l));
    }
  }
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
  if (c.evaluations != initial_evaluations_[0] + 4 * static_cast<std::uint64_t>(c.step))
    throw CheckpointError(fmt::format("the checkpoint's RHS count {} is not {} + 4 x step {}",
                                      c.evaluations, initial_evaluations_[0], c.step));
  for (const auto& h : {c.h_AH, c.shared_h_AH})
    if (h && !(std::isfinite(*h) && *h > 0.0))
      throw CheckpointError(fmt::format("the checkpoint's horizon radius {} is not a radius", *h));
  levels_u_[0] = c.u;
  for (std::size_t l = 1; l < n_levels; ++l)
    levels_u_[l] = c.finer[l - 1];
  t_ = c.t;
  step_ = c.step;
  k_series_ = c.k_series;
  k_profiles_ = c.k_profiles;
  rhs_[0].set_horizon_radius(c.h_AH);
  rhs_[0].set_evaluations(c.evaluations);
  if (n_levels > 1) {
    shared_h_AH_ = c.shared_h_AH;
    h_AH_history_ = c.h_AH_history;
    for (std::size_t l = 1; l < n_levels; ++l) {
      rhs_[l].set_horizon_radius(c.level_h_AH[l]);
      // level l takes steps(l) steps of 4 evaluations per step of the hierarchy
      const std::uint64_t n =
          initial_evaluations_[l]
          + 4 * static_cast<std::uint64_t>(c.step) * static_cast<std::uint64_t>(stepper_.steps(l));
      rhs_[l].set_evaluations(n);
      stepper_.set_evaluations(l, n);
    }
    for (std::size_t l = 0; l < n_levels; ++l)
      stepper_.set_history(l, c.history[l]);
  } else {
    shared_h_AH_ = c.h_AH;
  }
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
  c.u = levels_u_[0];
  if (layout_.levels() > 1) {
    c.finer.assign(levels_u_.begin() + 1, levels_u_.end());
    c.shared_h_AH = shared_h_AH_before_rhs_; // before the next step's first RHS, as h_AH
    c.h_AH_history = h_AH_history_;
    for (std::size_t l = 0; l < layout_.levels(); ++l) {
      c.level_h_AH.push_back(l == 0 ? h_AH_before_rhs : rhs_[l].horizon_radius());
      c.history.push_back(stepper_.history(l));
    }
  }
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
  };
  // Writes every output time in (t_prev, t_]: on the step itself, or between the steps from
  // each level's dense output (boxes, pending_) or the Hermite interpolant of (u_prev_,
  // dudt_prev_) and (the state, dudt_now_) (a single grid). The diagnostics read the levels'
  // states and t_, so the interpolated states stand in for them while they are written.
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
      } else if (layout_.levels() > 1) {
        // every level's dense output at t_out, the fine boundaries from their parents
        const auto p = std::find_if(pending_.begin(), pending_.end(), [&](const PendingOutput& q) {
          return std::abs(q.t - t_out) <= tol;
        });
        if (p == pending_.end()
            || std::find(p->filled.begin(), p->filled.end(), false) != p->filled.end())
          throw std::logic_error(fmt::format("no dense output of every level at t = {}", t_out));
        std::swap(levels_u_, p->u);
        stepper_.fill_ghosts(levels_u_);
        const double t_step = std::exchange(t_, t_out);
        write(series, profiles);
        t_ = t_step;
        std::swap(levels_u_, p->u);
      } else { // a single grid
        hermite_interpolate(u_prev_, dudt_prev_, levels_u_[0], dudt_now_, t_ - t_prev,
                            (t_out - t_prev) / (t_ - t_prev), u_out_);
        std::swap(levels_u_[0], u_out_);
        const double t_step = std::exchange(t_, t_out);
        write(series, profiles);
        t_ = t_step;
        std::swap(levels_u_[0], u_out_);
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
    search_at_step();
    if (layout_.levels() > 1
        && config_.rhs.horizon_shift.variant == HorizonShiftParams::Variant::box_substage) {
      // every box starts from the radius found on the box holding the horizon
      const std::size_t l = horizon_level();
      const auto found = with_time([&] {
        return find_horizon_near(levels_u_[l], layout_.grid(l), config_.horizon_search.finder,
                                 config_.rhs.horizon_shift.h);
      });
      shared_h_AH_ = found ? std::optional<double>(found->r) : std::nullopt;
    }
    // The stepper was initialised before the horizon was found: quadratic time interpolation's
    // earlier time levels (one RK4 step backwards) are made again with the horizon shift that
    // the evolution will use (without it they lack beta_H, an O(dt) inconsistency at every fine
    // boundary in the first step that the Gamma-driver keeps)
    if (reinitialises())
      stepper_.initialise(levels_u_, t_);
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
  shared_h_AH_before_rhs_ = shared_h_AH_;
  dudt_now_.resize(levels_u_[0].size());
  rhs_[0](levels_u_[0], dudt_now_, t_); // RK4's first stage of the first step
  for (long n = step_ + 1; n <= s.n_steps; ++n) {
    const bool last = n == s.n_steps;
    const double t_prev = t_;
    // Keep the step's start for output between the steps (cheap copies, only when needed).
    const double t_next = last ? t_end : static_cast<double>(n) * s.dt;
    const bool dense = std::min(next_series(), next_profiles()) < t_next - 1e-9 * s.dt;
    if (dense && layout_.levels() > 1) {
      prepare_pending(t_, t_next);
    } else if (dense) {
      u_prev_ = levels_u_[0];
      dudt_prev_ = dudt_now_;
    }
    step(t_next - t_, dudt_now_);
    t_ = t_next; // no accumulated round-off in t
    step_ = n;
    check_finite();
    if (const long every = config_.horizon_search.every_steps; every > 0 && n % every == 0)
      update_held_horizon();
    search_at_step();
    // what a checkpoint records of the RHS before this evaluation (resume repeats it)
    const std::optional<double> h_AH_before_rhs = rhs_[0].horizon_radius();
    shared_h_AH_before_rhs_ = shared_h_AH_;
    evaluations_before_rhs_ = rhs_[0].evaluations();
    if (!last || dense)
      rhs_[0](levels_u_[0], dudt_now_, t_); // the next step's first stage, and d_t u for
                                            // the interpolant
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
