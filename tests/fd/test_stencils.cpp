// Finite-difference stencils of every order: the derived weights against the classic tables,
// exact on polynomials of their degree and not one degree higher, the dissipation's rate, the
// upwind identity (lopsided and biased pairs), and the order of convergence on a smooth function.
#include "fd/stencils.hpp"

#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <vector>

using namespace gbssn1d;
using fd::Rational;

namespace {

/// Samples of p(x) = sum c_k x^k at x0 + j h, j = -6 ... 6, centred in the returned array.
struct Samples {
  std::array<double, 13> v;
  const double* centre() const { return v.data() + 6; }
};

Samples sample(const std::vector<double>& c, double x0, double h) {
  Samples s;
  for (int j = -6; j <= 6; ++j) {
    const double x = x0 + j * h;
    double p = 0, xk = 1;
    for (double ck : c) {
      p += ck * xk;
      xk *= x;
    }
    s.v[static_cast<std::size_t>(j + 6)] = p;
  }
  return s;
}

double derivative(const std::vector<double>& c, double x, int order) {
  double sum = 0;
  for (std::size_t k = static_cast<std::size_t>(order); k < c.size(); ++k) {
    double factor = 1;
    for (int m = 0; m < order; ++m)
      factor *= static_cast<double>(k) - m;
    sum += c[k] * factor * std::pow(x, static_cast<double>(k) - order);
  }
  return sum;
}

/// A polynomial of degree d with O(1) coefficients.
std::vector<double> polynomial(int d) {
  std::vector<double> c;
  for (int k = 0; k <= d; ++k)
    c.push_back(std::sin(1.3 * k + 0.4));
  return c;
}

template <std::size_t n>
bool weights_are(const fd::Stencil<n>& s, const std::array<std::int64_t, n>& num,
                 std::int64_t den) {
  for (std::size_t k = 0; k < n; ++k)
    if (!(s.exact(k) == Rational(num[k], den)))
      return false;
  return true;
}

template <int p>
void check_exactness() {
  CAPTURE(p);
  const double h = 0.1, x0 = 0.37;
  // exact up to degree p (first derivatives), p + 1 (the centred second derivative)
  const auto c = polynomial(p), c1 = polynomial(p + 1);
  const auto s = sample(c, x0, h), s1 = sample(c1, x0, h);
  const double scale = std::abs(derivative(c, x0, 1)) + 1.0;
  CHECK(std::abs(fd::d1_centred<p>(s.centre()) / h - derivative(c, x0, 1)) < 1e-11 * scale);
  CHECK(std::abs(fd::d1_lopsided_plus<p>(s.centre()) / h - derivative(c, x0, 1)) < 1e-11 * scale);
  CHECK(std::abs(fd::d1_lopsided_minus<p>(s.centre()) / h - derivative(c, x0, 1)) < 1e-11 * scale);
  CHECK(std::abs(fd::d2_centred<p>(s1.centre()) / (h * h) - derivative(c1, x0, 2))
        < 1e-9 * (std::abs(derivative(c1, x0, 2)) + 1.0));
  // the biased upwind pair is exact up to degree p + 1
  const double scale1 = std::abs(derivative(c1, x0, 1)) + 1.0;
  CHECK(std::abs(fd::d1_biased_plus<p>(s1.centre()) / h - derivative(c1, x0, 1)) < 1e-10 * scale1);
  CHECK(std::abs(fd::d1_biased_minus<p>(s1.centre()) / h - derivative(c1, x0, 1)) < 1e-10 * scale1);
  // the (p+2)-th difference annihilates degree p + 1
  CHECK(std::abs(fd::difference<p>(s1.centre())) < 1e-12);
  // and none is exact one degree higher (the checks above can fail): x^(p+1), x^(p+2)
  std::vector<double> mono(static_cast<std::size_t>(p + 2), 0.0);
  mono.back() = 1.0;
  const auto sm = sample(mono, x0, h);
  CHECK(std::abs(fd::d1_centred<p>(sm.centre()) / h - derivative(mono, x0, 1))
        > 1e-3 * std::pow(h, p));
  CHECK(std::abs(fd::d1_lopsided_plus<p>(sm.centre()) / h - derivative(mono, x0, 1))
        > 1e-3 * std::pow(h, p));
  mono.push_back(0.0);
  std::swap(mono[mono.size() - 1], mono[mono.size() - 2]); // x^(p+2)
  const auto sm2 = sample(mono, x0, h);
  CHECK(std::abs(fd::d2_centred<p>(sm2.centre()) / (h * h) - derivative(mono, x0, 2))
        > 1e-3 * std::pow(h, p));
  CHECK(std::abs(fd::d1_biased_plus<p>(sm2.centre()) / h - derivative(mono, x0, 1))
        > 1e-3 * std::pow(h, p + 1));
  CHECK(std::abs(fd::difference<p>(sm2.centre())) > 1e-3 * std::pow(h, p + 2));
}

template <int p>
void check_dissipation_and_upwind() {
  CAPTURE(p);
  // the highest grid mode (-1)^j is damped at the full rate: sign x norm x difference = -1
  Samples mode;
  for (int j = -6; j <= 6; ++j)
    mode.v[static_cast<std::size_t>(j + 6)] = (j % 2 == 0) ? 1.0 : -1.0;
  CHECK(fd::Order<p>::dissipation_sign * fd::Order<p>::dissipation_norm
            * fd::difference<p>(mode.centre())
        == doctest::Approx(-1.0));
  // the upwind pair from the lopsided sum and the difference equals the lopsided stencils
  const double f_data[] = {0.3, -1.7, 2.9, 0.11, -0.8, 4.4, 1.3, -0.6, 2.2, 0.05, -3.1};
  const double* f = f_data + 5;
  const double plus = fd::d1_lopsided_plus<p>(f), minus = fd::d1_lopsided_minus<p>(f);
  CHECK(plus - minus
        == doctest::Approx(fd::Order<p>::upwind_ratio * fd::difference<p>(f)).epsilon(1e-13));
  CHECK(plus + minus == doctest::Approx(fd::lopsided_sum<p>(f)).epsilon(1e-13));
  for (double beta : {-2.5, -1e-3, 0.0, 1e-3, 0.7}) {
    const double from_sums = fd::advect_from<p>(beta, fd::lopsided_sum<p>(f), fd::difference<p>(f));
    CHECK(from_sums == doctest::Approx(fd::advect<p>(beta, f)).epsilon(1e-13).scale(1.0));
  }
  // the same for the biased pair, whose half sum is the centred derivative of order p + 2
  using fd::Upwind;
  const double bplus = fd::d1_biased_plus<p>(f), bminus = fd::d1_biased_minus<p>(f);
  CHECK(bplus - bminus
        == doctest::Approx(
               fd::Order<p>::template upwind_ratio_of<Upwind::biased> * fd::difference<p>(f))
               .epsilon(1e-13));
  CHECK(bplus + bminus == doctest::Approx(fd::upwind_sum<p, Upwind::biased>(f)).epsilon(1e-13));
  if constexpr (p < 8)
    CHECK(0.5 * (bplus + bminus) == doctest::Approx(fd::d1_centred<p + 2>(f)).epsilon(1e-13));
  for (double beta : {-2.5, -1e-3, 0.0, 1e-3, 0.7}) {
    const double from_sums = fd::advect_from<p, Upwind::biased>(
        beta, fd::upwind_sum<p, Upwind::biased>(f), fd::difference<p>(f));
    CHECK(from_sums
          == doctest::Approx(fd::advect<p, Upwind::biased>(beta, f)).epsilon(1e-13).scale(1.0));
  }
  // upwind: where beta > 0 the biased stencil reaches one point further towards +x than -x
  CHECK(fd::Order<p>::biased_plus.first == -fd::Order<p>::half);
}

/// Order of the error of d1, d2 and the upwind derivative on sin(3x) + x exp(x), fitted over
/// h, h/2, h/4 (h = 0.1, and 0.02 for the one-sided 2nd-order upwind stencil to be asymptotic).
template <int p>
void check_convergence() {
  CAPTURE(p);
  auto f = [](double x) { return std::sin(3 * x) + x * std::exp(x); };
  auto f1 = [](double x) { return 3 * std::cos(3 * x) + (1 + x) * std::exp(x); };
  auto f2 = [](double x) { return -9 * std::sin(3 * x) + (2 + x) * std::exp(x); };
  const double x0 = 0.3;
  std::array<double, 3> e1{}, e2{}, eu{}, eb{};
  for (int level = 0; level < 3; ++level) {
    const double h = (p == 2 ? 0.02 : 0.1) / std::pow(2.0, level); // asymptotic for each p
    std::array<double, 13> v{};
    for (int j = -6; j <= 6; ++j)
      v[static_cast<std::size_t>(j + 6)] = f(x0 + j * h);
    const double* c = v.data() + 6;
    e1[static_cast<std::size_t>(level)] = std::abs(fd::d1_centred<p>(c) / h - f1(x0));
    e2[static_cast<std::size_t>(level)] = std::abs(fd::d2_centred<p>(c) / (h * h) - f2(x0));
    eu[static_cast<std::size_t>(level)] = std::abs(fd::advect<p>(1.0, c) / h - f1(x0));
    eb[static_cast<std::size_t>(level)] =
        std::abs(fd::advect<p, fd::Upwind::biased>(-1.0, c) / -h - f1(x0));
  }
  for (const auto& e : {e1, e2, eu})
    for (std::size_t k = 0; k + 1 < 3; ++k)
      CHECK(std::log2(e[k] / e[k + 1]) == doctest::Approx(p).epsilon(0.1));
  for (std::size_t k = 0; k + 1 < 3; ++k) // the biased pair: one order more
    CHECK(std::log2(eb[k] / eb[k + 1]) == doctest::Approx(p + 1).epsilon(0.1));
}

} // namespace

