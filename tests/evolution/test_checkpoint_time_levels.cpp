// A checkpoint's quadratic time levels (boxes with --time-interp quadratic keep two earlier
// states of every level but the finest): each must lie before the checkpoint's time, or the
// resumed run would interpolate in time from a state that is not this run's past.
#include "evolution/checkpoint.hpp"

#include "../simulation_support.hpp"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <unistd.h>

using namespace gbssn1d;
using gbssn1d::testing::simulation;

// Guards the time check of resumable_checkpoint (evolution/checkpoint.cpp): a stored time level
// at or after the checkpoint's time is refused (it was accepted, and the run went on from it).
TEST_CASE("resume refuses a checkpoint whose quadratic time level is not before its time") {
  namespace fs = std::filesystem;
  Params p;
  p.grid = RadialGrid::boxes;
  p.levels = 3;
  p.rmax = 16.0;
  p.N = 16;
  p.id = InitialDataKind::onelog_trumpet;
  p.time_interp = mesh::TimeInterpolation::quadratic;
  p.cfl = 0.25;
  p.tmax = 1.0;
  p.dt_series = 0.5;
  p.checkpoint_every = 0.5;
  const fs::path dir =
      fs::temp_directory_path() / fmt::format("gbssn1d_test_time_levels_{}", ::getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::optional<Checkpoint> mid;
  {
    Simulation first = simulation(p);
    first.on_checkpoint = [&](const Checkpoint& ck) {
      if (std::abs(ck.t - 0.5) < 1e-9)
        mid = ck;
    };
    Output out(dir, first.run_facts(), Formulation::bssn, {});
    first.run(&out);
  }
  fs::remove_all(dir);
  REQUIRE(mid);
  REQUIRE(mid->history.size() == 3);
  REQUIRE(mid->history[0].size() == 2);
  CHECK(mid->history[0][0].t < mid->history[0][1].t);
  CHECK(mid->history[0][1].t < mid->t);
  {
    Simulation resumed = simulation(p);
    CHECK_NOTHROW(resumed.restore(*mid)); // as written: accepted
  }
  for (const std::size_t l : {0u, 1u})
    for (const std::size_t k : {0u, 1u})
      for (const double later : {0.0, mid->dt, 1.0}) {
        INFO("level " << l << ", time level " << k << " at t + " << later);
        Checkpoint c = *mid;
        c.history[l][k].t = mid->t + later;
        Simulation resumed = simulation(p);
        CHECK_THROWS_AS(resumed.restore(c), CheckpointError);
      }
}
