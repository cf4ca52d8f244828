// The measurement half of the horizon shift's control (evolution/horizon_tracker.hpp): where the
// apparent horizon lies on a level's state or on an RK stage's state, and on which level it is
// looked for. It holds no h_AH of its own; what is done with a radius (held, extrapolated, fed
// to the right-hand side) is the tracker's strategy.
#pragma once

#include "evolution/evolution_config.hpp"
#include "horizon/apparent_horizon.hpp"
#include "mesh/layout.hpp"

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

class HorizonProbe {
public:
  /// Reads `levels` (which outlive the probe).
  HorizonProbe(const EvolutionConfig& config, const mesh::MeshLayout& layout,
               const std::vector<State>& levels)
      : config_(config), layout_(layout), levels_(levels) {}

  /// A search near `seed` on level l's state; a HorizonFinderError gets the time added.
  std::optional<MarginalSurface> search(std::size_t l, double seed, double t) const;
  /// A search near `seed` on an RK stage's state u on `grid`; a HorizonFinderError gets the
  /// stage's time added.
  std::optional<MarginalSurface> search_stage(const State& u, const Grid& grid, double seed,
                                              double t) const;
  /// The level searched: the finest on which the horizon at radius r (or, without one, the
  /// standard radius 0.8304 M) lies well inside; 0 for a single grid.
  std::size_t level(const std::optional<double>& r) const;
  std::size_t levels() const { return layout_.levels(); }
  /// Throws HorizonLostError: at time t no horizon was found on level l, last at radius `last`.
  [[noreturn]] void lost(std::size_t l, double t, double last) const;

private:
  const EvolutionConfig& config_;
  const mesh::MeshLayout& layout_;
  const std::vector<State>& levels_;
};

} // namespace gbssn1d
