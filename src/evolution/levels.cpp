#include "evolution/levels.hpp"

#include "initial_data/initial_data.hpp"

#include <algorithm>
#include <cmath>

namespace gbssn1d {

Schedule make_schedule(const EvolutionConfig& config, double dt) {
  Schedule s;
  s.dt = dt;
  s.n_steps = static_cast<long>(std::ceil(config.tmax / s.dt - 1e-9));
  return s;
}

mesh::MeshLayout make_layout(const EvolutionConfig& config) {
  if (config.refinement.levels > 1)
    return mesh::MeshLayout(config.grid.rmax, config.grid.N, config.refinement.levels,
                            config.grid.fd_order);
  return mesh::MeshLayout(make_grid(config.grid).map(), config.grid.N, 1, config.grid.fd_order);
}

void apply_chi_floor(State& u, const Grid& grid, double chi_floor) {
  if (chi_floor <= 0.0)
    return;
  for (double& chi : field(u, grid, Var::chi))
    chi = std::max(chi, chi_floor);
}

std::vector<GbssnRhs> make_level_rhs(const EvolutionConfig& config, const mesh::MeshLayout& layout,
                                     const LevelHorizonSource& source) {
  std::vector<GbssnRhs> rhs;
  for (std::size_t l = 0; l < layout.levels(); ++l) {
    rhs.emplace_back(layout.grid(l), config.rhs);
    // quadratic interpolation fills a box's buffer once per step and evolves it: its outer
    // ghosts then need the boundary condition
    rhs.back().set_outer_ghosts_from_parent(
        l > 0 && config.stepping.time != mesh::TimeInterpolation::quadratic);
    if (source)
      rhs.back().set_horizon_source([l, source](const State& u, const Grid& grid, double t,
                                                std::uint64_t evaluation,
                                                std::optional<double> held) {
        return source(l, u, grid, t, evaluation, held);
      });
  }
  return rhs;
}

std::vector<State> initial_levels(const mesh::MeshLayout& layout, const InitialDataParams& id,
                                  Fields fields) {
  std::vector<State> u;
  for (std::size_t l = 0; l < layout.levels(); ++l)
    u.push_back(initial_data(layout.grid(l), id, fields));
  return u;
}

std::vector<mesh::LevelRhs> level_functors(std::vector<GbssnRhs>& rhs) {
  std::vector<mesh::LevelRhs> f;
  for (auto& r : rhs)
    f.emplace_back([&r](const State& u, State& dudt, double t) { r(u, dudt, t); });
  return f;
}

} // namespace gbssn1d
