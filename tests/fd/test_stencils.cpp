// Finite-difference stencils: exact on polynomials of their degree, 4th order on smooth data.
#include "fd/stencils.hpp"

#include <doctest/doctest.h>

#include <array>
#include <cmath>

using namespace gbssn1d;

namespace {

/// Samples of p(x) = sum c_k x^k at x0 + j h, j = -4 ... 4, centred in the returned array.
struct Samples {
  std::array<double, 9> v;
  const double* centre() const { return v.data() + 4; }
};

template <std::size_t D>
Samples sample(const std::array<double, D>& c, double x0, double h) {
  Samples s;
  for (int j = -4; j <= 4; ++j) {
    const double x = x0 + j * h;
    double p = 0, xk = 1;
    for (double ck : c) {
      p += ck * xk;
      xk *= x;
    }
    s.v[j + 4] = p;
  }
  return s;
}

template <std::size_t D>
double derivative(const std::array<double, D>& c, double x, int order) {
  double sum = 0;
  for (std::size_t k = order; k < D; ++k) {
    double factor = 1;
    for (int m = 0; m < order; ++m)
      factor *= static_cast<double>(k - m);
    sum += c[k] * factor * std::pow(x, static_cast<double>(k) - order);
  }
  return sum;
}

} // namespace

TEST_CASE("first-derivative stencils are exact for quartics") {
  const std::array<double, 5> c{0.3, -1.2, 0.7, 2.1, -0.45};
  const double h = 0.1, x0 = 0.37;
  const auto s = sample(c, x0, h);
  const double exact = derivative(c, x0, 1);
  CHECK(std::abs(fd::d1_centred(s.centre()) / h - exact) < 1e-12);
  CHECK(std::abs(fd::d1_lopsided_plus(s.centre()) / h - exact) < 1e-12);
  CHECK(std::abs(fd::d1_lopsided_minus(s.centre()) / h - exact) < 1e-12);
  CHECK(std::abs(fd::d1_backward(s.centre()) / h - exact) < 1e-12);
  CHECK(std::abs(fd::advect(-0.8, s.centre()) / h - (-0.8) * exact) < 1e-12);
  CHECK(std::abs(fd::advect(0.8, s.centre()) / h - 0.8 * exact) < 1e-12);
}

TEST_CASE("second-derivative stencil is exact for quintics, KO annihilates them") {
  const std::array<double, 6> c{0.3, -1.2, 0.7, 2.1, -0.45, 0.9};
  const double h = 0.1, x0 = -0.21;
  const auto s = sample(c, x0, h);
  CHECK(std::abs(fd::d2_centred(s.centre()) / (h * h) - derivative(c, x0, 2)) < 1e-11);
  CHECK(std::abs(fd::ko6(s.centre())) < 1e-12);
  // and the highest grid mode is damped at the full rate: ko6 of (-1)^j is -64 at j = 0
  Samples mode;
  for (int j = -4; j <= 4; ++j)
    mode.v[j + 4] = (j % 2 == 0) ? 1.0 : -1.0;
  CHECK(fd::ko6(mode.centre()) == doctest::Approx(-64.0));
}

TEST_CASE("stencils are not exact one degree higher (the tests can fail)") {
  const std::array<double, 6> c{0, 0, 0, 0, 0, 1.0}; // x^5
  const double h = 0.1, x0 = 0.37;
  const auto s = sample(c, x0, h);
  // the leading truncation errors, exact here (the next terms need f^(7), f^(8) = 0):
  // D1 f - f' = -(h^4/30) f^(5) = -4 h^4 for x^5;  D2 f - f'' = -(h^4/90) f^(6) = -8 h^4 for x^6
  CHECK(fd::d1_centred(s.centre()) / h - derivative(c, x0, 1)
        == doctest::Approx(-4.0 * std::pow(h, 4)).epsilon(1e-9));
  const std::array<double, 7> c6{0, 0, 0, 0, 0, 0, 1.0}; // x^6
  const auto s6 = sample(c6, x0, h);
  CHECK(fd::d2_centred(s6.centre()) / (h * h) - derivative(c6, x0, 2)
        == doctest::Approx(-8.0 * std::pow(h, 4)).epsilon(1e-9));
}

TEST_CASE("upwind stencils from the lopsided sum and the 6th difference equal the lopsided ones") {
  // plus - minus = ko6 / 12 and plus + minus = lopsided_sum, exactly as polynomials in f
  const double f_data[] = {0.3, -1.7, 2.9, 0.11, -0.8, 4.4, 1.3};
  const double* f = f_data + 3;
  const double plus = gbssn1d::fd::d1_lopsided_plus(f), minus = gbssn1d::fd::d1_lopsided_minus(f);
  CHECK(plus - minus == doctest::Approx(gbssn1d::fd::ko6(f) / 12.0).epsilon(1e-14));
  CHECK(plus + minus == doctest::Approx(gbssn1d::fd::lopsided_sum(f)).epsilon(1e-14));
  for (double beta : {-2.5, -1e-3, 0.0, 1e-3, 0.7}) {
    const double from_sums =
        gbssn1d::fd::advect_from(beta, gbssn1d::fd::lopsided_sum(f), gbssn1d::fd::ko6(f));
    CHECK(from_sums == doctest::Approx(gbssn1d::fd::advect(beta, f)).epsilon(1e-14).scale(1.0));
  }
}
