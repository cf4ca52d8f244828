// config/params.cpp: every flag reaches the evolution's typed configuration, with its unit.
#include "../simulation_support.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>

using namespace gbssn1d;
using gbssn1d::testing::small_trumpet_params;
using gbssn1d::testing::validated;

// Each flag gets a value that is neither its default nor another flag's, so that a flag
// dropped or wired to the wrong field fails.
TEST_CASE("evolution_config: each flag reaches its field, areal windows scale with M") {
  Params p;
  p.grid = RadialGrid::uniform;
  p.N = 123;
  p.rmax = 61.0;
  p.id = InitialDataKind::maximal_trumpet;
  p.M = 2.0;
  p.lapse0 = InitialLapse::one;
  p.eta = 0.7;
  p.advective_shift = true;
  p.non_advective_lapse = true;
  p.cfl = 0.3;
  p.ko_sigma = 0.05;
  p.upwind = fd::Upwind::biased;
  p.chi_floor = 2e-6;
  p.tmax = 7.0;
  p.dt_series = 0.5;
  p.dt_profiles = 3.5;
  p.checkpoint_every = 2.5;
  p.norm_rmin = 1.5;
  p.norm_rmax = 9.0;
  p.norm_Rmin = 3.0;
  p.norm_Rmax = 11.0;
  p.norm_Rint = 1.7;
  p.rahA = 0.4;
  p.rah0 = 1.3;
  p.rah_width = 2.5;
  p.rah_ramp = 4.0;
  p.rah_profile = ShiftProfile::rational3;
  p.rah_normal = ShiftNormal::smooth;
  p.rah_chi_smooth = 0.02;
  p.ah_every = AhEvery::parse("3");
  p.ah_tmin = 0.5;
  p.ah_tmax = 6.0;
  p.ah_tol = 1e-11;
  const EvolutionConfig c = evolution_config(validated(p));
  CHECK(c.grid.kind == GridKind::uniform);
  CHECK(c.grid.N == 123);
  CHECK(c.grid.rmax == 61.0);
  CHECK(c.initial_data.kind == InitialDataKind::maximal_trumpet);
  CHECK(c.initial_data.M == 2.0);
  CHECK(c.initial_data.lapse0 == InitialLapse::one);
  CHECK(c.rhs.gauge.shift.eta == 0.7);
  CHECK(c.rhs.gauge.shift.advective);
  CHECK_FALSE(c.rhs.gauge.slicing.advective);
  CHECK(c.stepping.cfl == 0.3);
  CHECK(c.rhs.ko_sigma == 0.05);
  CHECK(c.rhs.upwind == fd::Upwind::biased);
  CHECK(c.chi_floor == 2e-6);
  CHECK(c.tmax == 7.0);
  CHECK(c.dt_series == 0.5);
  CHECK(c.dt_profiles == 3.5);
  CHECK(c.checkpoint_every == 2.5);
  CHECK(c.norms.rmin == 1.5);
  CHECK(c.norms.rmax == 9.0);
  CHECK(c.norms.Rmin == 6.0); // --norm-R* are multiples of M
  CHECK(c.norms.Rmax == 22.0);
  CHECK(c.norms.Rint == doctest::Approx(3.4));
  const HorizonShiftParams& hs = c.rhs.horizon_shift;
  CHECK(hs.A == 0.4);
  CHECK(hs.h == 1.3);
  CHECK(hs.width == 2.5);
  CHECK(hs.ramp == 4.0);
  CHECK(hs.profile == ShiftProfile::rational3);
  CHECK(hs.normal == ShiftNormal::smooth);
  CHECK(hs.chi_smooth == 0.02);
  CHECK(c.horizon_search.every_steps == 3);
  CHECK(c.horizon_search.t_min == 0.5);
  CHECK(c.horizon_search.t_max == 6.0);
  CHECK(c.horizon_search.finder.tolerance == 1e-11);
}

