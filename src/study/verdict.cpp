#include "study/verdict.hpp"

#include "study/orders.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace gbssn1d {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

} // namespace

double order_at(const std::vector<double>& N, double coarse, double fine) {
  if (!std::isfinite(fine))
    return -inf; // the finer member's value is not a number: nothing converges
  if (fine == 0.0)
    return coarse > 0.0 ? inf : std::numeric_limits<double>::quiet_NaN();
  if (N.size() == 2)
    return order_two_level(coarse, fine, N[0], N[1]);
  const double p = order_three_level(coarse, fine, N[0], N[1], N[2]);
  if (!std::isnan(p))
    return p;
  // no order in (0, 30]: the ratio of the differences lies beyond one end of the bracket
  return coarse / fine >= three_level_ratio(30.0, N[0], N[1], N[2]) ? inf : -inf;
}

double round_off_floor(double M, double dr_min) {
  const double ratio = M / dr_min;
  return std::numeric_limits<double>::epsilon() * ratio * ratio;
}

std::string class_words(ConvergenceClass c) {
  switch (c) {
  case ConvergenceClass::converges:
    return "converges";
  case ConvergenceClass::to_floor:
    return "converges until the round-off floor";
  case ConvergenceClass::unjudged:
    return "not judged";
  case ConvergenceClass::pre_asymptotic:
    return "pre-asymptotic";
  case ConvergenceClass::diverges:
    break;
  }
  return "does not converge";
}

namespace {

/// The order of the RMS of `s` over the judged times times[begin, end).
double rms_order(const OrderSeries& s, const std::vector<std::size_t>& times, std::size_t begin,
                 std::size_t end) {
  double sum_coarse = 0.0, sum_fine = 0.0;
  for (std::size_t q = begin; q < end; ++q) {
    sum_coarse += s.coarse[times[q]] * s.coarse[times[q]];
    sum_fine += s.fine[times[q]] * s.fine[times[q]];
  }
  const double n = static_cast<double>(end - begin);
  return order_at(s.N, std::sqrt(sum_coarse / n), std::sqrt(sum_fine / n));
}

/// Every time of `s` into `j`: those with a value, those at the round-off floor, the orders
/// below `threshold` and the worst. Returns the judged times.
std::vector<std::size_t> scan_times(const OrderSeries& s, double threshold, OrderJudgement& j) {
  std::vector<std::size_t> times; // the judged times
  for (std::size_t t = 0; t < s.coarse.size(); ++t) {
    const double c = s.coarse[t], f = s.fine[t];
    j.valued += std::isfinite(c) ? 1 : 0;
    // no value, not to be judged, or no error at all (G^r of the initial data): neither
    // judged nor at the floor
    if (!std::isfinite(c) || !std::isfinite(s.floor[t]) || (c == 0.0 && f == 0.0))
      continue;
    if (f <= kFloorFactor * s.floor[t]) { // the finer member at round-off: not judged
      if (j.at_floor++ == 0) {
        j.first_floor = t;
        j.floor_value = s.floor[t];
      }
      continue;
    }
    times.push_back(t); // (a non-finite finer value too: it fails)
    const double p = order_at(s.N, c, f);
    if (p < j.worst) {
      j.worst = p;
      j.worst_at = t;
    }
    if (p < threshold && j.below++ == 0) {
      j.first_below = t;
      j.first_order = p;
    }
  }
  return times;
}

/// The order of the RMS over all judged times and over consecutive windows of (about) a tenth
/// of them each, and from them the class of `j`.
void classify(const OrderSeries& s, const std::vector<std::size_t>& times, double threshold,
              OrderJudgement& j) {
  if (j.judged == 0) {
    j.p_rms = std::numeric_limits<double>::quiet_NaN();
    j.worst = std::numeric_limits<double>::quiet_NaN();
    // no value at any time (not one at the floor or both zero): not judged, not "converges"
    j.kind = j.at_floor > 0  ? ConvergenceClass::to_floor
             : j.valued == 0 ? ConvergenceClass::unjudged
                             : ConvergenceClass::converges;
    return;
  }
  j.p_rms = rms_order(s, times, 0, j.judged);
  // consecutive windows of (about) a tenth of the judged times each
  j.windows = s.windowed ? std::min<std::size_t>(kWindows, j.judged) : 0;
  for (std::size_t w = 0; w < j.windows; ++w) {
    const std::size_t begin = w * j.judged / j.windows, end = (w + 1) * j.judged / j.windows;
    const double p = rms_order(s, times, begin, end);
    if (p < threshold && j.windows_below++ == 0) {
      j.window_begin = times[begin];
      j.window_end = times[end - 1];
      j.window_order = p;
    }
    if (p < 0.0 && j.windows_worse++ == 0) {
      j.worse_begin = times[begin];
      j.worse_end = times[end - 1];
      j.worse_order = p;
    }
  }
  const bool falls = !(j.p_rms < kFallingOrder) && j.windows_worse == 0;
  const bool meets = !(j.p_rms < threshold) && j.windows_below == 0;
  // kWindows or fewer judged times: each tenth of the run would be one time, and one time
  // does not decide (header comment)
  j.too_short = j.judged <= kWindows;
  j.kind = j.too_short      ? ConvergenceClass::unjudged
           : !falls         ? ConvergenceClass::diverges
           : !meets         ? ConvergenceClass::pre_asymptotic
           : j.at_floor > 0 ? ConvergenceClass::to_floor
                            : ConvergenceClass::converges;
}

} // namespace

