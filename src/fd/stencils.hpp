// Finite-difference stencils on the uniform computational coordinate x (spacing dx), of order
// 2, 4, 6 or 8 (`--fd-order`).
//
// The coefficients are derived, not typed: Fornberg's algorithm (Math. Comp. 51:699, 1988) runs
// at compile time in exact rational arithmetic, and each stencil is stored as integer weights
// over one common denominator. The 4th-order weights are the classic ones, e.g. (1, -8, 0, 8, -1)
// / 12 for the first derivative (tests/fd/test_stencils.cpp checks them and every order against
// polynomials).
//
// Each operator takes a pointer to the value at the point and reads its neighbours f[k]. They
// are inline and branch-free, so that point loops vectorise. Radial derivatives follow by the
// chain rule (grid/grid.hpp).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>

namespace gbssn1d::fd {

/// The finite-difference orders offered.
inline constexpr std::array<int, 4> orders{2, 4, 6, 8};
inline constexpr bool valid_order(int order) {
  return order == 2 || order == 4 || order == 6 || order == 8;
}
/// The widest reach of order `order`'s stencils (upwind and dissipation): order / 2 + 1, the
/// run-time value of Order<p>::radius.
inline constexpr std::size_t stencil_radius(int order) {
  return static_cast<std::size_t>(order / 2 + 1);
}

/// An exact rational p / q (q > 0, lowest terms), for deriving weights at compile time.
struct Rational {
  std::int64_t p, q;
  static constexpr std::int64_t gcd(std::int64_t a, std::int64_t b) {
    a = a < 0 ? -a : a;
    b = b < 0 ? -b : b;
    while (b != 0) {
      const std::int64_t t = a % b;
      a = b;
      b = t;
    }
    return a == 0 ? 1 : a;
  }
  constexpr Rational() : p(0), q(1) {} // user-provided: value-initialised arrays hold 0/1
  constexpr Rational(std::int64_t num, std::int64_t den = 1) : p(num), q(den) {
    if (q < 0) {
      p = -p;
      q = -q;
    }
    const std::int64_t g = gcd(p, q);
    p /= g;
    q /= g;
  }
  friend constexpr Rational operator+(Rational a, Rational b) {
    const std::int64_t g = gcd(a.q, b.q);
    return {a.p * (b.q / g) + b.p * (a.q / g), a.q / g * b.q};
  }
  friend constexpr Rational operator-(Rational a, Rational b) { return a + Rational(-b.p, b.q); }
  friend constexpr Rational operator*(Rational a, Rational b) {
    const std::int64_t g1 = gcd(a.p, b.q), g2 = gcd(b.p, a.q);
    return {(a.p / g1) * (b.p / g2), (a.q / g2) * (b.q / g1)};
  }
  friend constexpr Rational operator/(Rational a, Rational b) { return a * Rational(b.q, b.p); }
  friend constexpr bool operator==(Rational a, Rational b) { return a.p == b.p && a.q == b.q; }
};

/// Fornberg's algorithm: the weights of the m-th derivative at x = 0 on the n integer nodes
/// first, first + 1, ..., first + n - 1 (unit spacing), exact.
template <std::size_t n>
constexpr std::array<Rational, n> fornberg(int m, int first) {
  // c[j][k]: weight of node j for the k-th derivative, k = 0 ... m (the recursion of the paper,
  // Table 1, with the evaluation point z = 0)
  std::array<std::array<Rational, 9>, n> c{};
  Rational c1 = 1;
  c[0][0] = 1;
  for (std::size_t i = 1; i < n; ++i) {
    const Rational xi = static_cast<std::int64_t>(first + static_cast<int>(i));
    Rational c2 = 1;
    const int mn = static_cast<int>(i) < m ? static_cast<int>(i) : m;
    for (std::size_t j = 0; j < i; ++j) {
      const Rational xj = static_cast<std::int64_t>(first + static_cast<int>(j));
      const Rational c3 = xi - xj;
      c2 = c2 * c3;
      if (j == i - 1)
        for (int k = mn; k >= 0; --k) {
          const Rational prev_k1 = k > 0 ? c[i - 1][k - 1] : Rational(0);
          const Rational xi_prev =
              static_cast<std::int64_t>(first + static_cast<int>(i) - 1); // x_{i-1}
          const Rational value = c1 * (Rational(k) * prev_k1 - xi_prev * c[i - 1][k]) / c2;
          c[i][k] = value; // through a temporary (see combine)
        }
      for (int k = mn; k >= 0; --k) {
        const Rational prev_k1 = k > 0 ? c[j][k - 1] : Rational(0);
        const Rational value = (xi * c[j][k] - Rational(k) * prev_k1) / c3;
        c[j][k] = value;
      }
    }
    c1 = c2;
  }
  std::array<Rational, n> w{};
  for (std::size_t j = 0; j < n; ++j)
    w[j] = c[j][m];
  return w;
}

/// A stencil as integer weights w[k] on the points first ... first + n - 1, over a common
/// denominator: sum_k w[k] f[first + k] / denominator.
template <std::size_t n>
struct Stencil {
  int first = 0;
  std::array<std::int64_t, n> weight{};
  std::int64_t denominator = 1;
  static constexpr std::size_t size = n;
  /// The weights over one denominator, the least common multiple of theirs.
  static constexpr Stencil from(const std::array<Rational, n>& w, int first_point) {
    Stencil s;
    s.first = first_point;
    std::int64_t l = 1;
    for (const Rational& r : w)
      l = l / Rational::gcd(l, r.q) * r.q;
    s.denominator = l;
    for (std::size_t k = 0; k < n; ++k)
      s.weight[k] = w[k].p * (l / w[k].q);
    return s;
  }
  constexpr Rational exact(std::size_t k) const { return Rational(weight[k], denominator); }
  /// sum_k w[k] f[first + k] (without the denominator), in increasing k, skipping zeros. `f`
  /// points at the value at the point, or is any F whose f[k] is the k-th neighbour's value (a
  /// window of SIMD vectors: bench/stencil_windows.cpp), summed in the same order.
  template <class F>
  [[gnu::always_inline]] auto sum(const F& f) const {
    using T = std::remove_cvref_t<decltype(f[0])>;
    T s{};
    bool started = false;
#pragma GCC unroll 16
    for (std::size_t k = 0; k < n; ++k) {
      if (weight[k] == 0)
        continue;
      const T t = static_cast<double>(weight[k]) * f[first + static_cast<int>(k)];
      s = started ? s + t : t;
      started = true;
    }
    return s;
  }
  template <class F>
  [[gnu::always_inline]] auto operator()(const F& f) const {
    return sum(f) * (1.0 / static_cast<double>(denominator));
  }
};

namespace detail {

/// The (2 radius)-th difference on -radius ... radius: binomial weights with alternating signs,
/// end weights +1.
template <std::size_t n>
constexpr std::array<Rational, n> difference_weights() {
  std::array<Rational, n> w{};
  std::int64_t binom = 1;
  for (std::size_t k = 0; k < n; ++k) {
    w[k] = Rational((k % 2 == 0 ? 1 : -1) * binom);
    binom = binom * static_cast<std::int64_t>(n - 1 - k) / static_cast<std::int64_t>(k + 1);
  }
  return w;
}

/// plus + sign x minus on the wide stencil -radius ... radius, exact, for a first-derivative
/// stencil `plus` on n_plus points from `first` and its mirror image minus(x) = -plus(-x). Each
/// weight is computed in one expression: the accumulating form (w[i] = w[i] + ...) gave 0/0
/// weights under GCC 12's constant evaluation when Order<p> was instantiated (observed; the
/// cause in the compiler was not isolated; the tests check every weight against the classic
/// tables).
template <std::size_t n_plus, int first, int radius>
constexpr std::array<Rational, 2 * radius + 1> combine(int sign) {
  const std::array<Rational, n_plus> plus = fornberg<n_plus>(1, first);
  auto plus_at = [&plus](int x) {
    return x >= first && x < first + static_cast<int>(n_plus)
               ? plus[static_cast<std::size_t>(x - first)]
               : Rational(0);
  };
  std::array<Rational, 2 * radius + 1> w{};
  for (int x = -radius; x <= radius; ++x)
    w[static_cast<std::size_t>(x + radius)] = plus_at(x) - Rational(sign) * plus_at(-x);
  return w;
}

/// Whether a = c b for the constant c = a[0] / b[0].
template <std::size_t n>
constexpr bool proportional(const std::array<Rational, n>& a, const std::array<Rational, n>& b) {
  const Rational c = a[0] / b[0];
  for (std::size_t k = 0; k < n; ++k)
    if (!(a[k] == c * b[k]))
      return false;
  return true;
}

} // namespace detail

/// The stencil of the upwind first derivative in the advection terms beta d_r f (`--upwind`);
/// both lean towards where the flow comes from and reach p/2 + 1 points on that side.
enum class Upwind {
  /// order p on -(p/2 - 1) ... p/2 + 1 (p + 1 points): the moving-puncture codes' lopsided
  /// stencil, e.g. (-3, -10, 18, -6, 1)/12 at 4th order
  lopsided,
  /// order p + 1 on -p/2 ... p/2 + 1 (p + 2 points): the upwind-biased stencil, e.g.
  /// (3, -30, -20, 60, -15, 2)/60 at 4th order; the centred derivative of order p + 2 plus a
  /// (p+2)-th difference that is 2.5 times weaker than the lopsided one's at 4th order
  biased,
};

/// The stencils of one order p (p = 2, 4, 6, 8), all times the power of dx of their derivative:
///  - d1, d2: centred first and second derivatives on -p/2 ... p/2;
///  - lopsided_plus: first derivative of order p on -(p/2 - 1) ... p/2 + 1, leaning towards +x;
///    lopsided_minus, its mirror image; biased_plus and biased_minus, of order p + 1 on
///    -p/2 ... p/2 + 1 and its mirror image (Upwind);
///  - difference: the (p+2)-th difference on -(p/2 + 1) ... p/2 + 1 with end weights +1 (the
///    Kreiss-Oliger operator's stencil), which annihilates polynomials of degree <= p + 1;
///  - upwind_sum<u>: plus + minus of the upwind pair u. Their difference is a symmetric stencil
///    that annihilates degree <= p, i.e. `upwind_ratio<u>` times `difference` (checked here at
///    compile time), so each upwind derivative is (upwind_sum +/- upwind_ratio difference) / 2.
///    The biased pair's sum is twice the centred derivative of order p + 2 (also checked).
template <int p>
struct Order {
  static_assert(valid_order(p), "finite-difference orders are 2, 4, 6 and 8");
  static constexpr int half = p / 2;
  static constexpr int radius = half + 1; ///< the widest reach: upwind and dissipation
  static_assert(stencil_radius(p) == static_cast<std::size_t>(radius));
  static constexpr std::size_t n_centred = 2 * half + 1, n_wide = 2 * radius + 1;

