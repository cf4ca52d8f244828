// The verdict of a converge study and its sentences (converge_report.hpp: judge_study): the
// rule's finding (study/verdict.hpp) written out for convergence.dat and stderr.
#include "io/output.hpp"
#include "study/converge_report.hpp"
#include "study/verdict.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <vector>

namespace gbssn1d {

namespace {

/// The sentences of a study's verdict: where each quantity's orders dip, their RMS orders over
/// time and over windows of the run, the members at the round-off floor, the finding and the
/// order lines of convergence.dat.
class VerdictWords {
public:
  VerdictWords(const ConvergeStudy& s, const Verdict& verdict) : s_(s), verdict_(verdict) {}

  std::string time_at(std::size_t q) const { return time_text(s_.records.front().rows[q].t); }

  /// Where one item's orders fall below the threshold: the first time, the lowest order.
  std::string dips(const OrderJudgement& j) const {
    return j.below == 0
               ? fmt::format("lowest order {} at t = {}", order_text(j.worst), time_at(j.worst_at))
               : fmt::format("order {} at t = {} is the first below {}, lowest {} at "
                             "t = {}",
                             order_text(j.first_order), time_at(j.first_below),
                             order_text(verdict_.threshold), order_text(j.worst),
                             time_at(j.worst_at));
  }

  std::string rms_text(const OrderJudgement& j) const {
    std::string text = fmt::format("order of its RMS over time {}", order_text(j.p_rms));
    if (j.windows_worse > 0)
      text += fmt::format(", over t = {} ... {} {} ({} of {} windows of the run below 0)",
                          time_at(j.worse_begin), time_at(j.worse_end), order_text(j.worse_order),
                          j.windows_worse, j.windows);
    else if (j.windows_below > 0)
      text +=
          fmt::format(", over t = {} ... {} {} ({} of {} windows of the run below {})",
                      time_at(j.window_begin), time_at(j.window_end), order_text(j.window_order),
                      j.windows_below, j.windows, order_text(verdict_.threshold));
    return text;
  }

  /// The floor of member k relative to the quantities' scales, and its finest spacing.
  std::string floor_text(std::size_t k) const {
    return fmt::format("dr_min = M/{:.4g}, floor {:.2g} of the scale", s_.base.M / s_.dr_min[k],
                       round_off_floor(s_.base.M, s_.dr_min[k]));
  }

  /// The items whose finer member lay at the floor, grouped by that (finest) member and by
  /// resolutions; neighbours at the floor at the same times share their count.
  std::string floor_finding() const {
    std::string text;
    for (std::size_t k = s_.members.size(); k-- > 0;) {
      std::vector<std::string> sets; // per resolutions: "H_L2_ext, M_L2_ext at N = ... (...)"
      std::vector<std::vector<double>> seen;
      for (const auto& first : verdict_.items) {
        if (first.at_floor == 0 || first.N.back() != s_.Nd(k)
            || std::find(seen.begin(), seen.end(), first.N) != seen.end())
          continue;
        seen.push_back(first.N);
        sets.push_back(fmt::format("{} at {}", floor_set(first.N), resolutions_text(first.N)));
      }
      if (!sets.empty())
        text += fmt::format("{}N = {} ({}): {}", text.empty() ? "" : "; ", s_.members[k].N,
                            floor_text(k), fmt::join(sets, "; "));
    }
    return fmt::format("the round-off floor (the finer value within {:g} times eps (M/dr_min)^2 "
                       "of its scale; those times not judged) reached by {}",
                       kFloorFactor, text);
  }

  /// The rule's finding over the common times.
  std::string judged() const {
    const ConvergenceClass kind = verdict_.kind();
    if (const OrderJudgement* failure = verdict_.failure())
      return failure_finding(*failure, kind);
    const OrderJudgement* w = verdict_.weakest();
    const std::string orders =
        w ? fmt::format("every judged order of an RMS over time (norms: also over each tenth of "
                        "the run) at least {} (expected order {}); the lowest over time is {} ({} "
                        "at {})",
                        order_text(verdict_.threshold), verdict_.design, order_text(w->p_rms),
                        w->quantity, resolutions_text(w->N))
          : "no monitored value lies above its round-off floor: nothing is judged";
    return kind == ConvergenceClass::to_floor
               ? fmt::format("{}: {}; {}", class_words(kind), orders, floor_finding())
               : fmt::format("{}: {}", class_words(kind), orders);
  }

