// The apparent horizon's coordinate radius h_AH that the horizon-adjusting shift beta_H uses
// (docs/gbssn1d-equations.md, the horizon-adjusting shift): measured on the state, held or
// extrapolated between measurements, and handed to every level's right-hand side. The mode is
// decided once from the configuration, as SpECTRE's control systems separate measurement from
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
//                 polynomial through the last (up to) four radii (error O(dt^4)).
// Until a first horizon is found beta_H = 0; a horizon found and then lost by a search stops the
// run (HorizonLostError), rather than letting beta_H switch off unsaid.
#pragma once

#include "evolution/evolution_config.hpp"
#include "gbssn/rhs.hpp"
#include "horizon/apparent_horizon.hpp"
#include "mesh/layout.hpp"

#include <array>
#include <optional>
#include <vector>

namespace gbssn1d {

/// The apparent horizon the horizon shift was following is no longer found: beta_H would switch
/// off and the run go on in another gauge without a word, so the run stops instead, as on a
/// finder failure (a HorizonFinderError: exit status 3, the output up to then kept). The message
/// names the time and the last radius.
class HorizonLostError : public HorizonFinderError {
public:
  using HorizonFinderError::HorizonFinderError;
};

class HorizonTracker {
public:
  enum class Mode { off, prescribed, held, substage, extrapolated };

  /// Reads `levels` and sets the h_AH of `rhs` (one per level); both outlive the tracker.
  HorizonTracker(const EvolutionConfig& config, const mesh::MeshLayout& layout,
                 const std::vector<State>& levels, std::vector<GbssnRhs>& rhs);

  Mode mode() const { return mode_; }

  /// h_AH for an evaluation of level `level`'s RHS on the stage state u at time t, the
  /// evaluation'th of that RHS, which holds `held` so far (GbssnRhs::HorizonSource): the
  /// prescribed value, a search or extrapolation in the search window (modes substage and
  /// extrapolated, and the midstep-update variant's stage), else `held`.
  std::optional<double> at_evaluation(std::size_t level, const State& u, const Grid& grid, double t,
                                      std::uint64_t evaluation, std::optional<double> held);
  /// Before the first step at time t: the first searches of the held and extrapolated modes,
  /// and with box-substage every box's starting radius.
  void start(double t);
  /// After step n of the hierarchy, from t_before to t: the searches due (held every n steps
  /// or every interval T; the extrapolated mode's search).
  void after_step(long n, double t_before, double t);

  /// h_AH for the state at time t, as the evolution's RHS would use it now (a search for the
  /// substage mode); nullopt: no horizon, beta_H = 0.
  std::optional<double> radius(double t);
  /// The level searched: the finest on which the horizon (or, before one is found, the
  /// standard radius 0.8304 M) lies well inside; 0 for a single grid.
  std::size_t level() const;

  /// What a checkpoint keeps (boxes): the shared radius before the coming RHS, and the history.
  std::optional<double> shared_before_rhs() const { return shared_before_rhs_; }
  const std::vector<std::array<double, 2>>& history() const { return history_; }
  /// Records the shared radius as it is before the next RHS evaluation (for checkpoints).
  void mark_before_rhs() { shared_before_rhs_ = shared_; }
  /// Continues from a checkpoint's radius and history.
  void restore(const std::optional<double>& shared,
               const std::vector<std::array<double, 2>>& history);

  /// Subcycled boxes in the extrapolated mode: over the first steps of the hierarchy its history
  /// holds fewer than four radii, and the coarse boxes step first, up to a step of the hierarchy
  /// ahead of the last search. That step is capped by the coarse boxes' damping limit and is
  /// the same at every N (0.5 M at eta = 2/M), so the constant, linear and quadratic
  /// extrapolations of those steps put an offset into the gauge that N does not reduce (1.3e-4
  /// in r_AH: docs/horizon-shift-study.md, Sec. 6.7). Whether the run starts from a pilot.
  bool wants_start_nodes() const;
  /// The pilot's radii (t, h_AH) at every step of the finest box from t = 0 (time-ordered):
  /// while t <= their last time, h_AH(t) is the cubic through the four nodes around t.
  void seed_start(std::vector<std::array<double, 2>> nodes);

private:
  /// A search at an RK substage of `level` near `seed` (modes substage and extrapolated).
  std::optional<double> locate(std::size_t level, const State& u, const Grid& grid, double seed,
                               double t);
  /// Whether an RK stage's h_AH is searched for on the stage state: the substage mode, and a
  /// single grid's extrapolated mode until its history holds four radii.
  bool searches_stages() const;
  /// h_AH at time t from the history (extrapolated mode).
  std::optional<double> extrapolated_at(double t) const;
  /// A search near `seed` on level l's state; a HorizonFinderError gets the time added.
  std::optional<MarginalSurface> search(std::size_t l, double seed, double t) const;
  /// Whether the held mode searches after step n (from t_before to t): every n-th step, or the
  /// first step at or past a multiple of the interval. From the times alone, so that a resumed
  /// run searches where an uninterrupted one does.
  bool held_search_due(long n, double t_before, double t) const;
  void update_held(double t);
  void search_at_step(double t);
  /// Throws HorizonLostError: at time t no horizon was found on level l, last at radius `last`.
  [[noreturn]] void lost(std::size_t l, double t, double last) const;

  const EvolutionConfig& config_;
  const mesh::MeshLayout& layout_;
  const std::vector<State>& levels_;
  std::vector<GbssnRhs>& rhs_;
  Mode mode_;
  /// The radius every level's horizon shift uses, found on level()'s state; the others read it.
  std::optional<double> shared_;
  std::optional<double> shared_before_rhs_;
  std::vector<std::array<double, 2>> history_;     ///< extrapolated: (t, h_AH) of the last searches
  std::vector<std::array<double, 2>> start_nodes_; ///< seed_start's nodes, empty without a pilot
  /// extrapolated_at's polynomial in Newton's form, and the history it was formed from
  mutable std::vector<std::array<double, 2>> newton_nodes_;
  mutable std::vector<double> newton_coefficients_;
};

} // namespace gbssn1d
