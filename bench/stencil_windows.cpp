// The stencils of the point loop, two ways (stencil_windows.hpp). The hypothesis tested
// (docs/roofline.md, Sec. 3): the 4th-order loop is bound by its loads, most of them unaligned
// loads of each field's neighbours f[i-3] ... f[i+3], about two per neighbour; loading each
// field's block once, as aligned vectors, and forming the shifted windows in registers (AVX-512
// valignq) would take the stencils' share of the loop's time down.
//
// Both versions evaluate the same stencils of fd::Order<4> (Stencil::sum takes a pointer or a
// window of vectors) in the same order, on the same staged layout: each input row at a
// compile-time offset from one base (as GbssnRhs::interior stages them), 64-byte aligned.
#include "stencil_windows.hpp"

#include "fd/stencils.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <utility>

namespace {

constexpr int order = 4;
using O = gbssn1d::fd::Order<order>;
constexpr int R = O::radius;
constexpr std::size_t n_fields = 9, beta = 5; // beta: the field whose value advects the rest
constexpr std::size_t B = 256;                // points per block (GbssnRhs::block_size)
constexpr std::size_t pad = 8;                // >= R, a whole 64-byte line before each row
constexpr std::size_t stride = B + 2 * pad;   // doubles from one row to the next
static_assert(pad >= static_cast<std::size_t>(R));

/// The per-block constants of the loop: 1/dx, the dissipation's and the advection's factors.
struct Factors {
  double inv_dx = 64.0, ko_scale = -0.01, half_ratio = 0.5 * O::upwind_ratio;
};

/// One point's terms of field f (a pointer at the point, or a window), with the point's grid
/// factors: what gather() and the point loop make of its stencils, summed into one result.
template <class F, class T>
[[gnu::always_inline]] inline T field_terms(const F& f, T inv_rx, T d2_fx, T beta_r, T abs_beta_r,
                                            const Factors& c) {
  const T d1_scale = c.inv_dx * inv_rx, d2_scale = d1_scale * d1_scale;
  const T d1 = O::d1(f), d2 = O::d2(f), diff = O::difference.sum(f),
          upwind = O::lopsided_sum.sum(f);
  const T d = d1 * d1_scale;
  const T dd = d2 * d2_scale + d1 * c.inv_dx * d2_fx;
  const T adv = 0.5 * beta_r * upwind + c.half_ratio * abs_beta_r * diff;
  return f[0] + d + dd + adv + c.ko_scale * inv_rx * diff;
}

/// sum_k w[k] f[first + k] in two partial sums (alternate non-zero terms), added at the end:
/// half of Stencil::sum's chain of dependent FMAs, for one multiply and one add more. Tests
/// whether the chains' latency limits the loop (docs/roofline.md, Sec. 7).
template <std::size_t n>
[[gnu::always_inline]] inline double tree_sum(const gbssn1d::fd::Stencil<n>& st, const double* f) {
  double s[2] = {0.0, 0.0};
  bool started[2] = {false, false};
  int which = 0;
#pragma GCC unroll 16
  for (std::size_t k = 0; k < n; ++k) {
    if (st.weight[k] == 0)
      continue;
    const double t = static_cast<double>(st.weight[k]) * f[st.first + static_cast<int>(k)];
    s[which] = started[which] ? s[which] + t : t;
    started[which] = true;
    which = 1 - which;
  }
  return started[1] ? s[0] + s[1] : s[0];
}
/// field_terms with each stencil in two partial sums (tree_sum).
[[gnu::always_inline]] inline double field_terms_tree(const double* f, double inv_rx, double d2_fx,
                                                      double beta_r, double abs_beta_r,
                                                      const Factors& c) {
  const double d1_scale = c.inv_dx * inv_rx, d2_scale = d1_scale * d1_scale;
  const double d1 = tree_sum(O::d1, f) * (1.0 / static_cast<double>(O::d1.denominator)),
               d2 = tree_sum(O::d2, f) * (1.0 / static_cast<double>(O::d2.denominator)),
               diff = tree_sum(O::difference, f), upwind = tree_sum(O::lopsided_sum, f);
  const double d = d1 * d1_scale;
  const double dd = d2 * d2_scale + d1 * c.inv_dx * d2_fx;
  const double adv = 0.5 * beta_r * upwind + c.half_ratio * abs_beta_r * diff;
  return f[0] + d + dd + adv + c.ko_scale * inv_rx * diff;
}
/// As the point loop, with each stencil in two partial sums.
void stencils_tree(const double* in, const double* inv_rx, const double* d2_fx, double* out,
                   const Factors& c) {
#pragma GCC ivdep
  for (std::size_t i = 0; i < B; ++i) {
    const double beta_r = in[beta * stride + i] * c.inv_dx * inv_rx[i];
    const double abs_beta_r = beta_r < 0.0 ? -beta_r : beta_r;
#pragma GCC unroll 16
    for (std::size_t v = 0; v < n_fields; ++v)
      out[v * stride + i] =
          field_terms_tree(in + v * stride + i, inv_rx[i], d2_fx[i], beta_r, abs_beta_r, c);
  }
}

/// The neighbours of a point as sums f[k] + f[-k] and differences f[k] - f[-k] (k = 1 ... R):
/// a symmetric stencil (d2, the difference) reads the sums, an antisymmetric one (d1, the
/// upwind sum) the differences.
template <class T>
struct Pairs {
  T f0, sum[R + 1], diff[R + 1];
  template <class F>
  explicit Pairs(const F& f) : f0(f[0]) {
    for (int k = 1; k <= R; ++k) {
      sum[k] = f[k] + f[-k];
      diff[k] = f[k] - f[-k];
    }
  }
  /// sum_k w[k] f[first + k] of a stencil on -radius ... radius (symmetric or antisymmetric)
  template <std::size_t n>
  [[gnu::always_inline]] T apply(const gbssn1d::fd::Stencil<n>& s) const {
    // zero weights left out, as Stencil::sum does (0 x f0 is not folded: f0 may be infinite)
    const int radius = -s.first;
    const bool symmetric = s.weight[0] == s.weight[n - 1];
    T t{};
    bool started = false;
    if (s.weight[static_cast<std::size_t>(radius)] != 0) {
      t = static_cast<double>(s.weight[static_cast<std::size_t>(radius)]) * f0;
      started = true;
    }
    for (int k = 1; k <= radius; ++k) {
      const std::int64_t w = s.weight[static_cast<std::size_t>(radius + k)];
      if (w == 0)
        continue;
      const T term = static_cast<double>(w) * (symmetric ? sum[k] : diff[k]);
      t = started ? t + term : term;
      started = true;
    }
    return t;
  }
};

/// field_terms with the stencils summed from the pairs.
template <class T>
[[gnu::always_inline]] inline T field_terms_pairs(const Pairs<T>& f, T inv_rx, T d2_fx, T beta_r,
                                                  T abs_beta_r, const Factors& c) {
  const T d1_scale = c.inv_dx * inv_rx, d2_scale = d1_scale * d1_scale;
  const T d1 = f.apply(O::d1) * (1.0 / static_cast<double>(O::d1.denominator)),
          d2 = f.apply(O::d2) * (1.0 / static_cast<double>(O::d2.denominator)),
          diff = f.apply(O::difference), upwind = f.apply(O::lopsided_sum);
  const T d = d1 * d1_scale;
  const T dd = d2 * d2_scale + d1 * c.inv_dx * d2_fx;
  const T adv = 0.5 * beta_r * upwind + c.half_ratio * abs_beta_r * diff;
  return f.f0 + d + dd + adv + c.ko_scale * inv_rx * diff;
}

/// As the point loop, with each field's stencils from its pairs.
void stencils_pairs(const double* in, const double* inv_rx, const double* d2_fx, double* out,
                    const Factors& c) {
#pragma GCC ivdep
  for (std::size_t i = 0; i < B; ++i) {
    const double beta_r = in[beta * stride + i] * c.inv_dx * inv_rx[i];
    const double abs_beta_r = beta_r < 0.0 ? -beta_r : beta_r;
#pragma GCC unroll 16
    for (std::size_t v = 0; v < n_fields; ++v)
      out[v * stride + i] = field_terms_pairs(Pairs<double>(in + v * stride + i), inv_rx[i],
                                              d2_fx[i], beta_r, abs_beta_r, c);
  }
}

/// As the point loop: a scalar loop over the block's points, vectorised by GCC at the width it
/// prefers for the target (-march=native: 512 bits on Sapphire Rapids, 256 on Ice Lake).
void stencils_autovectorised(const double* in, const double* inv_rx, const double* d2_fx,
                             double* out, const Factors& c) {
#pragma GCC ivdep
  for (std::size_t i = 0; i < B; ++i) {
    const double beta_r = in[beta * stride + i] * c.inv_dx * inv_rx[i];
    const double abs_beta_r = beta_r < 0.0 ? -beta_r : beta_r;
#pragma GCC unroll 16
    for (std::size_t v = 0; v < n_fields; ++v)
      out[v * stride + i] =
          field_terms(in + v * stride + i, inv_rx[i], d2_fx[i], beta_r, abs_beta_r, c);
  }
}

/// The same, vectorised at 512 bits where the target has them (the width of windows-8).
[[gnu::target("prefer-vector-width=512")]] void
stencils_autovectorised_512(const double* in, const double* inv_rx, const double* d2_fx,
                            double* out, const Factors& c) {
#pragma GCC ivdep
  for (std::size_t i = 0; i < B; ++i) {
    const double beta_r = in[beta * stride + i] * c.inv_dx * inv_rx[i];
    const double abs_beta_r = beta_r < 0.0 ? -beta_r : beta_r;
#pragma GCC unroll 16
    for (std::size_t v = 0; v < n_fields; ++v)
      out[v * stride + i] =
          field_terms(in + v * stride + i, inv_rx[i], d2_fx[i], beta_r, abs_beta_r, c);
  }
}

// GCC's vector extensions (a vector_size attribute on a dependent alias is dropped, hence one
// specialisation per width)
template <int L>
struct VectorOf;
template <>
struct VectorOf<4> {
  typedef double type __attribute__((vector_size(32)));
  typedef long mask __attribute__((vector_size(32)));
};
template <>
struct VectorOf<8> {
  typedef double type __attribute__((vector_size(64)));
  typedef long mask __attribute__((vector_size(64)));
};
template <int L>
using Vec = typename VectorOf<L>::type;
template <int L>
using Mask = typename VectorOf<L>::mask;

template <int L, std::size_t... j>
constexpr Mask<L> lanes_from(long s, std::index_sequence<j...>) {
  return Mask<L>{(s + static_cast<long>(j))...};
}
/// f[i+k ... i+k+L-1] from the aligned vectors before, at and after i (k in -R ... R).
template <int L, int k>
[[gnu::always_inline]] inline Vec<L> shifted(Vec<L> before, Vec<L> at, Vec<L> after) {
  constexpr auto seq = std::make_index_sequence<L>{};
  if constexpr (k == 0)
    return at;
  else if constexpr (k < 0)
    return __builtin_shuffle(before, at, lanes_from<L>(L + k, seq));
  else
    return __builtin_shuffle(at, after, lanes_from<L>(k, seq));
}
/// The neighbours -R ... R of L points as vectors: f[k] for the stencils.
template <int L>
struct Window {
  Vec<L> w[2 * R + 1];
  Vec<L> operator[](int k) const { return w[k + R]; }
};
template <int L, int... k>
[[gnu::always_inline]] inline Window<L> window(const double* f, std::integer_sequence<int, k...>) {
  const Vec<L> before = *reinterpret_cast<const Vec<L>*>(f - L),
               at = *reinterpret_cast<const Vec<L>*>(f),
               after = *reinterpret_cast<const Vec<L>*>(f + L);
  return Window<L>{{shifted<L, k - R>(before, at, after)...}};
}

/// Explicit vectors of L doubles: three aligned loads per field and L points.
template <int L>
void stencils_windows(const double* in, const double* inv_rx_row, const double* d2_fx_row,
                      double* out, const Factors& c) {
  static_assert(L >= R && pad % L == 0 && B % L == 0);
  using V = Vec<L>;
  for (std::size_t i = 0; i < B; i += L) {
    const V inv_rx = *reinterpret_cast<const V*>(inv_rx_row + i),
            d2_fx = *reinterpret_cast<const V*>(d2_fx_row + i);
    const V beta_r = *reinterpret_cast<const V*>(in + beta * stride + i) * c.inv_dx * inv_rx;
    const V abs_beta_r = beta_r < 0.0 ? -beta_r : beta_r;
#pragma GCC unroll 16
    for (std::size_t v = 0; v < n_fields; ++v) {
      const Window<L> w =
          window<L>(in + v * stride + i, std::make_integer_sequence<int, 2 * R + 1>{});
      *reinterpret_cast<V*>(out + v * stride + i) =
          field_terms(w, inv_rx, d2_fx, beta_r, abs_beta_r, c);
    }
  }
}

struct Aligned {
  double* p;
  explicit Aligned(std::size_t n)
      : p(static_cast<double*>(std::aligned_alloc(64, (n * sizeof(double) + 63) / 64 * 64))) {}
  ~Aligned() { std::free(p); }
  Aligned(const Aligned&) = delete;
  Aligned& operator=(const Aligned&) = delete;
};

} // namespace

