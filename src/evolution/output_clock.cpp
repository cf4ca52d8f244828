#include "evolution/output_clock.hpp"

#include "evolution/levels.hpp"
#include "mesh/time_interpolation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace gbssn1d {

OutputClock::OutputClock(const EvolutionConfig& config, double dt)
    : dt_series_(config.dt_series), dt_profiles_(config.dt_profiles), tmax_(config.tmax),
      tol_(1e-9 * dt) {}

double OutputClock::next_series() const {
  return std::min(static_cast<double>(k_series) * dt_series_, tmax_);
}

double OutputClock::next_profiles() const {
  return std::min(static_cast<double>(k_profiles) * dt_profiles_, tmax_);
}

std::optional<OutputClock::Due> OutputClock::due_by(double t) const {
  const double t_out = std::min(next_series(), next_profiles());
  if (t_out > t + tol_)
    return std::nullopt;
  return Due{t_out, std::abs(next_series() - t_out) <= tol_,
             std::abs(next_profiles() - t_out) <= tol_};
}

bool OutputClock::advance(const Due& d) {
  if (d.series)
    ++k_series;
  if (d.profiles)
    ++k_profiles;
  return d.t < tmax_ - tol_;
}

bool OutputClock::before(double t) const {
  return std::min(next_series(), next_profiles()) < t - tol_;
}

std::vector<double> OutputClock::times_inside(double t0, double t1) const {
  std::vector<double> times;
  auto add = [&](double cadence, long k) {
    for (;; ++k) {
      const double t = static_cast<double>(k) * cadence;
      if (t >= t1 - tol_ || t >= tmax_ - tol_)
        return;
      if (t <= t0 + tol_)
        continue;
      if (std::none_of(times.begin(), times.end(),
                       [&](double known) { return std::abs(known - t) <= tol_; }))
        times.push_back(t);
    }
  };
  add(dt_series_, k_series);
  add(dt_profiles_, k_profiles);
  std::sort(times.begin(), times.end());
  return times;
}

double checkpoint_after(double every, double t) {
  return every > 0.0 ? (std::floor(t / every + 1e-9) + 1.0) * every
                     : std::numeric_limits<double>::infinity();
}

DenseOutput::DenseOutput(const mesh::MeshLayout& layout, double chi_floor, double dt)
    : layout_(layout), chi_floor_(chi_floor), tol_(1e-9 * dt) {}

void DenseOutput::prepare(const std::vector<double>& times) {
  pending_.clear();
  for (double t : times)
    pending_.push_back(
        {t, std::vector<State>(layout_.levels()), std::vector<bool>(layout_.levels(), false)});
}

void DenseOutput::fill(std::size_t level, double t0, double dt, const State& u0,
                       const std::array<const State*, 4>& k) {
  for (auto& p : pending_) {
    if (p.filled[level] || p.t <= t0 + tol_ * 0.5 || p.t > t0 + dt + tol_)
      continue;
    const double theta = std::min((p.t - t0) / dt, 1.0);
    const mesh::StageWeights w = mesh::dense_output_weights(theta, dt);
    State& out = p.u[level];
    out.fit(u0);
    for (std::size_t i = 0; i < u0.size(); ++i)
      out[i] = w[0] * u0[i] + w[1] * (*k[0])[i] + w[2] * (*k[1])[i] + w[3] * (*k[2])[i]
               + w[4] * (*k[3])[i];
    apply_chi_floor(out, layout_.grid(level), chi_floor_);
    p.filled[level] = true;
  }
}

std::vector<State>& DenseOutput::at(double t) {
  const auto p = std::find_if(pending_.begin(), pending_.end(),
                              [&](const Pending& q) { return std::abs(q.t - t) <= tol_; });
  if (p == pending_.end()
      || std::find(p->filled.begin(), p->filled.end(), false) != p->filled.end())
    throw std::logic_error(fmt::format("no dense output of every level at t = {}", t));
  return p->u;
}

} // namespace gbssn1d
