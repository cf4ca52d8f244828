#include "mesh/composite.hpp"

#include <stdexcept>

namespace gbssn1d::mesh {

namespace {

/// The composite cells: (level, interior index) from the finest level outwards.
void composite_cells(const MeshLayout& layout, std::vector<std::size_t>& level,
                     std::vector<std::size_t>& index) {
  const std::size_t n = layout.n_cells(), finest = layout.levels() - 1;
  for (std::size_t i = 0; i < n; ++i) {
    level.push_back(finest);
    index.push_back(i);
  }
  for (std::size_t l = finest; l-- > 0;)
    for (std::size_t i = n / 2; i < n; ++i) {
      level.push_back(l);
      index.push_back(i);
    }
}

Grid composite_grid(const MeshLayout& layout) {
  if (layout.levels() == 1)
    return layout.grid(0);
  std::vector<std::size_t> level, index;
  composite_cells(layout, level, index);
  std::vector<double> r, dr;
  for (std::size_t k = 0; k < level.size(); ++k) {
    const Grid& g = layout.grid(level[k]);
    r.push_back(g.r()[g.first_interior() + index[k]]);
    dr.push_back(g.dr()[g.first_interior() + index[k]]);
  }
  return Grid(r, dr);
}

} // namespace

Composite::Composite(const MeshLayout& layout) : layout_(&layout), grid_(composite_grid(layout)) {
  composite_cells(layout, level_, index_);
}

std::vector<double> Composite::gather(const std::vector<std::span<const double>>& per_level) const {
  if (per_level.size() != layout_->levels())
    throw std::invalid_argument("the composite needs one array per level");
  const std::size_t g = Grid::n_ghost, finest = layout_->levels() - 1;
  std::vector<double> out(grid_.n_total());
  for (std::size_t i = 0; i < g; ++i) {
    out[i] = per_level[finest][i];
    out[g + size() + i] = per_level[0][g + layout_->n_cells() + i];
  }
  for (std::size_t k = 0; k < size(); ++k)
    out[g + k] = per_level[level_[k]][g + index_[k]];
  return out;
}

std::vector<double>
Composite::gather_interior(const std::vector<std::span<const double>>& per_level) const {
  if (per_level.size() != layout_->levels())
    throw std::invalid_argument("the composite needs one array per level");
  std::vector<double> out(size());
  for (std::size_t k = 0; k < size(); ++k)
    out[k] = per_level[level_[k]][index_[k]];
  return out;
}

void Composite::gather_state(const std::vector<State>& u, State& out) const {
  const auto vars = u.front().vars();
  out = make_state(grid_, u.front().fields());
  for (const auto& entry : vars) {
    std::vector<std::span<const double>> arrays;
    for (std::size_t l = 0; l < layout_->levels(); ++l)
      arrays.push_back(field(u[l], layout_->grid(l), entry.var));
    const std::vector<double> v = gather(arrays);
    std::copy(v.begin(), v.end(), field(out, grid_, entry.var).begin());
  }
}

} // namespace gbssn1d::mesh
