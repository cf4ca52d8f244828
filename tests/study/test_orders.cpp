// Order formulas against sequences of known order (equations document, Sec. 15).
#include "study/orders.hpp"

#include <doctest/doctest.h>

#include <array>
#include <cmath>

using namespace gbssn1d;

TEST_CASE("three-level order: the document's example and sequences of known order") {
  // 48, 64, 96 and p = 4 give the ratio 2.6923
  CHECK(three_level_ratio(4.0, 48, 64, 96) == doctest::Approx(2.6923).epsilon(1e-4));
  for (double p : {1.0, 2.0, 3.7, 4.0, 6.0}) {
    const std::array<std::array<double, 3>, 3> families{
        {{48.0, 64.0, 96.0}, {100.0, 200.0, 400.0}, {320.0, 480.0, 640.0}}};
    for (const auto& [N1, N2, N3] : families) {
      auto u = [&](double N) { return 0.37 + 2.5 * std::pow(N, -p) + 1e-3 * std::pow(N, -p - 2); };
      const double order =
          order_three_level(std::abs(u(N1) - u(N2)), std::abs(u(N2) - u(N3)), N1, N2, N3);
      INFO("p = " << p << ", N = " << N1 << " " << N2 << " " << N3);
      CHECK(order == doctest::Approx(p).epsilon(0.02));
    }
  }
  CHECK(std::isnan(order_three_level(1.0, 0.0, 48, 64, 96)));
}

TEST_CASE("two-level order of a quantity whose exact value is zero") {
  // 48 -> 64 at p = 4: E1/E2 = (64/48)^4 = 3.16049
  CHECK(std::pow(64.0 / 48.0, 4.0) == doctest::Approx(3.16049).epsilon(1e-5));
  CHECK(order_two_level(3.16049, 1.0, 48, 64) == doctest::Approx(4.0).epsilon(1e-4));
  CHECK(order_two_level(16.0, 1.0, 100, 200) == doctest::Approx(4.0));
  CHECK(order_fitted({100, 200, 400}, {1.0, 1.0 / 16, 1.0 / 256}) == doctest::Approx(4.0));
  CHECK(order_fitted({100, 150, 200}, {1.0, std::pow(1.5, -2.0), 0.25}) == doctest::Approx(2.0));
}