Verdict judge_convergence(const std::vector<OrderSeries>& series, double design_order) {
  Verdict v;
  v.design = design_order;
  v.threshold = design_order - kOrderTolerance;
  for (const auto& s : series) {
    OrderJudgement j;
    j.quantity = s.quantity;
    j.N = s.N;
    j.worst = inf;
    const std::vector<std::size_t> times = scan_times(s, v.threshold, j);
    j.judged = times.size();
    classify(s, times, v.threshold, j);
    v.items.push_back(std::move(j));
  }
  v.nothing_judged =
      !v.items.empty()
      && std::all_of(v.items.begin(), v.items.end(), [](const auto& j) { return j.judged == 0; })
      && std::any_of(v.items.begin(), v.items.end(), [](const auto& j) { return j.at_floor > 0; });
  return v;
}

ConvergenceClass Verdict::kind() const {
  if (nothing_judged)
    return ConvergenceClass::unjudged;
  ConvergenceClass worst = ConvergenceClass::converges;
  for (const auto& j : items)
    worst = std::max(worst, j.kind);
  return worst;
}

bool Verdict::converges() const {
  return failure() == nullptr;
}

const OrderJudgement* Verdict::failure() const {
  const ConvergenceClass k = kind();
  if (k != ConvergenceClass::unjudged && k != ConvergenceClass::pre_asymptotic
      && k != ConvergenceClass::diverges)
    return nullptr;
  // of the items of the study's class, the one with the lowest RMS order over time (the first
  // of those without one)
  const OrderJudgement* worst = nullptr;
  for (const auto& j : items)
    if (j.kind == k
        && (!worst || j.p_rms < worst->p_rms || (std::isnan(j.p_rms) && !std::isnan(worst->p_rms))))
      worst = &j;
  if (worst)
    return worst;
  return nothing_judged ? &items.front() : nullptr;
}

ConvergenceClass Verdict::kind_of(const std::string& prefix) const {
  ConvergenceClass worst = ConvergenceClass::converges;
  bool any = false;
  for (const auto& j : items)
    if (j.quantity.starts_with(prefix)) {
      worst = std::max(worst, j.kind);
      any = true;
    }
  return any ? worst : ConvergenceClass::unjudged;
}

const OrderJudgement* Verdict::weakest() const {
  const OrderJudgement* w = nullptr;
  for (const auto& j : items)
    if (j.converges() && j.judged > 0 && (!w || j.p_rms < w->p_rms))
      w = &j;
  return w;
}

std::string resolutions_text(const std::vector<double>& N) {
  if (N.size() == 2)
    return fmt::format("N = {} and {}", N[0], N[1]);
  return fmt::format("N = {}, {} and {}", N[0], N[1], N[2]);
}

std::string order_text(double p) {
  if (std::isnan(p))
    return "-";
  if (p == -inf)
    return "< 0";
  if (p == inf)
    return "inf";
  return fmt::format("{:.2f}", p);
}

} // namespace gbssn1d
