// The one decimal reader of flags, config files, sweep values and tables (config/numbers.hpp).
#include "config/numbers.hpp"
#include "config/params.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <string>

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

TEST_CASE("a refused value of a million digits is shown by its first 100 bytes and its length, "
          "not echoed whole") {
  const std::string huge(1000000, '1');
  const gbssn1d::ParamError e("--N", huge, "is not a whole number in range");
  const std::string text = e.what();
  CHECK(text.size() < 300);
  CHECK(text.find("--N = " + huge.substr(0, 100) + "... (1000000 bytes) is invalid") == 0);
  CHECK(std::string(gbssn1d::ParamError("--N", "12", "why").what()) == "--N = 12 is invalid: why");
}

TEST_CASE("a well-formed number beyond a double's range is refused as too large or too small, "
          "naming it") {
  auto why = [](const std::string& text) {
    try {
      (void)gbssn1d::parse_number<double>("--rah0", text);
    } catch (const gbssn1d::ParamError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  CHECK(why("1e999")
        == "--rah0 = 1e999 is invalid: is too large in magnitude for a double "
           "(beyond about 1.8e308)");
  CHECK(why("-1e999").find("too large in magnitude") != std::string::npos);
  CHECK(why("1e-400").find("too small in magnitude") != std::string::npos);
  CHECK(why("inf") == "--rah0 = inf is invalid: must be a finite decimal number");
  CHECK(why("1e99x") == "--rah0 = 1e99x is invalid: must be a finite decimal number");
  CHECK(gbssn1d::real_out_of_range("1e300").empty());
}