  /// convergence.dat's verdict, its rule and one line per quantity and resolutions.
  std::string order_lines(const std::string& verdict_text) const {
    std::string lines = fmt::format(
        "verdict: {}\nverdict rule: for each norm at each pair of neighbouring members, and each "
        "field's differences at each triple, at the times where the finer value is above {:g} "
        "times the round-off floor of the finest member, eps (M/dr_min)^2 of its scale (1/M^2 for "
        "H and M_r, 1/M for G^r, the field's RMS for fields), the order of the RMS over those "
        "times (for norms also of the RMS over each tenth of them): converges if each is at least "
        "{} (expected order {} - {}), until the round-off floor if so and some times were at the "
        "floor; pre-asymptotic if some is below that but every RMS order over time is at least "
        "{:g} and no tenth's below 0; does not converge otherwise; H_L2_int (inside the horizon) "
        "is not judged, nor are field differences at t = 0 (the same data, interpolated)\n",
        verdict_text, kFloorFactor, order_text(verdict_.threshold), verdict_.design,
        kOrderTolerance, kFallingOrder);
    for (const auto& j : verdict_.items)
      lines += fmt::format("order {} {}: {}; {} of {} judged times below {}{}{}: {}\n", j.quantity,
                           resolutions_text(j.N), rms_text(j), j.below, j.judged,
                           order_text(verdict_.threshold), j.judged > 0 ? ", " + dips(j) : "",
                           j.at_floor > 0 ? fmt::format(
                               "; {} time{} at the round-off floor {:.2g} from t = {}", j.at_floor,
                               j.at_floor == 1 ? "" : "s", j.floor_value, time_at(j.first_floor))
                                          : "",
                           class_words(j.kind));
    return lines;
  }

private:
  /// The quantities at the floor at resolutions N, neighbours at the floor at the same times
  /// sharing their count: "H_L2_ext, M_L2_ext (3 of 40 times from t = 12)".
  std::string floor_set(const std::vector<double>& N) const {
    std::string set, names;
    const OrderJudgement* last = nullptr;
    const auto close = [&] {
      if (last)
        set +=
            fmt::format("{}{} ({} of {} times from t = {})", set.empty() ? "" : ", ", names,
                        last->at_floor, last->at_floor + last->judged, time_at(last->first_floor));
      names.clear();
    };
    for (const auto& j : verdict_.items) {
      if (j.at_floor == 0 || j.N != N)
        continue;
      if (last
          && (j.at_floor != last->at_floor || j.judged != last->judged
              || j.first_floor != last->first_floor))
        close();
      names += (names.empty() ? "" : ", ") + j.quantity;
      last = &j;
    }
    close();
    return set;
  }

  std::string failure_finding(const OrderJudgement& failure, ConvergenceClass kind) const {
    std::size_t more = 0;
    for (const auto& i : verdict_.items)
      more += i.kind == kind ? 1 : 0;
    if (verdict_.nothing_judged)
      return fmt::format(
          "{}: every monitored value lies within {:g} times its round-off floor estimate at "
          "every common time, so nothing is judged ({}); the estimate, eps (M/dr_min)^2, takes "
          "each member's smallest cell (dr_min), which may lie far from where the norms are "
          "taken: a grid much finer at its innermost cells than elsewhere (--dr-inner), a run "
          "too short to leave round-off, or a quantity that vanishes exactly",
          class_words(kind), kFloorFactor, floor_finding());
    if (kind == ConvergenceClass::unjudged)
      return fmt::format(
          "{}: {} at {} has no value at any common time (a norm whose window holds no point of "
          "the coarser member: NaN in its timeseries.dat){}",
          class_words(kind), failure.quantity, resolutions_text(failure.N),
          more > 1 ? fmt::format(" (and {} more quantity/resolution sets; see the order lines)",
                                 more - 1)
                   : "");
    const std::string why =
        kind == ConvergenceClass::pre_asymptotic ? ""
        : failure.p_rms < kFallingOrder
            ? fmt::format("the order of its RMS over time is below {:g} (its error does not fall "
                          "with N); ",
                          kFallingOrder)
            : fmt::format("over t = {} ... {} (a tenth of the run) the finer member is worse "
                          "(RMS order below 0); ",
                          time_at(failure.worse_begin), time_at(failure.worse_end));
    return fmt::format(
        "{}: {} at {}: {}{}; {} (expected order {}){}{}", class_words(kind), failure.quantity,
        resolutions_text(failure.N), why, dips(failure), rms_text(failure), verdict_.design,
        more > 1
            ? fmt::format(" (and {} more quantity/resolution sets; see the order lines)", more - 1)
            : std::string(),
        kind == ConvergenceClass::pre_asymptotic
            ? fmt::format("; the errors fall with N (every order of an RMS over time at least "
                          "{:g}, no tenth of the run where the finer member is worse)",
                          kFallingOrder)
            : std::string());
  }

  const ConvergeStudy& s_;
  const Verdict& verdict_;
};

} // namespace

StudyVerdict judge_study(const ConvergeStudy& s, const StudyEnding& e) {
  StudyVerdict v;
  v.verdict = judge_convergence(
      order_series(s), s.options.expect_order.value_or(static_cast<double>(s.base.fd_order)));
  const VerdictWords words(s, v.verdict);
  v.judged = words.judged();
  v.verdict_text =
      e.signal != 0 ? "not judged: the study was interrupted"
      : e.write_failed
          ? fmt::format("not judged: {} (a write failed; the study is incomplete)", e.failed)
      : !e.failed.empty() ? fmt::format("does not converge: {} (over the common times up to t = "
                                        "{}: {})",
                                        e.failed, e.t_common, v.judged)
                          : v.judged;
  v.order_lines = words.order_lines(v.verdict_text);
  v.kind = v.verdict.kind();
  v.converges = v.verdict.converges();
  return v;
}

} // namespace gbssn1d
