#include "mesh/level_steps.hpp"

#include <cmath>
#include <cstddef>

namespace gbssn1d::mesh {

std::vector<long> level_steps(const MeshLayout& layout, const StepperOptions& options) {
  // Level l's step is dt_finest x 2^k_l, the largest such step within cfl dr_l and dt_max; its
  // parent's is the same or twice it (refinement factor 1 or 2 in time).
  const std::size_t n_levels = layout.levels();
  const double dt_finest = options.cfl * layout.spacing(n_levels - 1);
  std::vector<long> steps(n_levels, 1);
  if (options.subcycling) {
    std::vector<int> k(n_levels, 0);
    for (std::size_t l = n_levels - 1; l-- > 0;) {
      k[l] = k[l + 1];
      const double twice = std::ldexp(dt_finest, k[l] + 1);
      if (twice <= options.cfl * layout.spacing(l) * (1.0 + 1e-12) && twice <= options.dt_max)
        ++k[l];
    }
    for (std::size_t l = 0; l < n_levels; ++l)
      steps[l] = 1L << (k[0] - k[l]);
  }
  return steps;
}

double hierarchy_dt(const MeshLayout& layout, const StepperOptions& options) {
  const std::size_t finest = layout.levels() - 1;
  return static_cast<double>(level_steps(layout, options)[finest]) * options.cfl
         * layout.spacing(finest);
}

} // namespace gbssn1d::mesh
