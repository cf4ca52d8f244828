// The machine's ceilings for the roofline of the right-hand side (docs/roofline.md): one core's
// clock, its double-precision arithmetic throughput at each vector width, its division
// throughput, and its memory bandwidth from each level of the cache hierarchy.
//
//   build/gbssn1d_bench --sections peak [--fma-latency 4]
//
// Each figure is the best of several repetitions (the ceiling, not the average: a shared machine
// only ever slows a repetition down). The kernels are GCC vector extensions of 1, 4 and 8 doubles
// (scalar, 256-bit and 512-bit registers), compiled with the project's flags (-march=native), so
// they use whatever the kernel of gbssn1d can use:
//  - clock: a chain of dependent FMAs, each waiting for the last; cycles = chain length x the
//    FMA latency (`--fma-latency`, 4 cycles on the Intel and AMD cores of the last decade);
//  - FMA and multiply throughput: 12 independent chains, enough to fill two pipelined units;
//  - division throughput: 8 independent chains;
//  - bandwidth: the sum of an array (read) and a = b + s c (triad: two reads, one write, counted
//    as 24 bytes per element), for arrays that fit L1, L2, the shared L3, and none of them;
//  - front end: loops of K seven-byte NOPs (x86-64 only), code of 0.9 to 14 KiB a loop: the
//    bytes of code the core fetches and decodes a cycle when nothing else limits it (a loop that
//    fits the decoded-instruction cache streams from it; one that does not is decoded again each
//    iteration, at 16 bytes a cycle on Intel cores). The point loop is 3.7 KiB of code
//    (bench/loop_mix.py), so this says whether its size alone could bound it.
#include "machine_ceilings.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace {

using clock_type = std::chrono::steady_clock;

/// The least time of `repeats` calls of f (each call's own time), in seconds.
double best_of(int repeats, const std::function<void()>& f) {
  double best = 1e300;
  for (int k = 0; k < repeats; ++k) {
    const auto t0 = clock_type::now();
    f();
    best = std::min(best, std::chrono::duration<double>(clock_type::now() - t0).count());
  }
  return best;
}

/// Keeps a value alive without letting the compiler see through it.
template <class T>
void keep(T& v) {
  asm volatile("" : "+x"(v));
}
template <class T>
void keep_memory(T* p) {
  asm volatile("" : : "r"(p) : "memory");
}

// GCC's vector extensions (an attribute on a dependent size is ignored, so each width is spelled)
using v4 = double __attribute__((vector_size(32)));
using v8 = double __attribute__((vector_size(64)));
template <int lanes>
struct Vec;
template <>
struct Vec<1> {
  using type = double;
};
template <>
struct Vec<4> {
  using type = v4;
};
template <>
struct Vec<8> {
  using type = v8;
};

/// n dependent FMAs x = x a + b (the chain's latency).
template <int lanes>
void fma_chain(long n) {
  using V = typename Vec<lanes>::type;
  V x = V{} + 1.0, a = V{} + 0.999999, b = V{} + 1e-7;
  keep(a);
  keep(b);
  for (long i = 0; i < n; ++i) {
    x = x * a + b;
    keep(x);
  }
  keep(x);
}

/// n rounds of 12 independent FMAs (or multiplications, mul = true), each chain in a register of
/// its own (named: an array of them is kept in memory).
template <int lanes, bool mul>
void throughput(long n) {
  using V = typename Vec<lanes>::type;
  V a = V{} + 0.999999, b = V{} + 1e-7;
  keep(a);
  keep(b);
  V x0 = a + 0.1, x1 = a + 0.2, x2 = a + 0.3, x3 = a + 0.4, x4 = a + 0.5, x5 = a + 0.6,
    x6 = a + 0.7, x7 = a + 0.8, x8 = a + 0.9, x9 = a + 1.0, x10 = a + 1.1, x11 = a + 1.2;
  const auto op = [&](V x) { return mul ? x * a : x * a + b; };
  for (long i = 0; i < n; ++i) {
    x0 = op(x0), x1 = op(x1), x2 = op(x2), x3 = op(x3), x4 = op(x4), x5 = op(x5);
    x6 = op(x6), x7 = op(x7), x8 = op(x8), x9 = op(x9), x10 = op(x10), x11 = op(x11);
    asm volatile(""
                 : "+x"(x0), "+x"(x1), "+x"(x2), "+x"(x3), "+x"(x4), "+x"(x5), "+x"(x6), "+x"(x7),
                   "+x"(x8), "+x"(x9), "+x"(x10), "+x"(x11));
  }
}

/// n rounds of 8 independent divisions.
template <int lanes>
void divisions(long n) {
  using V = typename Vec<lanes>::type;
  V a = V{} + 1.0000001;
  keep(a);
  V x0 = a + 1.0, x1 = a + 2.0, x2 = a + 3.0, x3 = a + 4.0, x4 = a + 5.0, x5 = a + 6.0,
    x6 = a + 7.0, x7 = a + 8.0;
  for (long i = 0; i < n; ++i) {
    x0 = a / x0, x1 = a / x1, x2 = a / x2, x3 = a / x3;
    x4 = a / x4, x5 = a / x5, x6 = a / x6, x7 = a / x7;
    asm volatile(""
                 : "+x"(x0), "+x"(x1), "+x"(x2), "+x"(x3), "+x"(x4), "+x"(x5), "+x"(x6), "+x"(x7));
  }
}

using V8 = Vec<8>::type;

/// The sum of `n` doubles at `a` (8-lane accumulators, 4 of them: reads only).
double read_sum(const V8* a, std::size_t n) {
  V8 s[4] = {};
  for (std::size_t i = 0; i + 4 <= n / 8; i += 4)
#pragma GCC unroll 4
    for (int c = 0; c < 4; ++c)
      s[c] += a[i + static_cast<std::size_t>(c)];
  V8 t = s[0] + s[1] + s[2] + s[3];
  double r = 0.0;
  for (int l = 0; l < 8; ++l)
    r += t[l];
  return r;
}

