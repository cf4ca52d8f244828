#include "study/converge_report.hpp"

#include "core/console.hpp"
#include "core/stop_signal.hpp"

#include "core/registry.hpp"
#include "io/output.hpp"
#include "study/orders.hpp"
#include "study/verdict.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <mutex>
#include <optional>
#include <set>

#include <iterator>

namespace gbssn1d {

namespace fs = std::filesystem;

namespace {

/// The norms compared across members: column stem, order stem, value (judged: part of the
/// verdict; length_power: the quantity's scale is M^length_power, 1/M^2 for H and M_r, 1/M for
/// G^r, of which round_off_floor(M, dr_min) is round-off).
struct Norm {
  const char *column, *order;
  double SeriesRow::*value;
  bool judged;
  int length_power;
};
const Norm norms[] = {{"H_L2_ext", "H", &SeriesRow::H_L2_ext, true, -2},
                      {"M_L2_ext", "M", &SeriesRow::M_L2_ext, true, -2},
                      {"G_L2_ext", "G", &SeriesRow::G_L2_ext, true, -1},
                      {"H_L2_R", "H_R", &SeriesRow::H_L2_R, true, -2},
                      {"M_L2_R", "M_R", &SeriesRow::M_L2_R, true, -2},
                      {"H_L2_int", "H_int", &SeriesRow::H_L2_int, false, -2}};
constexpr int n_norms = static_cast<int>(std::size(norms));

/// Every judged norm at each pair of neighbouring members and every field's differences at
/// each triple, over the common times, with the round-off floor of the finest member involved.
std::vector<OrderSeries> order_series(const ConvergeStudy& s) {
  const auto& [base, options, members, radii, fields, samples_key, records, n_times, dr_min] = s;
  const std::size_t m = members.size();
  const auto Nd = [&](std::size_t k) { return s.Nd(k); };
  std::vector<OrderSeries> series;
  for (const auto& c : norms) {
    if (!c.judged)
      continue;
    for (std::size_t k = 0; k + 1 < m; ++k) {
      OrderSeries s{c.column, {Nd(k), Nd(k + 1)}, {}, {}, {}};
      for (std::size_t q = 0; q < n_times; ++q) {
        s.coarse.push_back(records[k].rows[q].*c.value);
        s.fine.push_back(records[k + 1].rows[q].*c.value);
        s.floor.push_back(round_off_floor(base.M, dr_min[k + 1])
                          * std::pow(base.M, c.length_power));
      }
      series.push_back(std::move(s));
    }
  }
  for (std::size_t f = 0; f < fields.size(); ++f)
    for (std::size_t k = 0; k + 2 < m; ++k) {
      OrderSeries s{options.fields[f], {Nd(k), Nd(k + 1), Nd(k + 2)}, {}, {}, {}, false};
      const std::size_t off = f * radii.size();
      const std::vector<double> zeros(off + radii.size(), 0.0);
      for (std::size_t q = 0; q < n_times; ++q) {
        const auto& a = records[k].field_samples[q];
        const auto& b = records[k + 1].field_samples[q];
        const auto& c = records[k + 2].field_samples[q];
        s.coarse.push_back(rms_difference(a, b, off, radii.size()));
        s.fine.push_back(rms_difference(b, c, off, radii.size()));
        // the field's scale: the RMS of the triple's coarsest member's values at the radii; at
        // t = 0 the members start from the same data and differ by the 6th-order interpolation
        // onto the coarsest radii alone, which the three-level formula does not describe: not
        // judged
        s.floor.push_back(records.front().rows[q].t == 0.0
                              ? std::numeric_limits<double>::infinity()
                              : round_off_floor(base.M, dr_min[k + 2])
                                    * rms_difference(a, zeros, off, radii.size()));
      }
      series.push_back(std::move(s));
    }
  return series;
}

} // namespace

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

StudyEnding study_ending(const ConvergeStudy& s) {
  const auto& members = s.members;
  const auto& records = s.records;
  const std::size_t m = members.size(), n_times = s.n_times;
  StudyEnding e;
  e.signal = stop_signal();
  const int signal = e.signal;
  std::string& failed = e.failed;
  for (std::size_t k = 0; k < m; ++k)
    if (!records[k].error.empty() && failed.empty())
      failed = fmt::format("member N = {} failed: {}", members[k].N, records[k].error);
  for (std::size_t k = 0; k < m; ++k)
    e.write_failed = e.write_failed || records[k].write_failed;
  e.t_common = n_times > 0 ? records.front().rows[n_times - 1].t : 0.0;
  e.ending =
      signal != 0 ? fmt::format("interrupted by {} at t = {} (partial: every member only to this "
                                "time; rerun the same command to resume)",
                                signal_name(signal), e.t_common)
      : !failed.empty()
          ? fmt::format("stopped: {} (partial: common times up to t = {})", failed, e.t_common)
          : fmt::format("completed at t = {}", e.t_common);
  e.status_line = fmt::format("status: {}\n", e.ending);
  e.end_line = fmt::format("# end: {}\n", e.ending);

  return e;
}

void write_convergence_dat(const ConvergeStudy& s, const std::string& base_config,
                           const StudyEnding& e, const StudyVerdict& v) {
  const auto& [base, options, members, radii, fields, samples_key, records, n_times, dr_min] = s;
  const std::size_t m = members.size();
  const auto Nd = [&](std::size_t k) { return s.Nd(k); };
  const std::string& status_line = e.status_line;
  const std::string& end_line = e.end_line;
  const std::string& order_lines = v.order_lines;
  std::vector<std::string> cols{"t"};
  for (const auto& c : norms)
    for (std::size_t k = 0; k < m; ++k)
      cols.push_back(fmt::format("{}_N{}", c.column, members[k].N));
  for (const auto& c : norms)
    for (std::size_t k = 0; k + 1 < m; ++k)
      cols.push_back(fmt::format("p_{}_{}_{}", c.order, members[k].N, members[k + 1].N));
  for (const auto& name : options.fields)
    for (std::size_t k = 0; k + 2 < m; ++k)
      cols.push_back(
          fmt::format("p3_{}_{}_{}_{}", name, members[k].N, members[k + 1].N, members[k + 2].N));

  const std::string header =
      base_config + status_line + order_lines
      + fmt::format("converge: N = {}; p_X_a_b = ln(X_a/X_b)/ln(b/a) of the norms (X_L2_ext: "
                    "coordinate window, X_L2_R: areal window, H_L2_int: near the puncture); "
                    "p3_f_a_b_c solves |f_a - f_b|/|f_b - f_c| = (a^-p - b^-p)/(b^-p - c^-p) "
                    "(Sec. 15) with RMS differences of f at the coarsest grid's radii in "
                    "[norm-rmin, norm-rmax] (6th-order interpolation)\n",
                    fmt::join(options.N, ","));
  {
    DataFile file(fs::path(options.out) / "convergence.dat", header, cols);
    for (std::size_t s = 0; s < n_times; ++s) {
      std::string line = time_text(records.front().rows[s].t);
      auto norm = [&](std::size_t k, int c) { return records[k].rows[s].*norms[c].value; };
      for (int c = 0; c < n_norms; ++c)
        for (std::size_t k = 0; k < m; ++k)
          line += fmt::format(" {:.16e}", norm(k, c));
      for (int c = 0; c < n_norms; ++c)
        for (std::size_t k = 0; k + 1 < m; ++k)
          line +=
              fmt::format(" {:.6e}", order_two_level(norm(k, c), norm(k + 1, c), Nd(k), Nd(k + 1)));
      for (std::size_t f = 0; f < fields.size(); ++f)
        for (std::size_t k = 0; k + 2 < m; ++k) {
          const auto& a = records[k].field_samples[s];
          const auto& b = records[k + 1].field_samples[s];
          const auto& c = records[k + 2].field_samples[s];
          const std::size_t off = f * radii.size();
          line += fmt::format(" {:.6e}", order_three_level(rms_difference(a, b, off, radii.size()),
                                                           rms_difference(b, c, off, radii.size()),
                                                           Nd(k), Nd(k + 1), Nd(k + 2)));
        }
      line += "\n";
      file.write(line.data(), line.size());
    }
    file.write(end_line.data(), end_line.size());
    file.flush(); // checked: a failed write throws OutputError
  }
}

void write_scaled_H(const ConvergeStudy& s, const std::string& base_config, const StudyEnding& e) {
  const auto& [base, options, members, radii, fields, samples_key, records, n_times, dr_min] = s;
  const std::size_t m = members.size();
  const auto Nd = [&](std::size_t k) { return s.Nd(k); };
  const std::string& status_line = e.status_line;
  const std::string& end_line = e.end_line;
  // scaled_H.dat: H at the common radii, finer members times (N_k/N_0)^order
  {
    std::vector<std::string> scols{"r"};
    for (std::size_t k = 0; k < m; ++k)
      scols.push_back(k == 0 ? fmt::format("H_N{}", members[k].N)
                             : fmt::format("H_N{}_scaled", members[k].N));
    DataFile file(fs::path(options.out) / "scaled_H.dat",
                  base_config + status_line
                      + fmt::format("scaled_H.dat: H of member N_k times (N_k/N_0)^{} "
                                    "at the coarsest grid's exterior radii\n",
                                    options.order),
                  scols);
    std::vector<double> times = options.scaled_times;
    if (times.empty())
      times.push_back(base.tmax);
    bool first = true;
    std::set<std::size_t> written; // output rows with a block: each once
    for (double tw : times) {
      if (n_times == 0)
        break;
      std::size_t s = 0;
      for (std::size_t q = 0; q < n_times; ++q)
        if (std::abs(records.front().rows[q].t - tw) < std::abs(records.front().rows[s].t - tw))
          s = q;
      if (!written.insert(s).second) {
        say("gbssn1d converge: note: --scaled-times {} falls on the output at t = {}, which has "
            "its block already (one block per output time)\n",
            time_text(tw), time_text(records.front().rows[s].t));
        continue;
      }
      std::string block = first ? "" : "\n\n";
      first = false;
      block += "# t = " + time_text(records.front().rows[s].t) + "\n";
      for (std::size_t j = 0; j < radii.size(); ++j) {
        block += fmt::format("{:.16e}", radii[j]);
        for (std::size_t k = 0; k < m; ++k)
          block += fmt::format(" {:.16e}",
                               records[k].H_samples[s][j] * std::pow(Nd(k) / Nd(0), options.order));
        block += "\n";
      }
      file.write(block.data(), block.size());
    }
    file.write(end_line.data(), end_line.size());
    file.flush();
  }
}

} // namespace gbssn1d
