// The composite of box-in-box levels (mesh/composite.hpp): its cells tile [0, rmax] without
// overlap, each r from the finest level covering it, and gathering returns the levels' values;
// one level is its own composite. Also the per-level steps under a largest step (dt_max).
#include "mesh/composite.hpp"
#include "mesh/hierarchy.hpp"
#include "mesh/level_steps.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <span>
#include <vector>

using namespace gbssn1d;
using namespace gbssn1d::mesh;

TEST_CASE("the composite of boxes tiles [0, rmax] with each r from the finest box covering it") {
  const double rmax = 64.0;
  const std::size_t n = 16, levels = 4;
  const MeshLayout layout(rmax, n, levels);
  const Composite c(layout);
  const Grid& g = c.grid();
  REQUIRE(c.size() == n + (levels - 1) * n / 2);
  REQUIRE(g.n_interior() == c.size());
  // cells tile [0, rmax]: faces r -+ dr/2 meet, from 0 to rmax
  double face = 0.0;
  for (std::size_t k = 0; k < c.size(); ++k) {
    const std::size_t i = g.first_interior() + k;
    CHECK(g.r()[i] - 0.5 * g.dr()[i] == doctest::Approx(face).epsilon(1e-14));
    face = g.r()[i] + 0.5 * g.dr()[i];
    // the finest level whose extent holds the cell
    std::size_t finest = 0;
    for (std::size_t l = 0; l < levels; ++l)
      if (g.r()[i] < layout.extent(l))
        finest = l;
    CHECK(c.level(k) == finest);
    const Grid& lg = layout.grid(c.level(k));
    CHECK(lg.r()[lg.first_interior() + c.index(k)] == g.r()[i]);
    CHECK(g.dr()[i] == doctest::Approx(layout.spacing(c.level(k))));
  }
  CHECK(face == doctest::Approx(rmax));
  // ghosts: mirrored at the origin, continued outside
  CHECK(g.r()[0] == -g.r()[Grid::mirror(0)]);
  CHECK(g.r()[g.end_interior()] == doctest::Approx(rmax + 0.5 * layout.spacing(0)));
  // no finite differences on a composite: its map factors are NaN
  CHECK(std::isnan(g.inv_dr_dx()[g.first_interior()]));

  // gathering: each level's value f_l(r) = l * 1000 + r lands at its cell
  std::vector<std::vector<double>> f(levels);
  std::vector<std::span<const double>> spans;
  for (std::size_t l = 0; l < levels; ++l) {
    const Grid& lg = layout.grid(l);
    for (std::size_t i = 0; i < lg.n_total(); ++i)
      f[l].push_back(1000.0 * static_cast<double>(l) + lg.r()[i]);
    spans.emplace_back(f[l]);
  }
  const std::vector<double> all = c.gather(spans);
  for (std::size_t i = 0; i < g.n_total(); ++i) {
    const bool origin = i < g.first_interior();
    const bool outer = i >= g.end_interior();
    const double level = origin ? levels - 1.0 : outer ? 0.0 : c.level(i - g.first_interior());
    CHECK(all[i] == doctest::Approx(1000.0 * level + g.r()[i]));
  }
}

TEST_CASE("one level is its own composite") {
  const MeshLayout layout(RadialMap::sinh(50.0, 0.05, 400), 200, 1);
  const Composite c(layout);
  CHECK(c.grid().r() == layout.grid(0).r());
  CHECK(c.grid().dr() == layout.grid(0).dr());
  std::vector<double> f(layout.grid(0).n_total());
  for (std::size_t i = 0; i < f.size(); ++i)
    f[i] = std::sin(static_cast<double>(i));
  CHECK(c.gather({std::span<const double>(f)}) == f);
}

TEST_CASE("a largest step makes coarse boxes step with their child's dt, powers of two below") {
  const MeshLayout layout(1024.0, 48, 9); // spacings 21.3 M ... 1/12 M
  StepperOptions o;
  o.cfl = 0.25;
  const double dt_finest = 0.25 * layout.spacing(8);
  // without a limit every level steps at its CFL step: 2^(8-l) steps of the finest
  auto steps = level_steps(layout, o);
  for (std::size_t l = 0; l < 9; ++l)
    CHECK(steps[l] == (1L << l));
  CHECK(hierarchy_dt(layout, o) == doctest::Approx(0.25 * layout.spacing(0)));
  // dt_max = 0.5: the largest dt_finest x 2^k within it is 16 dt_finest = 1/3 (level 4's CFL
  // step); levels 0 ... 4 take it, each finer level twice its parent's count
  o.dt_max = 0.5;
  steps = level_steps(layout, o);
  CHECK(hierarchy_dt(layout, o) == doctest::Approx(16.0 * dt_finest));
  for (std::size_t l = 0; l < 9; ++l)
    CHECK(steps[l] == (l <= 4 ? 1L : 1L << (l - 4)));
  for (std::size_t l = 0; l < 9; ++l)
    CHECK(hierarchy_dt(layout, o) / static_cast<double>(steps[l])
          <= 0.25 * layout.spacing(l) * (1 + 1e-12));
  // without subcycling every level takes the finest step
  o.subcycling = false;
  steps = level_steps(layout, o);
  for (std::size_t l = 0; l < 9; ++l)
    CHECK(steps[l] == 1);
  CHECK(hierarchy_dt(layout, o) == dt_finest);
}