/// a = b + s c over n doubles.
void triad(V8* a, const V8* b, const V8* c, double s, std::size_t n) {
  for (std::size_t i = 0; i < n / 8; ++i)
    a[i] = b[i] + s * c[i];
}

struct Bandwidth {
  double read, triad; // bytes per second
};

/// Read and triad bandwidth for arrays of `bytes` each, repeated to about `seconds`.
Bandwidth bandwidth(std::size_t bytes, double seconds) {
  const std::size_t n = bytes / sizeof(double) / 32 * 32; // whole 4 x 8-lane rounds
  std::vector<V8> a(n / 8), b(n / 8), c(n / 8);
  for (std::size_t i = 0; i < n / 8; ++i) {
    a[i] = V8{} + 1.0;
    b[i] = V8{} + 2.0;
    c[i] = V8{} + 1e-3 * static_cast<double>(i % 7);
  }
  // repetitions per timing: about 1 ms of work each
  const long reps = std::max(1L, static_cast<long>(2e6 / static_cast<double>(n)));
  const int rounds = std::max(3, static_cast<int>(seconds / 2e-3));
  double sink = 0.0;
  const double t_read = best_of(rounds, [&] {
    for (long r = 0; r < reps; ++r) {
      sink += read_sum(b.data(), n);
      keep_memory(b.data());
    }
  });
  const double t_triad = best_of(rounds, [&] {
    for (long r = 0; r < reps; ++r) {
      triad(a.data(), b.data(), c.data(), 0.5, n);
      keep_memory(a.data());
    }
  });
  keep(sink);
  const double elements = static_cast<double>(n) * static_cast<double>(reps);
  return {8.0 * elements / t_read, 24.0 * elements / t_triad};
}

#if defined(__x86_64__)
/// n iterations of a loop of K seven-byte NOPs (0f 1f 80 00 00 00 00: nopl 0x0(%rax)).
template <int K>
[[gnu::noinline]] void nops(long n) {
  for (long i = 0; i < n; ++i)
    asm volatile(".rept %c0\n\t.byte 0x0f, 0x1f, 0x80, 0, 0, 0, 0\n\t.endr" : : "i"(K));
}
#endif

/// Seconds per call of f(n) for n chosen so that one call takes about 10 ms: the best of
/// `rounds` calls, divided by n.
double per_iteration(void (*f)(long), int rounds) {
  long n = 1000;
  while (best_of(1, [&] { f(n); }) < 1e-2 && n < (1L << 40))
    n *= 2;
  return best_of(rounds, [&] { f(n); }) / static_cast<double>(n);
}

} // namespace

void print_machine_ceilings(double seconds, double fma_latency) {
  const int rounds = 15;
  const double chain = per_iteration(fma_chain<1>, rounds);
  const double hz = fma_latency / chain;
  fmt::print("# gbssn1d machine ceilings, one core, best of {} repetitions\n", rounds);
  fmt::print("clock_GHz {:.3f}  (dependent FMA chain, {} cycles each)\n", hz * 1e-9, fma_latency);
  fmt::print("# operation lanes instructions_per_cycle flops_per_cycle Gflop_per_s\n");
  struct Row {
    const char* name;
    int lanes;
    void (*f)(long);
    int instructions;    // per call of f with n = 1
    double flops_per_op; // per lane
  };
  const Row rows[] = {
      {"fma", 1, throughput<1, false>, 12, 2.0}, {"fma", 4, throughput<4, false>, 12, 2.0},
      {"fma", 8, throughput<8, false>, 12, 2.0}, {"mul", 1, throughput<1, true>, 12, 1.0},
      {"mul", 4, throughput<4, true>, 12, 1.0},  {"mul", 8, throughput<8, true>, 12, 1.0},
      {"div", 1, divisions<1>, 8, 1.0},          {"div", 4, divisions<4>, 8, 1.0},
      {"div", 8, divisions<8>, 8, 1.0},
  };
  for (const Row& r : rows) {
    const double per_second = r.instructions / per_iteration(r.f, rounds);
    const double flops_per_instruction = r.flops_per_op * r.lanes;
    fmt::print("{} {} {:.3f} {:.2f} {:.2f}\n", r.name, r.lanes, per_second / hz,
               per_second / hz * flops_per_instruction, per_second * flops_per_instruction * 1e-9);
  }
#if defined(__x86_64__)
  fmt::print("# front end (loops of 7-byte NOPs): code_bytes_per_loop bytes_per_cycle "
             "instructions_per_cycle\n");
  struct Loop {
    int instructions;
    void (*f)(long);
  };
  const Loop loops[] = {{128, nops<128>}, {524, nops<524>}, {1024, nops<1024>}, {2048, nops<2048>}};
  for (const Loop& l : loops) {
    const double per_cycle = l.instructions / per_iteration(l.f, rounds) / hz;
    fmt::print("{} {:.1f} {:.2f}\n", 7 * l.instructions, 7.0 * per_cycle, per_cycle);
  }
#endif
  fmt::print("# bandwidth (arrays of the size given, each): bytes read_GB_per_s triad_GB_per_s\n");
  for (const std::size_t bytes : {std::size_t{16} << 10, std::size_t{512} << 10,
                                  std::size_t{32} << 20, std::size_t{512} << 20}) {
    const Bandwidth b = bandwidth(bytes, seconds);
    fmt::print("{} {:.1f} {:.1f}\n", bytes, b.read * 1e-9, b.triad * 1e-9);
  }
}