TEST_CASE("evolution_config: the defaults are the typed configuration's, eta = 2/M") {
  Params p;
  p.M = 2.0;
  const EvolutionConfig c = evolution_config(validated(p));
  const EvolutionConfig& d = evolution_defaults();
  CHECK(c.grid.kind == GridKind::sinh);
  CHECK(c.grid.N == d.grid.N);
  CHECK(c.grid.dr_inner == d.grid.dr_inner);
  CHECK(c.stepping.cfl == d.stepping.cfl);
  CHECK(c.stepping.cfl == 0.5); // measured (docs/horizon-shift-study.md Sec. 11)
  Params b;
  b.grid = RadialGrid::boxes;
  b.N = 64;
  const EvolutionConfig cb = evolution_config(validated(b));
  CHECK(cb.stepping.cfl == 0.5); // boxes too (Sec. 11: their errors are those of cfl 0.25)
  CHECK(cb.stepping.time == mesh::TimeInterpolation::rk_stages);
  CHECK(cb.stepping.subcycling);
  CHECK(cb.stepping.dt_max == doctest::Approx(dt_max_of_damping(2.0))); // eta = 2/M, M = 1
  CHECK(std::isinf(c.stepping.dt_max)); // a single grid: no largest step
  CHECK(c.chi_floor == d.chi_floor);
  CHECK(c.rhs.upwind == fd::Upwind::lopsided); // Sec. 7.4: biased costs at M/8 and shrinks
  CHECK(c.rhs.gauge.shift.eta == 1.0);         // 2/M
  CHECK(c.rhs.gauge.slicing.mu_L == 2.0);
  CHECK(c.rhs.gauge.shift.xi == 0.75);
  CHECK(c.norms.rmax == doctest::Approx(std::min(10.0 * 2.0, d.grid.rmax / 2.0)));
  CHECK(c.horizon_search.every_steps == 0); // every RK substage
  CHECK_FALSE(c.horizon_search.prescribed); // closed loop
}

TEST_CASE("a run that will write hundreds of MB says so first, naming the flag that thins it") {
  auto warned = [](Params p) {
    int n = 0;
    std::string text;
    for (const auto& w : warnings(validated(p)))
      if (w.find("MB into --out") != std::string::npos) {
        ++n;
        text = w;
      }
    return std::pair(n, text);
  };
  Params p;
  p.N = 1600;
  p.tmax = 2000.0; // 401 blocks of 1600 rows: about 250 MB (measured: 246 MB written)
  const auto [n, text] = warned(p);
  CHECK(n == 1);
  CHECK(text.find("--dt-profiles") != std::string::npos);
  CHECK(text.find("401 blocks of 1600 rows") != std::string::npos);
  p.dt_profiles = 50.0; // 41 blocks: about 26 MB
  CHECK(warned(p).first == 0);
  CHECK(warned(Params{}).first == 0);
}

TEST_CASE("--upwind biased warns where it measured worse: a throat coarser than M/12, a shrink") {
  auto warned = [](Params p, const std::string& text) {
    int n = 0;
    for (const auto& w : warnings(validated(p)))
      n += w.find(text) != std::string::npos;
    return n;
  };
  Params p = small_trumpet_params(1024, 128.0); // M/8
  p.upwind = fd::Upwind::biased;
  CHECK(warned(p, "spacing of 0.125 M at r = M") == 1);
  p.N = 1536; // M/12: where biased is better
  CHECK(warned(p, "--upwind biased") == 0);
  p.upwind = fd::Upwind::lopsided;
  p.N = 1024;
  CHECK(warned(p, "--upwind") == 0);
  Params b; // boxes: the finest box's spacing, 1024/2^8/32 = M/8
  b.grid = RadialGrid::boxes;
  b.rmax = 1024.0;
  b.N = 32;
  b.upwind = fd::Upwind::biased;
  CHECK(warned(b, "spacing of 0.125 M") == 1);
  b.N = 64;
  CHECK(warned(b, "--upwind biased") == 0);
  Params s; // the default sinh grid: finer than M/12 at r = M
  s.upwind = fd::Upwind::biased;
  CHECK(warned(s, "--upwind biased") == 0);
  s.rahA = 0.5;
  s.rah0 = 0.6;
  CHECK(warned(s, "with a shrink (--rah0 0.6") == 1);
  s.rah0 = 1.2;
  CHECK(warned(s, "--upwind biased") == 0);
}