  static constexpr auto d1_exact = fornberg<n_centred>(1, -half);
  static constexpr auto d2_exact = fornberg<n_centred>(2, -half);
  static constexpr auto plus_exact = fornberg<n_centred>(1, -(half - 1));
  static constexpr auto biased_plus_exact = fornberg<n_centred + 1>(1, -half);
  static constexpr auto difference_exact = detail::difference_weights<n_wide>();
  static constexpr auto sum_exact = detail::combine<n_centred, -(half - 1), radius>(+1);
  static constexpr auto plus_minus_minus = detail::combine<n_centred, -(half - 1), radius>(-1);
  static constexpr auto biased_sum_exact = detail::combine<n_centred + 1, -half, radius>(+1);
  static constexpr auto biased_plus_minus_minus = detail::combine<n_centred + 1, -half, radius>(-1);
  /// each upwind pair's plus - minus is a multiple of the difference (asserted below)
  static constexpr bool upwind_is_difference() {
    return detail::proportional(plus_minus_minus, difference_exact)
           && detail::proportional(biased_plus_minus_minus, difference_exact);
  }
  /// the biased pair's half sum is the centred first derivative of order p + 2
  static constexpr bool biased_sum_is_centred() {
    const auto centred = fornberg<n_wide>(1, -radius);
    for (std::size_t k = 0; k < n_wide; ++k)
      if (!(biased_sum_exact[k] == Rational(2) * centred[k]))
        return false;
    return true;
  }