void print_stencil_windows(double seconds) {
  // smooth data with a shift of both signs, on one block; rows as staged: value i at row + i
  Aligned in(n_fields * stride + pad), grid(2 * stride), out_a(n_fields * stride),
      out_b(n_fields * stride);
  double* const rows = in.p + pad;
  for (std::size_t v = 0; v < n_fields; ++v)
    for (std::size_t j = 0; j < stride; ++j) {
      const double x = (static_cast<double>(j) - static_cast<double>(pad)) / B;
      rows[v * stride + j - pad] = std::sin(3.0 * x + static_cast<double>(v)) + 0.1 * x * x;
    }
  for (std::size_t i = 0; i < B; ++i) {
    grid.p[i] = 1.0 + 0.5 * std::cos(0.01 * static_cast<double>(i));     // inv_rx
    grid.p[stride + i] = 0.01 * std::sin(0.02 * static_cast<double>(i)); // d2_fx
  }
  const Factors c;
  using Kernel = void (*)(const double*, const double*, const double*, double*, const Factors&);
  struct Version {
    const char* name;
    Kernel kernel;
    double seconds = 0.0;
    long calls = 0;
    double fastest = 1e300; // the least time of one chunk: on a quiet core
  };
  Version versions[] = {{"autovectorised", stencils_autovectorised},
                        {"autovectorised-512", stencils_autovectorised_512},
                        {"windows-4", stencils_windows<4>},
                        {"windows-8", stencils_windows<8>},
                        {"pairs", stencils_pairs},
                        {"tree", stencils_tree}};
  // the versions' results: each against the point loop's way
  double largest = 0.0, difference = 0.0;
  stencils_autovectorised(rows, grid.p, grid.p + stride, out_a.p, c);
  for (const Version& version : versions) {
    version.kernel(rows, grid.p, grid.p + stride, out_b.p, c);
    for (std::size_t v = 0; v < n_fields; ++v)
      for (std::size_t i = 0; i < B; ++i) {
        largest = std::max(largest, std::abs(out_a.p[v * stride + i]));
        difference =
            std::max(difference, std::abs(out_a.p[v * stride + i] - out_b.p[v * stride + i]));
      }
  }
  using clock = std::chrono::steady_clock;
  constexpr int chunk = 200;
  const auto start = clock::now();
  while (std::chrono::duration<double>(clock::now() - start).count() < seconds)
    for (Version& version : versions) {
      const auto t0 = clock::now();
      for (int k = 0; k < chunk; ++k) {
        version.kernel(rows, grid.p, grid.p + stride, out_b.p, c);
        asm volatile("" ::: "memory"); // every call's stores happen
      }
      const double t = std::chrono::duration<double>(clock::now() - t0).count();
      version.seconds += t;
      version.fastest = std::min(version.fastest, t);
      version.calls += chunk;
    }
  fmt::print("# the point loop's stencils alone (4th order, 9 fields, blocks of {} points), "
             "alternating chunks for {:.3g} s; largest difference from the autovectorised "
             "results {:.3g} of the largest value\n",
             B, seconds, difference / largest);
  fmt::print("# version ns_per_point time_over_autovectorised fastest_chunk_ns_per_point "
             "fastest_over_autovectorised's (chunks of {} calls; the fastest: a quiet core)\n",
             chunk);
  for (const Version& version : versions)
    fmt::print("{} {:.3f} {:.3f} {:.3f} {:.3f}\n", version.name,
               1e9 * version.seconds / (static_cast<double>(version.calls) * B),
               version.seconds / versions[0].seconds, 1e9 * version.fastest / (chunk * B),
               version.fastest / versions[0].fastest);
}
