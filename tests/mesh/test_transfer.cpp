// Prolongation and restriction between box-in-box levels: exact for polynomials of degree 5 of
// either parity (also at the points next to r = 0, which read the coarse mirror by parity, with
// the ghosts deliberately poisoned), the leading error term for degree 6, 6th order on a smooth
// field, and restriction after prolongation returning the coarse field to 6th order.
#include "mesh/transfer.hpp"

#include "../test_support.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <vector>

using namespace gbssn1d;
using namespace gbssn1d::mesh;
using gbssn1d::testing::fit_order;

namespace {

const double poison = std::numeric_limits<double>::quiet_NaN();

/// f on the interior of `g`, NaN on every ghost (the operators must not read them).
std::vector<double> sampled(const Grid& g, const std::function<double(double)>& f) {
  std::vector<double> v(g.n_total(), poison);
  for (std::size_t i = g.first_interior(); i < g.end_interior(); ++i)
    v[i] = f(g.r()[i]);
  return v;
}

struct Poly {
  std::function<double(double)> f;
  int parity;
};

std::vector<Poly> polynomials_of_degree_5() {
  return {
      {[](double) { return 1.7; }, +1},
      {[](double r) { return 0.3 - 2.0 * r * r; }, +1},
      {[](double r) { return 1.0 + r * r - 0.7 * r * r * r * r; }, +1},
      {[](double r) { return 0.9 * r; }, -1},
      {[](double r) { return r - 0.4 * r * r * r; }, -1},
      {[](double r) { return 0.2 * r + r * r * r - 0.5 * std::pow(r, 5); }, -1},
  };
}

} // namespace

TEST_CASE("prolongation weights: 6-point Lagrange at +-1/4, mirror images summing to one") {
  double sum = 0.0;
  for (std::size_t m = 0; m < 6; ++m) {
    sum += prolong_weights_plus[m];
    CHECK(prolong_weights_plus[m] == doctest::Approx(prolong_weights_minus[5 - m]));
  }
  CHECK(sum == doctest::Approx(1.0));
  const double expected[6] = {3, -25, 150, 150, -25, 3};
  for (std::size_t m = 0; m < 6; ++m)
    CHECK(restrict_weights[m] * 256.0 == doctest::Approx(expected[m]));
}

TEST_CASE("prolongation is exact for polynomials of degree 5 with parity, next to r = 0 too") {
  const Grid coarse(RadialMap::uniform(2.0), 16), fine(RadialMap::uniform(1.0), 16);
  const long end = static_cast<long>(fine.n_interior() + Grid::n_ghost); // and the outer ghosts
  for (const auto& p : polynomials_of_degree_5()) {
    const auto c = sampled(coarse, p.f);
    std::vector<double> f(fine.n_total(), poison);
    prolong_field(c, f, p.parity, 0, end);
    for (long j = 0; j < end; ++j) {
      const double r = fine.r()[static_cast<std::size_t>(j) + Grid::n_ghost];
      CHECK(f[static_cast<std::size_t>(j) + Grid::n_ghost]
            == doctest::Approx(p.f(r)).epsilon(1e-13).scale(1.0));
    }
  }
}

TEST_CASE("prolongation of r^6: the error is the Lagrange remainder (10395/4096) dr^6") {
  const Grid coarse(RadialMap::uniform(2.0), 16), fine(RadialMap::uniform(1.0), 16);
  const double dr = coarse.dx() * 2.0;
  const auto r6 = [](double r) { return std::pow(r, 6); };
  const auto c = sampled(coarse, r6);
  std::vector<double> f(fine.n_total(), poison);
  prolong_field(c, f, +1, 0, 19);
  for (long j = 0; j < 19; ++j) {
    const std::size_t k = static_cast<std::size_t>(j) + Grid::n_ghost;
    CHECK(f[k] - r6(fine.r()[k])
          == doctest::Approx(10395.0 / 4096.0 * std::pow(dr, 6)).epsilon(1e-8));
  }
}

TEST_CASE("restriction is exact for degree 5 with parity, and r^6 leaves (225/64) dr_f^6") {
  const Grid coarse(RadialMap::uniform(2.0), 16), fine(RadialMap::uniform(1.0), 16);
  for (const auto& p : polynomials_of_degree_5()) {
    const auto f = sampled(fine, p.f);
    std::vector<double> c(coarse.n_total(), poison);
    restrict_field(f, c, p.parity, 0, 7); // cell 6 reads fine cells up to 15
    for (std::size_t i = 0; i < 7; ++i)
      CHECK(c[i + Grid::n_ghost]
            == doctest::Approx(p.f(coarse.r()[i + Grid::n_ghost])).epsilon(1e-13).scale(1.0));
  }
  const auto r6 = [](double r) { return std::pow(r, 6); };
  const auto f = sampled(fine, r6);
  std::vector<double> c(coarse.n_total(), poison);
  restrict_field(f, c, +1, 0, 7);
  const double dr_f = fine.dx() * 1.0;
  for (std::size_t i = 0; i < 7; ++i)
    CHECK(c[i + Grid::n_ghost] - r6(coarse.r()[i + Grid::n_ghost])
          == doctest::Approx(225.0 / 64.0 * std::pow(dr_f, 6)).epsilon(1e-8));
}

TEST_CASE("prolongation, restriction and restriction after prolongation: 6th order") {
  // an even and an odd smooth field, on the whole level including the cells next to r = 0
  const std::vector<Poly> fields{
      {[](double r) { return std::exp(-(r - 1) * (r - 1)) + std::exp(-(r + 1) * (r + 1)); }, +1},
      {[](double r) { return std::sin(1.3 * r) / (1 + r * r); }, -1}};
  for (const auto& p : fields) {
    std::vector<double> h, e_prolong, e_restrict, e_round_trip;
    for (std::size_t n : {32, 64, 128}) {
      const Grid coarse(RadialMap::uniform(6.0), n), fine(RadialMap::uniform(3.0), n);
      const auto c = sampled(coarse, p.f), f_exact = sampled(fine, p.f);
      std::vector<double> f(fine.n_total(), poison), c_back(coarse.n_total(), poison),
          c_restricted(coarse.n_total(), poison);
      const long nf = static_cast<long>(n), nc_fine = nf / 2;
      prolong_field(c, f, p.parity, 0, nf);
      restrict_field(f_exact, c_restricted, p.parity, 0, nc_fine - 2);
      restrict_field(f, c_back, p.parity, 0, nc_fine - 2);
      double ep = 0, er = 0, et = 0;
      for (long j = 0; j < nf; ++j) {
        const std::size_t k = static_cast<std::size_t>(j) + Grid::n_ghost;
        ep = std::max(ep, std::abs(f[k] - f_exact[k]));
      }
      for (long i = 0; i < nc_fine - 2; ++i) {
        const std::size_t k = static_cast<std::size_t>(i) + Grid::n_ghost;
        er = std::max(er, std::abs(c_restricted[k] - c[k]));
        et = std::max(et, std::abs(c_back[k] - c[k]));
      }
      h.push_back(1.0 / static_cast<double>(n));
      e_prolong.push_back(ep);
      e_restrict.push_back(er);
      e_round_trip.push_back(et);
    }
    MESSAGE("orders: prolongation " << fit_order(h, e_prolong) << ", restriction "
                                    << fit_order(h, e_restrict) << ", round trip "
                                    << fit_order(h, e_round_trip));
    CHECK(fit_order(h, e_prolong) > 5.5);
    CHECK(fit_order(h, e_restrict) > 5.5);
    CHECK(fit_order(h, e_round_trip) > 5.5);
  }
}
