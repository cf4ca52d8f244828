#include "mesh/prolong_rows.hpp"

#include "mesh/transfer.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <stdexcept>

namespace gbssn1d::mesh {

namespace {

/// s = sum_m w[m] a[m] (m = 0 ... M - 1, in that order) on the cells [lo, hi) of each of `rows`
/// rows of nt points (interior cell i at g + i): the loop over the cells vectorises, each sum
/// in a register (summing one array at a time through memory waited on store forwarding).
template <std::size_t M>
void combine_rows(const State* const* a, const double* w, State& s, std::size_t rows,
                  std::size_t nt, std::size_t g, long lo, long hi) {
  for (std::size_t v = 0; v < rows; ++v) {
    const std::size_t row = v * nt + g;
    std::array<const double*, M> f{};
    for (std::size_t m = 0; m < M; ++m)
      f[m] = a[m]->data() + row;
    double* const out = s.data() + row;
    for (long i = lo; i < hi; ++i) {
      double sum = 0.0;
#pragma GCC unroll 8
      for (std::size_t m = 0; m < M; ++m)
        sum = combination_term(sum, w[m], f[m][i]);
      out[i] = sum;
    }
  }
}

/// The coarse cells a fused fill (fill_rows) holds per row, at most.
constexpr long fused_cells = 64;

/// fine[j] for the interior cells j in [j_begin, j_end) of each of `rows` rows (at most
/// n_vars): the parent's arrays combined as combine_rows does on the coarse cells [lo, hi)
/// (0 <= lo, hi - lo <= fused_cells) into a local array, every row first, then prolonged from
/// it as prolong_field does. The same sums in the same order, so the same bits; gone are the
/// round trip through the parent's scratch rows and the mirror's branch (the fill of each stage
/// of every box, a tenth of a box run). All rows are combined before any is prolonged: a
/// prolongation reading a row just stored waits on store forwarding.
template <std::size_t M>
void fill_rows(const State* const* a, const double* w, std::size_t rows, std::size_t nt_c,
               State& fine, std::size_t nt_f, long lo, long hi, long j_begin, long j_end) {
  const std::size_t g = Grid::n_ghost, cells = static_cast<std::size_t>(hi - lo);
  std::array<double, n_vars * fused_cells> combined; // row v, coarse cell i: v * cells + i - lo
  for (std::size_t v = 0; v < rows; ++v) {
    std::array<const double*, M> f{};
    for (std::size_t m = 0; m < M; ++m)
      f[m] = a[m]->data() + v * nt_c + g + lo;
    double* const c = combined.data() + v * cells;
    for (std::size_t i = 0; i < cells; ++i) {
      double sum = 0.0;
#pragma GCC unroll 8
      for (std::size_t m = 0; m < M; ++m)
        sum = combination_term(sum, w[m], f[m][i]);
      c[i] = sum;
    }
  }
  for (std::size_t v = 0; v < rows; ++v) {
    const double* const c = combined.data() + v * cells; // c[i - lo]: coarse cell i
    double* const out = fine.data() + v * nt_f + g;
    // fine cell 2i at -1/4 from coarse centre i reads cells i-3 ... i+2, fine cell 2i+1 at
    // +1/4 reads i-2 ... i+3 (prolong_field): a pair's m-th terms are neighbours in c
    auto one = [&](long j, const std::array<double, 6>& wj, long first) {
      double sum = 0.0;
      for (std::size_t m = 0; m < 6; ++m)
        sum += wj[m] * c[first - lo + static_cast<long>(m)];
      out[j] = sum;
    };
    long j = j_begin;
    if ((j & 1) == 1) {
      one(j, prolong_weights_plus, j / 2 - 2);
      ++j;
    }
    for (; j + 1 < j_end; j += 2) {
      const double* const cm = c + (j / 2 - 3 - lo);
      double minus = 0.0, plus = 0.0;
      for (std::size_t m = 0; m < 6; ++m) {
        minus += prolong_weights_minus[m] * cm[m];
        plus += prolong_weights_plus[m] * cm[m + 1];
      }
      out[j] = minus;
      out[j + 1] = plus;
    }
    if (j < j_end)
      one(j, prolong_weights_minus, j / 2 - 3);
  }
}

} // namespace

void prolong_combination(std::span<const State* const> arrays, std::span<const double> weights,
                         const Grid& gc, State& fine, const Grid& gf, long j_begin,
                         State& scratch) {
  if (arrays.empty() || arrays.size() != weights.size())
    throw std::logic_error("prolong_combination needs one weight per array");
  const long j_end = static_cast<long>(gf.n_interior() + Grid::n_ghost);
  // the coarse cells the prolongation reads: floor(j/2) - 3 ... floor(j/2) + 3, mirrored below 0
  long lo = j_begin / 2 - 3;
  long hi = (j_end - 1) / 2 + 4;
  // The parent's arrays need not be of one formulation's count: the rows are those of the
  // state (size / nt).
  const std::size_t nt = gc.n_total(), g = Grid::n_ghost;
  const std::size_t size = arrays.front()->size();
  const std::size_t rows = size / nt;
  const State* const* const a = arrays.data();
  const double* const w = weights.data();
  if (lo >= 0 && hi - lo <= fused_cells && rows <= n_vars) { // away from the origin's mirror
    const std::size_t nt_f = gf.n_total();
    switch (arrays.size()) { // the counts the callers pass: each sum's terms in registers
    case 1:
      return fill_rows<1>(a, w, rows, nt, fine, nt_f, lo, hi, j_begin, j_end);
    case 2:
      return fill_rows<2>(a, w, rows, nt, fine, nt_f, lo, hi, j_begin, j_end);
    case 3:
      return fill_rows<3>(a, w, rows, nt, fine, nt_f, lo, hi, j_begin, j_end);
    case 5:
      return fill_rows<5>(a, w, rows, nt, fine, nt_f, lo, hi, j_begin, j_end);
    default:
      throw std::logic_error("prolong_combination combines 1, 2, 3 or 5 arrays");
    }
  }
  if (lo < 0) {
    hi = std::max(hi, -lo);
    lo = 0;
  }
  // near the origin: scratch = sum_m w[m] arrays[m] on the cells [lo, hi) of every variable,
  // then prolong_field with the mirror
  scratch.fit(*arrays.front());
  switch (arrays.size()) {
  case 1:
    combine_rows<1>(a, w, scratch, rows, nt, g, lo, hi);
    break;
  case 2:
    combine_rows<2>(a, w, scratch, rows, nt, g, lo, hi);
    break;
  case 3:
    combine_rows<3>(a, w, scratch, rows, nt, g, lo, hi);
    break;
  case 5:
    combine_rows<5>(a, w, scratch, rows, nt, g, lo, hi);
    break;
  default:
    throw std::logic_error("prolong_combination combines 1, 2, 3 or 5 arrays");
  }
  prolong(scratch, gc, fine, gf, j_begin, j_end);
}

} // namespace gbssn1d::mesh
