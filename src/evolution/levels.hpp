// The levels of a run and how they step, from its configuration: the layout (one level on the
// grid's map, or --levels boxes), the time step schedule, each level's RHS and the operation
// applied to a level's state after each step (the chi floor).
#pragma once

#include "evolution/evolution_config.hpp"
#include "gbssn/rhs.hpp"
#include "gbssn/state.hpp"
#include "grid/grid.hpp"
#include "mesh/hierarchy.hpp"

#include <functional>
#include <optional>
#include <vector>

namespace gbssn1d {

/// The time stepping of a run: dt = cfl x smallest spacing, whatever the output cadence; the
/// last step is shortened to end exactly at tmax. Output between steps is interpolated
/// (Simulation::run).
struct Schedule {
  double dt;
  long n_steps;
};
Schedule make_schedule(const EvolutionConfig& config, double dt);

/// The levels of `config`'s grid: one level on its map, or --levels boxes.
mesh::MeshLayout make_layout(const EvolutionConfig& config);

/// h_AH for an evaluation of level `level`'s RHS (GbssnRhs::HorizonSource, with the level).
using LevelHorizonSource = std::function<std::optional<double>(
    std::size_t level, const State& u, const Grid& grid, double t, std::uint64_t evaluation,
    std::optional<double> held)>;
/// One RHS per level of `layout`, each taking h_AH from `source` (if given).
std::vector<GbssnRhs> make_level_rhs(const EvolutionConfig& config, const mesh::MeshLayout& layout,
                                     const LevelHorizonSource& source);
/// The initial data on every level.
std::vector<State> initial_levels(const mesh::MeshLayout& layout, const InitialDataParams& id,
                                  Fields fields);
/// The stepper's view of each level's RHS (which must outlive it).
std::vector<mesh::LevelRhs> level_functors(std::vector<GbssnRhs>& rhs);

/// Raises chi to at least chi_floor on every point (0: nothing). On wormhole data the innermost
/// cell's chi (about 1e-7 on the default grid) passes through zero while the lapse collapses,
/// and the (d_r chi)^2 / chi terms of (R1)-(R4) then diverge; docs/horizon-shift-study.md Sec. 4.
void apply_chi_floor(State& u, const Grid& grid, double chi_floor);

} // namespace gbssn1d