  static constexpr Stencil<n_centred> d1 = Stencil<n_centred>::from(d1_exact, -half);
  static constexpr Stencil<n_centred> d2 = Stencil<n_centred>::from(d2_exact, -half);
  static constexpr Stencil<n_centred> lopsided_plus =
      Stencil<n_centred>::from(plus_exact, -(half - 1));
  static constexpr Stencil<n_centred> lopsided_minus =
      Stencil<n_centred>::from(fornberg<n_centred>(1, -(half + 1)), -(half + 1));
  static constexpr Stencil<n_centred + 1> biased_plus =
      Stencil<n_centred + 1>::from(biased_plus_exact, -half);
  static constexpr Stencil<n_centred + 1> biased_minus =
      Stencil<n_centred + 1>::from(fornberg<n_centred + 1>(1, -(half + 1)), -(half + 1));
  static constexpr Stencil<n_wide> difference = Stencil<n_wide>::from(difference_exact, -radius);
  static constexpr Stencil<n_wide> lopsided_sum = Stencil<n_wide>::from(sum_exact, -radius);
  static constexpr Stencil<n_wide> biased_sum = Stencil<n_wide>::from(biased_sum_exact, -radius);
  /// c of plus - minus = c difference (the difference's end weight is 1), per upwind pair
  static constexpr Rational upwind_ratio_exact = plus_minus_minus[0];
  static constexpr Rational biased_ratio_exact = biased_plus_minus_minus[0];
  template <Upwind u>
  static constexpr double upwind_ratio_of = u == Upwind::biased
                                                ? static_cast<double>(biased_ratio_exact.p)
                                                      / static_cast<double>(biased_ratio_exact.q)
                                                : static_cast<double>(upwind_ratio_exact.p)
                                                      / static_cast<double>(upwind_ratio_exact.q);
  static constexpr double upwind_ratio = upwind_ratio_of<Upwind::lopsided>;
  template <Upwind u>
  static constexpr const Stencil<n_wide>& upwind_sum() {
    if constexpr (u == Upwind::biased)
      return biased_sum;
    else
      return lopsided_sum;
  }

