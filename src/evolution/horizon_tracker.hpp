// The apparent horizon's coordinate radius h_AH that the horizon-adjusting shift beta_H uses
// (docs/gbssn1d-equations.md, the horizon-adjusting shift). What is measured (HorizonProbe: the
// finder on a level's or an RK stage's state) is kept apart from what is controlled: the h_AH
// each level's right-hand side is handed, decided by one strategy per mode, made once from the
// configuration by make_horizon_tracker, as SpECTRE's control systems separate measurement from
// the control they feed:
//   off           no horizon shift (rahA = 0): h_AH is never needed;
//   prescribed    open loop, h_AH(t) from a file, no searches;
//   held          a search every n steps (or once a step), or after the first step at or past
//                 each multiple of a fixed interval T of evolution time (--ah-interval), the
//                 radius held between them (the midstep-update variant: inside the RHS, at the
//                 2nd substage of every n-th step);
//   substage      a single grid, or boxes with the box-substage variant: the RHS of the level
//                 holding the horizon searches on every RK stage's state, the others read it;
//   extrapolated  boxes, searches every substage (the default), or any grid with
//                 --ah-every extrapolated: a search (on the box holding the horizon) after each
//                 step of the hierarchy, and h_AH at any stage's time from the Lagrange
//                 polynomial through the last (up to) four radii (error O(dt^4));
//                 evolution/horizon_extrapolated.hpp, with the start's pilot for subcycled boxes.
// Until a first horizon is found beta_H = 0; a horizon found and then lost by a search stops the
// run (HorizonLostError), rather than letting beta_H switch off unsaid.
#pragma once

#include "evolution/evolution_config.hpp"
#include "evolution/horizon_probe.hpp"
#include "gbssn/rhs.hpp"
#include "mesh/layout.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace gbssn1d {

class HorizonTracker {
public:
  enum class Mode { off, prescribed, held, substage, extrapolated };

  /// Reads `levels` and sets the h_AH of `rhs` (one per level); both outlive the tracker.
  HorizonTracker(const EvolutionConfig& config, const mesh::MeshLayout& layout,
                 const std::vector<State>& levels, std::vector<GbssnRhs>& rhs)
      : config_(config), probe_(config, layout, levels), rhs_(rhs) {}
  virtual ~HorizonTracker() = default;
  HorizonTracker(const HorizonTracker&) = delete;
  HorizonTracker& operator=(const HorizonTracker&) = delete;

  virtual Mode mode() const = 0;

  /// h_AH for an evaluation of level `level`'s RHS on the stage state u at time t, the
  /// evaluation'th of that RHS, which holds `held` so far (GbssnRhs::HorizonSource).
  virtual std::optional<double> at_evaluation(std::size_t level, const State& u, const Grid& grid,
                                              double t, std::uint64_t evaluation,
                                              std::optional<double> held) = 0;
  /// Before the first step of a run (not a resumed one): a pilot run, where the mode needs one
  /// (horizon_extrapolated.hpp). dt is the hierarchy's step, finest_steps the finest level's
  /// steps in it.
  virtual void before_run(double /*t*/, double /*dt*/, long /*finest_steps*/) {}
  /// Before the first step at time t: the mode's first search, and with box-substage every
  /// box's starting radius.
  void start(double t);
  /// After step n of the hierarchy, from t_before to t: the searches due.
  virtual void after_step(long /*n*/, double /*t_before*/, double /*t*/) {}

  /// h_AH for the state at time t, as the evolution's RHS would use it now; nullopt: no
  /// horizon, beta_H = 0.
  virtual std::optional<double> radius(double t) = 0;
  /// The level searched: the finest on which the horizon (or, before one is found, the
  /// standard radius 0.8304 M) lies well inside; 0 for a single grid.
  std::size_t level() const { return probe_.level(shared_); }

  /// What a checkpoint keeps: the shared radius before the coming RHS, and the extrapolated
  /// mode's history (empty in the others).
  std::optional<double> shared_before_rhs() const { return shared_before_rhs_; }
  virtual const std::vector<std::array<double, 2>>& history() const;
  /// Records the shared radius as it is before the next RHS evaluation (for checkpoints).
  void mark_before_rhs() { shared_before_rhs_ = shared_; }
  /// Continues from a checkpoint's radius and history.
  virtual void restore(const std::optional<double>& shared,
                       const std::vector<std::array<double, 2>>& history);

protected:
  /// The mode's part of start().
  virtual void on_start(double /*t*/) {}
  /// A search on level `level`'s RK stage state near `seed`: on a single grid, or on the box
  /// holding the horizon, whose radius every other box reads. A horizon lost stops the run.
  std::optional<double> locate(std::size_t level, const State& u, const Grid& grid, double seed,
                               double t);
  /// A search on the level holding the horizon near the radius its RHS holds: h_AH now.
  std::optional<double> search_now(double t) const;

  const EvolutionConfig& config_;
  HorizonProbe probe_;
  std::vector<GbssnRhs>& rhs_;
  /// The radius every level's horizon shift uses, found on level()'s state; the others read it.
  std::optional<double> shared_;
  std::optional<double> shared_before_rhs_;
};

/// The strategy of the configuration's mode. Reads `levels` and sets the h_AH of `rhs` (one per
/// level); config, layout, levels and rhs outlive it.
std::unique_ptr<HorizonTracker> make_horizon_tracker(const EvolutionConfig& config,
                                                     const mesh::MeshLayout& layout,
                                                     const std::vector<State>& levels,
                                                     std::vector<GbssnRhs>& rhs);

} // namespace gbssn1d
