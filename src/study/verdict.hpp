// The verdict of a convergence study: does each monitored quantity converge at (near) the
// design order, at the times where its error is above round-off? For one quantity and one pair
// (norms, exact value 0) or triple (field differences) of resolutions:
//  - judged times: those where the finer value (the finer norm, or |f_b - f_c|) is above
//    kFloorFactor times the round-off floor of the finest member involved (round_off_floor:
//    eps (M/dr)^2 of the quantity's scale, dr the smallest cell whose round-off can have
//    reached where the quantity is taken) and the coarse value is finite. The other times
//    are "at the floor" (their orders measure round-off, not truncation error), not judged;
//    times where both values are exactly 0 (G^r of the initial data) are neither;
//  - the order of the RMS over the judged times (the norms', or the differences', RMS over time,
//    then the two- or three-level formula), and for constraint norms the order of the RMS over
//    each tenth of the judged times (consecutive windows): a finer member whose constraint grows
//    late, or for a tenth of the run, is caught even where the early errors dominate the whole
//    run's RMS, while the order at single times does not decide. Field differences are judged
//    by the whole run's RMS only: their three-level orders over short windows swing where a
//    gauge pulse crosses the comparison window (1+log trumpet, M/15 to M/30: K's order 0.8-1 at
//    12-14 M, 3.9 over the run).
// The quantity's class, and the study's (the worst of its quantities' at all pairs/triples):
//  1. converges: every judged order at least design - kOrderTolerance (the threshold), no time
//     at the floor;
//  2. converges until the round-off floor: the same, but the finer member lay at the floor at
//     some times (or at all of them);
//  3. pre-asymptotic: the errors fall with N (the whole run's RMS order at least kFallingOrder,
//     and no window's RMS order below 0: no tenth of the run where the finer member is worse),
//     but some judged order is below the threshold;
//  4. does not converge: the whole run's RMS order below kFallingOrder, or a window's below 0.
// A quantity with 1 to kWindows judged times is too short to judge (each tenth of the run would
// be a single time, and single times do not decide): not judged, whatever its orders read; a
// study needs more judged times (a smaller --dt-series) for a verdict.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace gbssn1d {

/// Below design - kOrderTolerance an order counts as "not converging (yet)".
inline constexpr double kOrderTolerance = 1.5;
/// The number of consecutive windows of judged times whose RMS orders are judged too.
inline constexpr std::size_t kWindows = 10;
/// Errors fall with N when the whole run's RMS order is at least this (and no window's RMS
/// order is below 0).
inline constexpr double kFallingOrder = 1.0;
/// A time is judged only where the finer value is above kFloorFactor times the round-off floor.
inline constexpr double kFloorFactor = 10.0;

/// Round-off made in a cell reaches a quantity taken elsewhere no faster than this coordinate
/// speed (M per M): the characteristic speeds of the systems run (1+log's sqrt(2 alpha gamma^rr),
/// light's alpha sqrt(gamma^rr), the Gamma-driver's, each plus |beta^r|) stay below 2 where
/// alpha <= 1 and chi <= 1 (an assumption of the floor's estimate, not a measured bound: a
/// faster signal would make the estimate too low at early times).
inline constexpr double kSignalSpeed = 2.0;

/// The round-off floor of a member, relative to the quantity's scale (1/M^2 for H and M_r, 1/M
/// for G^r, the field's RMS for field differences): the round-off of a second difference at
/// spacing dr, eps_machine (M/dr)^2, where dr is the smallest cell whose round-off can have
/// reached the quantity (MemberCells::reach: the cells of its window at t = 0, then those within
/// kSignalSpeed t; after a few M the member's innermost cell). Calibration: the measured floor
/// of the standard gauge's H_L2_R (stationary 1+log trumpet, default sinh grid) was 3-8e-11 at
/// N = 3200 (dr_min = M/400) and 1.2-2.4e-10 at N = 6400 (M/800); the estimate gives 3.5e-11
/// and 1.4e-10. At t = 0 the same trumpet's H_L2_ext at N = 1600 (1.55e-11) is the N = 800
/// one's / 15.4 (order 3.95), not round-off, though within 10 times the innermost cell's
/// estimate (8.9e-12): the reason the window's cells set the floor until the innermost ones'
/// round-off can have arrived.
double round_off_floor(double M, double dr);

