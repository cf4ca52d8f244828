// The one decimal reader of flags, config files, sweep values and tables (config/numbers.hpp).
#include "config/numbers.hpp"

#include <doctest/doctest.h>

#include <cmath>

using gbssn1d::parse_decimal;

TEST_CASE("parse_decimal: -0 reads as 0 (no sign), so that 0 and -0 are one configuration") {
  for (const char* zero : {"-0", "-0.0", "-0e5", "0", "+0"}) {
    INFO(zero);
    const auto v = parse_decimal<double>(zero);
    REQUIRE(v);
    CHECK(*v == 0.0);
    CHECK_FALSE(std::signbit(*v));
  }
  CHECK(std::signbit(*parse_decimal<double>("-1e-300"))); // only zero loses its sign
  CHECK_FALSE(parse_decimal<double>("0x1"));
  CHECK_FALSE(parse_decimal<double>("1,5"));
  CHECK_FALSE(parse_decimal<double>("nan"));
}
