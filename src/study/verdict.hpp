// The verdict of a convergence study: does each monitored quantity converge at (near) the
// design order, at the times where its error is above round-off? The rule, for one quantity and
// one pair (norms, exact value 0) or triple (field differences) of resolutions:
//  - judged times: those where the coarse value (the coarser norm, or |f_a - f_b|) is finite and
//    above `floor` (round-off: 1e-10 of the quantity's scale);
//  - the order of the RMS over the judged times (the norms', or the differences', RMS over time,
//    then the two- or three-level formula) must be at least design - 1.5;
//  - for constraint norms, so must the order of the RMS over each tenth of the judged times
//    (consecutive windows): a finer member whose constraint grows late, or for a tenth of the
//    run, fails even where the early errors dominate the whole run's RMS, while the order at
//    single times does not decide. Field differences are judged by the whole run's RMS only:
//    their three-level orders over short windows swing where a gauge pulse crosses the
//    comparison window (1+log trumpet, M/15 to M/30: K's order 0.8-1 at 12-14 M, 3.9 over the
//    run).
// A study converges when every monitored quantity at every pair (triple) does.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace gbssn1d {

/// Below design - kOrderTolerance an order counts as "not converging".
inline constexpr double kOrderTolerance = 1.5;
/// The number of consecutive windows of judged times whose RMS orders are judged too.
inline constexpr std::size_t kWindows = 10;
/// Relative round-off floor of the coarse value: kRoundOffFloor times the quantity's scale.
inline constexpr double kRoundOffFloor = 1e-10;

/// One quantity at one pair (2 resolutions: values with exact value 0, order
/// ln(E_a/E_b)/ln(b/a)) or triple (3 resolutions: coarse = |f_a - f_b|, fine = |f_b - f_c|) of
/// resolutions, over the study's output times.
struct OrderSeries {
  std::string quantity;       ///< as named in convergence.dat: "H_L2_R", "chi"
  std::vector<double> N;      ///< 2 or 3 resolutions, increasing
  std::vector<double> coarse; ///< per time
  std::vector<double> fine;   ///< per time
  std::vector<double> floor;  ///< per time: a coarse value at or below it is not judged
  bool windowed = true;       ///< norms: also judge the RMS over each tenth of the times
};

/// What the rule found for one OrderSeries.
struct OrderJudgement {
  std::string quantity;
  std::vector<double> N;
  std::size_t judged = 0;        ///< times above the floor
  std::size_t below = 0;         ///< of those, with order below the threshold
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
  bool converges = true;
};

struct Verdict {
  double design = 4.0;    ///< the order expected
  double threshold = 2.5; ///< design - kOrderTolerance
  std::vector<OrderJudgement> items;
  bool converges() const;
  /// The first item that does not converge (in the order given), or nullptr.
  const OrderJudgement* failure() const;
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