TEST_CASE("Fornberg's algorithm gives the classic weights (exact rationals)") {
  // 2nd order: (-1, 0, 1)/2, (1, -2, 1); upwind on 0, 1, 2: (-3, 4, -1)/2
  CHECK(weights_are(fd::Order<2>::d1, {-1, 0, 1}, 2));
  CHECK(weights_are(fd::Order<2>::d2, {1, -2, 1}, 1));
  CHECK(weights_are(fd::Order<2>::lopsided_plus, {-3, 4, -1}, 2));
  // 4th order: (1, -8, 0, 8, -1)/12, (-1, 16, -30, 16, -1)/12, lopsided (-3, -10, 18, -6, 1)/12
  CHECK(weights_are(fd::Order<4>::d1, {1, -8, 0, 8, -1}, 12));
  CHECK(weights_are(fd::Order<4>::d2, {-1, 16, -30, 16, -1}, 12));
  CHECK(weights_are(fd::Order<4>::lopsided_plus, {-3, -10, 18, -6, 1}, 12));
  CHECK(weights_are(fd::Order<4>::lopsided_minus, {-1, 6, -18, 10, 3}, 12));
  CHECK(weights_are(fd::Order<4>::difference, {1, -6, 15, -20, 15, -6, 1}, 1));
  CHECK(fd::Order<4>::upwind_ratio_exact == Rational(1, 12));
  // biased (upwind-biased 5th order) on -2 ... 3: (3, -30, -20, 60, -15, 2)/60, ratio 1/30
  CHECK(weights_are(fd::Order<4>::biased_plus, {3, -30, -20, 60, -15, 2}, 60));
  CHECK(weights_are(fd::Order<4>::biased_minus, {-2, 15, -60, 20, 30, -3}, 60));
  CHECK(fd::Order<4>::biased_ratio_exact == Rational(1, 30));
  // 3rd order on -1 ... 2: (-2, -3, 6, -1)/6
  CHECK(weights_are(fd::Order<2>::biased_plus, {-2, -3, 6, -1}, 6));
  // 6th order: (-1, 9, -45, 0, 45, -9, 1)/60, (2, -27, 270, -490, 270, -27, 2)/180
  CHECK(weights_are(fd::Order<6>::d1, {-1, 9, -45, 0, 45, -9, 1}, 60));
  CHECK(weights_are(fd::Order<6>::d2, {2, -27, 270, -490, 270, -27, 2}, 180));
  // 8th order: (3, -32, 168, -672, 0, 672, -168, 32, -3)/840
  CHECK(weights_are(fd::Order<8>::d1, {3, -32, 168, -672, 0, 672, -168, 32, -3}, 840));
  CHECK(weights_are(fd::Order<8>::d2, {-9, 128, -1008, 8064, -14350, 8064, -1008, 128, -9}, 5040));
  // the outer boundary's backward derivative: (3, -16, 36, -48, 25)/12
  CHECK(weights_are(fd::backward4, {3, -16, 36, -48, 25}, 12));
}

TEST_CASE("every order is exact on polynomials of its degree and not one degree higher") {
  check_exactness<2>();
  check_exactness<4>();
  check_exactness<6>();
  check_exactness<8>();
}

TEST_CASE("every order damps the highest mode at the full rate and upwinds by the identity") {
  check_dissipation_and_upwind<2>();
  check_dissipation_and_upwind<4>();
  check_dissipation_and_upwind<6>();
  check_dissipation_and_upwind<8>();
}

TEST_CASE("every order converges at its order on a smooth function") {
  check_convergence<2>();
  check_convergence<4>();
  check_convergence<6>();
  check_convergence<8>();
}

TEST_CASE("the backward derivative is exact for quartics") {
  const auto c = polynomial(4);
  const double h = 0.1, x0 = 0.37;
  const auto s = sample(c, x0, h);
  CHECK(std::abs(fd::d1_backward(s.centre()) / h - derivative(c, x0, 1)) < 1e-11);
}
