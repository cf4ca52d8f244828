#include "evolution/horizon_probe.hpp"

#include <fmt/format.h>

#include <string>

namespace gbssn1d {

std::optional<MarginalSurface> HorizonProbe::search(std::size_t l, double seed, double t) const {
  try {
    // r alone (R_areal and the mass NaN): every caller reads r, and the areal radius took
    // half of a search (--ah-every extrapolated, a search per step, was no faster than one per
    // RK stage without the r alone)
    return find_horizon_near(levels_[l], layout_.grid(l), config_.horizon_search.finder, seed, 8,
                             false);
  } catch (const HorizonFinderError& e) {
    throw HorizonFinderError(fmt::format("{} (t = {:.6g})", e.what(), t));
  }
}

std::optional<MarginalSurface> HorizonProbe::search_stage(const State& u, const Grid& grid,
                                                          double seed, double t) const {
  try {
    // r alone: the areal radius is not interpolated (its 30 divisions were about a sixth of a
    // substage's search)
    return find_horizon_near(u, grid, config_.horizon_search.finder, seed, 8, false);
  } catch (const HorizonFinderError& e) {
    throw HorizonFinderError(fmt::format("{} (RK substage at t = {:.6g})", e.what(), t));
  }
}

std::size_t HorizonProbe::level(const std::optional<double>& r) const {
  if (layout_.levels() == 1)
    return 0;
  return layout_.finest_level_covering(r.value_or(standard_horizon_radius * config_.initial_data.M),
                                       RefinementSettings::horizon_margin_cells);
}

void HorizonProbe::lost(std::size_t l, double t, double last) const {
  const Grid& grid = layout_.grid(l);
  throw HorizonLostError(fmt::format(
      "the apparent horizon was lost at t = {:.6g} (last found at r_AH = {:.6g}, {:.3g} cells of "
      "dr = {:.3g} from the origin{}): none is left on the grid, and the horizon shift beta_H "
      "would switch off with it",
      t, last, last / grid.min_spacing(), grid.min_spacing(),
      layout_.levels() > 1 ? fmt::format(", level {}", l) : std::string()));
}

} // namespace gbssn1d
