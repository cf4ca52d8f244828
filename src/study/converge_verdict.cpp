// The verdict of a converge study and its sentences (converge_report.hpp: judge_study): the
// rule's finding (study/verdict.hpp) written out for convergence.dat and stderr.
#include "io/data_file.hpp"
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

  /// Member k's finest spacing, and the floor it sets relative to the quantities' scales once
  /// its round-off can have reached them.
  std::string floor_text(std::size_t k) const {
    return fmt::format("dr_min = M/{:.4g}, floor from its innermost cell {:.2g} of the scale",
                       s_.base.M / s_.cells[k].dr_min,
                       round_off_floor(s_.base.M, s_.cells[k].dr_min));
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
    return fmt::format("the round-off floor (the finer value within {:g} times eps (M/dr)^2 of "
                       "its scale, dr the smallest cell whose round-off can have reached it; "
                       "those times not judged) reached by {}",
                       kFloorFactor, text);
  }

  /// The Hamiltonian constraint's class, named first whatever the study's: "H converges (its
  /// lowest order of an RMS over time 3.91: H_L2_R at N = 800 and 1600)".
  std::string h_finding() const {
    const OrderJudgement* low = nullptr;
    for (const auto& j : verdict_.items)
      if (j.quantity.starts_with("H_") && j.judged > 0 && (!low || j.p_rms < low->p_rms))
        low = &j;
    // no H norm judged at any time (every value at the floor, or none): H is not judged
    const std::string words =
        class_words(low ? verdict_.kind_of("H_") : ConvergenceClass::unjudged);
    return low ? fmt::format("H {} (its lowest order of an RMS over time {}: {} at {})", words,
                             order_text(low->p_rms), low->quantity, resolutions_text(low->N))
               : fmt::format("H {}", words);
  }

  /// The rule's finding over the common times: the study's class, H's, then the worst item's.
  std::string judged() const {
    const ConvergenceClass kind = verdict_.kind();
    const std::string head = fmt::format("{}: {}; ", class_words(kind), h_finding());
    if (const OrderJudgement* failure = verdict_.failure())
      return head + failure_finding(*failure, kind);
    const OrderJudgement* w = verdict_.weakest();
    const std::string orders =
        w ? fmt::format("every judged order of an RMS over time (norms: also over each tenth of "
                        "the run) at least {} (expected order {}); the lowest over time is {} ({} "
                        "at {})",
                        order_text(verdict_.threshold), verdict_.design, order_text(w->p_rms),
                        w->quantity, resolutions_text(w->N))
          : "no monitored value lies above its round-off floor: nothing is judged";
    return kind == ConvergenceClass::to_floor
               ? fmt::format("{}{}; {}", head, orders, floor_finding())
               : head + orders;
  }

  /// convergence.dat's verdict, its rule and one line per quantity and resolutions.
  std::string order_lines(const std::string& verdict_text) const {
    std::string lines = fmt::format(
        "verdict: {}\nverdict rule: for each norm at each pair of neighbouring members, and each "
        "field's differences at each triple, at the times where the finer value is above {:g} "
        "times the round-off floor of the finest member, eps (M/dr)^2 of its scale (1/M^2 for "
        "H and M_r, 1/M for G^r, the field's RMS for fields; dr the smallest of its cells within "
        "{:g} t of where the quantity is taken), the order of the RMS over those "
        "times (for norms also of the RMS over each tenth of them): converges if each is at least "
        "{} (expected order {} - {}), until the round-off floor if so and some times were at the "
        "floor; pre-asymptotic if some is below that but every RMS order over time is at least "
        "{:g} and no tenth's below 0; does not converge otherwise; not judged with {} or fewer "
        "judged times (too short: single times do not decide); the verdict names H's class "
        "first, then the worst quantity's; H_L2_int (inside the horizon) is not judged, nor are "
        "field differences at t = 0 (the same data, interpolated)\n",
        verdict_text, kFloorFactor, kSignalSpeed, order_text(verdict_.threshold), verdict_.design,
        kOrderTolerance, kFallingOrder, kWindows);
    for (const auto& j : verdict_.items)
      lines += fmt::format("order {} {}: {}; {} of {} judged times below {}{}{}{}: {}\n",
                           j.quantity, resolutions_text(j.N), rms_text(j), j.below, j.judged,
                           order_text(verdict_.threshold), j.judged > 0 ? ", " + dips(j) : "",
                           j.at_floor > 0 ? fmt::format(
                               "; {} time{} at the round-off floor {:.2g} from t = {}", j.at_floor,
                               j.at_floor == 1 ? "" : "s", j.floor_value, time_at(j.first_floor))
                                          : "",
                           j.too_short ? fmt::format("; too short to judge (more than {} judged "
                                                     "times needed)",
                                                     kWindows)
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
        set += fmt::format("{}{} ({} of {} times from t = {}, floor {:.2g} there)",
                           set.empty() ? "" : ", ", names, last->at_floor,
                           last->at_floor + last->judged, time_at(last->first_floor),
                           last->floor_value);
      names.clear();
    };
    for (const auto& j : verdict_.items) {
      if (j.at_floor == 0 || j.N != N)
        continue;
      if (last
          && (j.at_floor != last->at_floor || j.judged != last->judged
              || j.first_floor != last->first_floor || j.floor_value != last->floor_value))
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
    const std::string others =
        more > 1
            ? fmt::format(" (and {} more quantity/resolution sets; see the order lines)", more - 1)
            : std::string();
    if (verdict_.nothing_judged)
      return fmt::format(
          "every monitored value lies within {:g} times its round-off floor estimate at every "
          "common time, so nothing is judged ({}); the estimate, eps (M/dr)^2, takes the "
          "smallest cell whose round-off can have reached the quantity: a run too short to "
          "leave round-off, or quantities that vanish exactly",
          kFloorFactor, floor_finding());
    if (kind == ConvergenceClass::unjudged && failure.too_short)
      return fmt::format(
          "{} at {} is too short to judge: {} judged time{}{} (more than {} needed: a run is "
          "judged by its RMS over each tenth of the judged times, and single times do not "
          "decide; a smaller --dt-series gives more){}",
          failure.quantity, resolutions_text(failure.N), failure.judged,
          failure.judged == 1 ? "" : "s",
          failure.at_floor > 0 ? fmt::format(", {} more at the round-off floor", failure.at_floor)
                               : "",
          kWindows, others);
    if (kind == ConvergenceClass::unjudged)
      return fmt::format("{} at {} has no value at any common time (a norm whose window holds no "
                         "point of the coarser member: NaN in its timeseries.dat){}",
                         failure.quantity, resolutions_text(failure.N), others);
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
        "the worst: {} at {}: {}{}; {} (expected order {}){}{}", failure.quantity,
        resolutions_text(failure.N), why, dips(failure), rms_text(failure), verdict_.design, others,
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