  /// The highest grid mode (-1)^j gives difference = (-1)^radius 2^(2 radius); the dissipation
  /// Q f = sigma/dx dissipation_sign difference(f) / 2^(2 radius) damps it at the rate sigma/dx.
  static constexpr double dissipation_sign = radius % 2 == 0 ? -1.0 : 1.0;
  static constexpr double dissipation_norm =
      1.0 / static_cast<double>(std::int64_t{1} << (2 * radius));
};

static_assert(Order<2>::upwind_is_difference() && Order<4>::upwind_is_difference()
                  && Order<6>::upwind_is_difference() && Order<8>::upwind_is_difference(),
              "an upwind pair's plus - minus must be a multiple of the (p+2)-th difference");
static_assert(Order<2>::biased_sum_is_centred() && Order<4>::biased_sum_is_centred()
                  && Order<6>::biased_sum_is_centred() && Order<8>::biased_sum_is_centred(),
              "the biased pair's half sum must be the centred derivative of order p + 2");

// The operators of order p, each times dx to its derivative's power.

template <int p>
[[gnu::always_inline]] inline double d1_centred(const double* f) {
  return Order<p>::d1(f);
}
template <int p>
[[gnu::always_inline]] inline double d2_centred(const double* f) {
  return Order<p>::d2(f);
}
template <int p>
[[gnu::always_inline]] inline double d1_lopsided_plus(const double* f) {
  return Order<p>::lopsided_plus(f);
}
/// The mirror image of d1_lopsided_plus, leaning towards -x.
template <int p>
[[gnu::always_inline]] inline double d1_lopsided_minus(const double* f) {
  return Order<p>::lopsided_minus(f);
}
template <int p>
[[gnu::always_inline]] inline double d1_biased_plus(const double* f) {
  return Order<p>::biased_plus(f);
}
template <int p>
[[gnu::always_inline]] inline double d1_biased_minus(const double* f) {
  return Order<p>::biased_minus(f);
}
/// plus + minus of the upwind pair u (Order).
template <int p, Upwind u = Upwind::lopsided>
[[gnu::always_inline]] inline double upwind_sum(const double* f) {
  return Order<p>::template upwind_sum<u>()(f);
}
template <int p>
[[gnu::always_inline]] inline double lopsided_sum(const double* f) {
  return upwind_sum<p, Upwind::lopsided>(f);
}
/// The (p+2)-th difference (Kreiss-Oliger stencil, without sign and normalisation).
template <int p>
[[gnu::always_inline]] inline double difference(const double* f) {
  return Order<p>::difference.sum(f);
}

/// Upwinded advection v f_x from upwind_sum<p, u>(f) and difference(f), branch-free:
///   v (S/2 + sign(v) c D/2) = v S/2 + |v| c D/2,  c = upwind_ratio_of<u>.
template <int p, Upwind u = Upwind::lopsided>
[[gnu::always_inline]] inline double advect_from(double beta, double upwind_sum,
                                                 double difference) {
  return 0.5 * beta * upwind_sum
         + (0.5 * Order<p>::template upwind_ratio_of<u>)*(beta < 0.0 ? -beta : beta) * difference;
}

/// Upwinded advection v f_x: the upwind stencil u leaning towards the direction the flow comes
/// from, times dx. The shift term beta d_r f of the equations is advection with velocity
/// -beta, so the stencil leans towards +x where beta > 0.
/// (With a branch; the point loops use advect_from.)
template <int p, Upwind u = Upwind::lopsided>
inline double advect(double beta, const double* f) {
  if constexpr (u == Upwind::biased)
    return beta * (beta > 0.0 ? d1_biased_plus<p>(f) : d1_biased_minus<p>(f));
  else
    return beta * (beta > 0.0 ? d1_lopsided_plus<p>(f) : d1_lopsided_minus<p>(f));
}

/// 4th-order one-sided (backward) first derivative, times dx; reads f[-4] ... f[0] (the outer
/// boundary condition, at every order).
inline constexpr Stencil<5> backward4 = Stencil<5>::from(fornberg<5>(1, -4), -4);
/// Summed from f[0] outwards, the way the largest weights come first (the boundary values nearly
/// cancel: this order keeps the rounding of the classic formula).
inline double d1_backward(const double* f) {
  double s = static_cast<double>(backward4.weight[4]) * f[0];
#pragma GCC unroll 4
  for (int k = 3; k >= 0; --k)
    s += static_cast<double>(backward4.weight[static_cast<std::size_t>(k)]) * f[k - 4];
  return s * (1.0 / static_cast<double>(backward4.denominator));
}

} // namespace gbssn1d::fd