/// One quantity at one pair (2 resolutions: values with exact value 0, order
/// ln(E_a/E_b)/ln(b/a)) or triple (3 resolutions: coarse = |f_a - f_b|, fine = |f_b - f_c|) of
/// resolutions, over the study's output times.
struct OrderSeries {
  std::string quantity;       ///< as named in convergence.dat: "H_L2_R", "chi"
  std::vector<double> N;      ///< 2 or 3 resolutions, increasing
  std::vector<double> coarse; ///< per time
  std::vector<double> fine;   ///< per time
  /// per time: the round-off floor of the finest member (absolute); a fine value at or below
  /// kFloorFactor times it is at the floor; a non-finite floor: the time is not judged, nor
  /// counted at the floor (field differences at t = 0)
  std::vector<double> floor;
  bool windowed = true; ///< norms: also judge the RMS over each tenth of the times
};

/// The classes of a verdict, best first (a study's is the worst of its items'). `unjudged`: a
/// quantity without a value at any time (a norm whose window held no point): nothing can be
/// said of it, and the study does not count as converging.
enum class ConvergenceClass { converges, to_floor, unjudged, pre_asymptotic, diverges };

/// The class's words, the verdict's first: "converges", "converges until the round-off floor",
/// "not judged", "pre-asymptotic", "does not converge".
std::string class_words(ConvergenceClass c);

/// What the rule found for one OrderSeries.
struct OrderJudgement {
  std::string quantity;
  std::vector<double> N;
  std::size_t judged = 0;        ///< times above the floor
  std::size_t at_floor = 0;      ///< times with the finer value at the floor (not judged)
  std::size_t valued = 0;        ///< times with a (finite) coarser value
  std::size_t first_floor = 0;   ///< time index of the first of those
  double floor_value = 0.0;      ///< the floor (absolute) there
  std::size_t below = 0;         ///< of the judged times, those with order below the threshold
  double p_rms = 0.0;            ///< order of the RMS over the judged times (NaN: none judged)
  std::size_t first_below = 0;   ///< time index of the first order below the threshold
  double first_order = 0.0;      ///< that order
  std::size_t worst_at = 0;      ///< time index of the lowest order
  double worst = 0.0;            ///< the lowest order at a judged time (-inf: none in (0, 30])
  std::size_t windows = 0;       ///< windows of judged times (kWindows, or fewer times)
  std::size_t windows_below = 0; ///< of those, with the order of their RMS below the threshold
  std::size_t window_begin = 0;  ///< time indices of the first window below: first time
  std::size_t window_end = 0;    ///< and last time
  double window_order = 0.0;     ///< its RMS order
  std::size_t windows_worse = 0; ///< windows with RMS order below 0 (the finer member worse)
  std::size_t worse_begin = 0;   ///< time indices of the first of those: first time
  std::size_t worse_end = 0;     ///< and last time
  double worse_order = 0.0;      ///< its RMS order
  /// 1 to kWindows judged times: too short to judge (each tenth of the run would be one time),
  /// class unjudged whatever its orders
  bool too_short = false;
  ConvergenceClass kind = ConvergenceClass::converges;
  /// Classes 1 and 2: every judged order meets the threshold.
  bool converges() const {
    return kind == ConvergenceClass::converges || kind == ConvergenceClass::to_floor;
  }
};

struct Verdict {
  double design = 4.0;    ///< the order expected
  double threshold = 2.5; ///< design - kOrderTolerance
  std::vector<OrderJudgement> items;
  /// No item judged at any time, some at the round-off floor: the study judged nothing, which is
  /// not a pass (`not judged`), however each item alone reads.
  bool nothing_judged = false;
  /// The study's class: the worst of its items' (converges for no items; not judged when
  /// nothing_judged).
  ConvergenceClass kind() const;
  /// Classes 1 and 2.
  bool converges() const;
  /// The item of the study's class with the lowest RMS order over time (the first without one)
  /// when that class is not judged, pre-asymptotic or does not converge: the worst item, to
  /// name; nullptr when the study converges.
  const OrderJudgement* failure() const;
  /// The worst class of the items whose quantity begins with `prefix` ("H_": the Hamiltonian
  /// constraint's norms, which the verdict names first); unjudged when there are none.
  ConvergenceClass kind_of(const std::string& prefix) const;
  /// The converging item with the lowest RMS order, or nullptr if none was judged.
  const OrderJudgement* weakest() const;
};

/// The order at one time: two-level for 2 resolutions, three-level for 3; +inf when the fine
/// value is 0 and the coarse one is not, -inf for 3 resolutions when no order in (0, 30] fits
/// because the finer difference is too large (not converging), +inf when it is too small.
double order_at(const std::vector<double>& N, double coarse, double fine);

/// Applies the rule (header comment) to every series.
Verdict judge_convergence(const std::vector<OrderSeries>& series, double design_order);

/// "N = 1600 -> 3200" or "N = 800, 1600, 3200".
std::string resolutions_text(const std::vector<double>& N);

/// An order as text: "3.98", "< 0" for -inf, "inf".
std::string order_text(double p);

} // namespace gbssn1d
