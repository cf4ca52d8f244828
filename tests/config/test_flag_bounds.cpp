// The values each flag accepts on its own, as its row of the flag table carries them
// (config/flag_table.hpp: Bounds, check_bounds()): the refusal's wording, a value no number
// reader gives (NaN, from a library user's Params), and a choice's unknown name. The command
// line's edges of every bound: tests/config/test_every_flag.cpp.

#include "config/config_file.hpp"
#include "config/flag_table.hpp"
#include "config/params.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <string>
#include <type_traits>

using namespace gbssn1d;

namespace {

/// The ParamError that resolving and validating `p` throws, or "" if none.
std::string refusal_of(const Params& p) {
  try {
    validate(resolve(p));
  } catch (const ParamError& e) {
    return e.what();
  }
  return "";
}

} // namespace

TEST_CASE("a flag's bounds: the refusal names the bound and its note, the edges as the row "
          "says") {
  CHECK(above(0.0).refusal(0.0) == "must be > 0");
  CHECK_FALSE(above(0.0).refusal(1e-300));
  CHECK(at_least(0.0, "0: off").refusal(-1e-300) == "must be >= 0 (0: off)");
  CHECK_FALSE(at_least(0.0).refusal(0.0));
  CHECK(within(0.0, 0.5).refusal(0.5000001) == "must lie in [0, 0.5]");
  CHECK_FALSE(within(0.0, 0.5).refusal(0.5));
  CHECK(within_below(0.0, 1.0).refusal(1.0) == "must lie in [0, 1)");
  CHECK_FALSE(within_below(0.0, 1.0).refusal(0.0));
  CHECK(above(-1.0, "why").refusal(-1.0) == "must be > -1 (why)");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (const Bounds& b : {finite(), above(0.0), at_least(0.0), within(0.0, 1.0)}) {
    CHECK(b.refusal(nan) == "must be a finite number");
    CHECK(b.refusal(inf) == "must be a finite number");
  }
  CHECK_FALSE(finite().refusal(-1e300));
}

TEST_CASE("every bounded real flag refuses NaN given through the library, naming itself") {
  // the command line's number reader refuses every non-finite text first; a program that fills
  // Params itself (docs/examples/own_experiment.cpp) meets the table's bounds
  int checked = 0;
  for (const auto& spec : param_specs()) {
    if (!spec.bounds)
      continue;
    const std::string flag = "--" + std::string(spec.name);
    std::visit(
        [&](auto member) {
          using T = std::decay_t<decltype(Params{}.*member)>;
          if constexpr (std::is_same_v<T, double> || std::is_same_v<T, std::optional<double>>) {
            Params p;
            p.id = InitialDataKind::onelog_trumpet;
            p.grid = RadialGrid::uniform;
            p.N = 32;
            p.rmax = 16.0;
            p.tmax = 0.0;
            p.*member = std::numeric_limits<double>::quiet_NaN();
            INFO(flag);
            const std::string why = refusal_of(p);
            CHECK(why.rfind(flag + " = nan is invalid: ", 0) == 0);
            ++checked;
          }
        },
        spec.member);
  }
  CHECK(checked > 25);
}

TEST_CASE("every choice flag refuses a name none of its choices has, listing them") {
  int checked = 0;
  for (const auto& spec : param_specs()) {
    const std::string flag = "--" + std::string(spec.name);
    std::visit(
        [&](auto member) {
          using T = std::decay_t<decltype(Params{}.*member)>;
          constexpr bool choice = ChoiceValue<T> || is_optional_choice<T>;
          if constexpr (choice && !std::is_same_v<T, AhEvery>) {
            const Params p = parse_evolve_args({flag, "no-such-choice"});
            INFO(flag);
            const std::string why = refusal_of(p);
            CHECK(why.rfind(flag + " = no-such-choice is invalid: must be one of ", 0) == 0);
            ++checked;
          }
        },
        spec.member);
  }
  CHECK(checked >= 13);
}
